#include "caustics/rhi/pipeline_stages.h"

#include <array>
#include <string>

namespace caustics::rhi {

const char* pipelineStagesName(PipelineStages stages) {
    // Every combination of the five bits, built once (32 strings), so the name can be returned as a
    // plain pointer like resourceStateName's.
    static const std::array<std::string, 32> kNames = [] {
        const char* bits[] = {"Raster", "Compute", "RayTracing", "Copy", "AccelStructBuild"};
        std::array<std::string, 32> names;
        for (uint32_t set = 0; set < 32; ++set) {
            for (uint32_t b = 0; b < 5; ++b)
                if (set & (1u << b)) names[set] += (names[set].empty() ? "" : "|") + std::string(bits[b]);
            if (names[set].empty()) names[set] = "None";
        }
        return names;
    }();
    return kNames[uint32_t(stages) & 31u].c_str();
}

}  // namespace caustics::rhi
