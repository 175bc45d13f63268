#pragma once
// Which kinds of GPU work sit on one side of a barrier: the work that produced a resource and the work
// that consumes it next. A resource state alone says "any shader stage" (ShaderResource and
// UnorderedAccess are valid in every stage), so a barrier that knows only states must wait for and
// block every stage; a barrier that also knows the stages waits only for the producer and blocks only
// the consumer (docs/embedding.md "Barriers"). The render graph fills them from each pass's kind.
#include <cstdint>

namespace caustics::rhi {

enum class PipelineStages : uint32_t {
    None = 0,                  // not said: every stage the resource state allows
    Raster = 1u << 0,          // draws: vertex input .. colour attachment output, depth tests
    Compute = 1u << 1,         // dispatches (including ray queries from compute)
    RayTracing = 1u << 2,      // dispatchRays
    Copy = 1u << 3,            // copies, clears, uploads
    AccelStructBuild = 1u << 4,// acceleration-structure builds, updates, copies
};

constexpr PipelineStages operator|(PipelineStages a, PipelineStages b) {
    return PipelineStages(uint32_t(a) | uint32_t(b));
}
constexpr PipelineStages operator&(PipelineStages a, PipelineStages b) {
    return PipelineStages(uint32_t(a) & uint32_t(b));
}
constexpr PipelineStages& operator|=(PipelineStages& a, PipelineStages b) { return a = a | b; }
constexpr bool hasAny(PipelineStages set, PipelineStages bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

// "Raster|Compute", or "None".
const char* pipelineStagesName(PipelineStages stages);

}  // namespace caustics::rhi
