// The kind of work a pass records, for the stage masks of the barriers around it (docs/embedding.md
// "Barriers"). A pass that does not say is inferred only where its accesses allow one kind of work.
#include "compiler_internal.h"

namespace caustics::rg::detail {

using rhi::PipelineStages;

namespace {
// The work an access implies on its own, or None where any shader stage could make it.
PipelineStages accessWork(Access access) {
    switch (access) {
        case Access::RenderTarget:
        case Access::DepthWrite:
        case Access::DepthRead:
        case Access::VertexBuffer:
        case Access::IndexBuffer: return PipelineStages::Raster;
        case Access::CopySource:
        case Access::CopyDest: return PipelineStages::Copy;
        case Access::AccelStructBuildInput:
        case Access::AccelStructBuild:
        case Access::AccelStructBuildRead: return PipelineStages::AccelStructBuild;
        default: return PipelineStages::None;
    }
}
}  // namespace

PipelineStages passStages(const PassDecl& pass) {
    if (pass.stages != PipelineStages::None) return pass.stages;
    PipelineStages implied = PipelineStages::None;
    bool shaderAccess = false;
    for (const AccessDecl& a : pass.accesses) {
        const PipelineStages work = accessWork(a.access);
        if (work == PipelineStages::None) shaderAccess = true;
        implied |= work;
    }
    // Shader reads and writes beside attachments are the draw's own shaders; beside copies or builds
    // alone they could be a dispatch of any kind, so nothing is inferred.
    if (shaderAccess && !hasAny(implied, PipelineStages::Raster)) return PipelineStages::None;
    return implied;
}

PipelineStages unionStages(PipelineStages a, PipelineStages b) {
    if (a == PipelineStages::None || b == PipelineStages::None) return PipelineStages::None;
    return a | b;
}

}  // namespace caustics::rg::detail
