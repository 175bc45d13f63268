// The ray-tracing state of a scene trace (docs/shaders.md): a pass's ray generation with this folder's
// closest hit (trace.rchit: reports the surface) and miss (trace.rmiss), the one TracePayload every scene
// trace shares (shaders/common/scene_trace.h). The forward and backward passes build theirs with it.
#include "caustic_maps/caustic_internal.h"
#include "caustics/pass_shaders.h"

namespace caustics {

using rhi::ShaderStage;

Status sceneTraceState(rhi::IDevice& d, const char* rayGen, uint32_t pushBytes, const rhi::BindingLayoutHandle& scene,
                       const rhi::BindingLayoutHandle& pass, rhi::StateObjectHandle& so, rhi::ShaderTableHandle& table) {
    rhi::StateObjectDesc desc;
    CAUSTICS_TRY(auto rg, pass_shaders::shaderLibrary(d.backend(), rayGen, "rayGen", ShaderStage::RayGen));
    CAUSTICS_TRY(auto miss, pass_shaders::shaderLibrary(d.backend(), "scene_trace/trace.rmiss", "miss", ShaderStage::Miss));
    CAUSTICS_TRY(auto hit, pass_shaders::shaderLibrary(d.backend(), "scene_trace/trace.rchit", "closestHit", ShaderStage::ClosestHit));
    desc.libraries = {rg, miss, hit};
    desc.hitGroups.push_back({"hit", rhi::HitGroupType::Triangles, "closestHit", "", ""});
    desc.maxPayloadBytes = 20;   // TracePayload
    desc.maxAttributeBytes = 8;
    desc.maxRecursionDepth = 1;  // the specular chain is iterated in the raygen shader
    desc.globalBindings.layouts = {scene, pass};
    desc.globalBindings.pushConstantBytes = pushBytes;
    desc.debugName = rayGen;
    CAUSTICS_TRY(so, d.createStateObject(desc));
    CAUSTICS_TRY(table, d.createShaderTable(rhi::ShaderTableDesc{so}.setRayGen("rayGen").addMiss("miss").addHitGroup("hit")));
    return okStatus();
}

}  // namespace caustics
