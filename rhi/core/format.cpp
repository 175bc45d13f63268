#include "caustics/rhi/format.h"

#include <array>

namespace caustics::rhi {

const FormatInfo& formatInfo(Format format) {
    // Indexed by Format; order must follow the enum.
    static const std::array<FormatInfo, 20> kInfos = {{
        {"Unknown", 0, false, false, false},
        {"R8_UNORM", 1, false, false, false},
        {"RG8_UNORM", 2, false, false, false},
        {"RGBA8_UNORM", 4, false, false, false},
        {"RGBA8_SRGB", 4, false, false, false},
        {"BGRA8_UNORM", 4, false, false, false},
        {"R16_FLOAT", 2, false, false, false},
        {"RG16_FLOAT", 4, false, false, false},
        {"RGBA16_FLOAT", 8, false, false, false},
        {"R32_UINT", 4, false, false, true},
        {"RG32_UINT", 8, false, false, true},
        {"RGBA32_UINT", 16, false, false, true},
        {"R32_FLOAT", 4, false, false, false},
        {"RG32_FLOAT", 8, false, false, false},
        {"RGB32_FLOAT", 12, false, false, false},
        {"RGBA32_FLOAT", 16, false, false, false},
        {"D32_FLOAT", 4, true, false, false},
        {"D24_UNORM_S8_UINT", 4, true, true, false},
        {"R11G11B10_FLOAT", 4, false, false, false},
        {"RGB10A2_UNORM", 4, false, false, false},
    }};
    static_assert(uint32_t(kLastFormat) + 1 == 20);
    uint32_t index = uint32_t(format);
    return kInfos[index < kInfos.size() ? index : 0];
}

}  // namespace caustics::rhi
