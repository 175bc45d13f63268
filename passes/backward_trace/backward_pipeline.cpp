// The second type's pipelines (paper 3.3): caustics.specularPixels (compute), caustics.backward (ray
// generation over the scene, with scene_trace's trace.rchit / trace.rmiss), the second type's guides
// (compute, second_type_guides_pass.cpp) and caustics.gather (ray
// generation, miss, and the procedural hit group sphere.rint + the any-hit of the radiance variant the
// device's atomics allow; docs/caustics.md, "Fixed point"). Their binding layouts come from the
// declarations in backward_bindings.h, gather_bindings.h and specular_pixels_bindings.h.
#include "backward_trace/backward_bindings.h"
#include "backward_trace/gather_bindings.h"
#include "backward_trace/second_type_guide_fill_bindings.h"
#include "backward_trace/second_type_guides_bindings.h"
#include "backward_trace/shaders/backward.h"
#include "backward_trace/shaders/gather.h"
#include "backward_trace/shaders/second_type_guide_fill.h"
#include "backward_trace/shaders/second_type_guides.h"
#include "backward_trace/shaders/specular_pixels.h"
#include "backward_trace/specular_pixels_bindings.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/pass_shaders.h"
#include "module/pass_bindings.h"

namespace caustics {

const shader_bindings::PassBindings& gatherBindings(const CausticResources::Impl& r) {
    return r.floatAtomics   ? shader_bindings::kGatherBindings
           : r.int64Atomics ? shader_bindings::kGatherFixed64Bindings
                            : shader_bindings::kGatherFixedBindings;
}

namespace {

Status createGatherState(CausticResources::Impl& r) {
    rhi::IDevice& d = *r.device;
    using rhi::ShaderStage;
    rhi::StateObjectDesc g;
    CAUSTICS_TRY(auto rgen, pass_shaders::shaderLibrary(d.backend(), "backward_trace/gather.rgen", "rayGen", ShaderStage::RayGen));
    CAUSTICS_TRY(auto miss, pass_shaders::shaderLibrary(d.backend(), "backward_trace/gather.rmiss", "miss", ShaderStage::Miss));
    CAUSTICS_TRY(auto isect, pass_shaders::shaderLibrary(d.backend(), "backward_trace/sphere.rint", "sphere", ShaderStage::Intersection));
    const char* anyHit = r.floatAtomics   ? "backward_trace/gather.rahit"
                         : r.int64Atomics ? "backward_trace/gather_fixed64.rahit"
                                          : "backward_trace/gather_fixed.rahit";
    CAUSTICS_TRY(auto ahit, pass_shaders::shaderLibrary(d.backend(), anyHit, "gather", ShaderStage::AnyHit));
    g.libraries = {rgen, miss, isect, ahit};
    g.hitGroups.push_back({"spheres", rhi::HitGroupType::Procedural, "", "gather", "sphere"});
    g.maxPayloadBytes = sizeof(shader::GatherPayload);
    g.maxAttributeBytes = 8;   // SphereAttributes (sphere.hlsl); GLSL reports none
    g.globalBindings.layouts = {r.gatherLayout};
    g.globalBindings.pushConstantBytes = sizeof(shader::GatherParams);
    g.debugName = "caustics.gather";
    CAUSTICS_TRY(r.gatherState, d.createStateObject(g));
    CAUSTICS_TRY(r.gatherTable,
                 d.createShaderTable(rhi::ShaderTableDesc{r.gatherState}.setRayGen("rayGen").addMiss("miss").addHitGroup("spheres")));
    return okStatus();
}

}  // namespace

Status createBackwardPipelines(CausticResources::Impl& r) {
    rhi::IDevice& d = *r.device;
    const auto all = rhi::ShaderStage::All;
    CAUSTICS_TRY(r.backwardLayout, createPassBindingLayout(d, shader_bindings::kBackwardBindings, 1, all));
    CAUSTICS_TRY(r.gatherLayout, createPassBindingLayout(d, gatherBindings(r), 0, all));
    CAUSTICS_TRY(r.specularPixelLayout, createPassBindingLayout(d, shader_bindings::kSpecularPixelsBindings, 0, all));
    CAUSTICS_TRY(r.specularPixelPipeline, createPassComputePipeline(d, "backward_trace/specular_pixels.comp", {r.specularPixelLayout},
                                                              sizeof(shader::SpecularPixelParams)));
    CAUSTICS_TRY(r.secondTypeGuideLayout, createPassBindingLayout(d, shader_bindings::kSecondTypeGuidesBindings, 0, all));
    CAUSTICS_TRY(r.secondTypeGuidePipeline, createPassComputePipeline(d, "backward_trace/second_type_guides.comp", {r.secondTypeGuideLayout},
                                                    sizeof(shader::SecondTypeGuideParams)));
    CAUSTICS_TRY(r.secondTypeGuideFillLayout, createPassBindingLayout(d, shader_bindings::kSecondTypeGuideFillBindings, 0, all));
    CAUSTICS_TRY(r.secondTypeGuideFillPipeline, createPassComputePipeline(d, "backward_trace/second_type_guide_fill.comp", {r.secondTypeGuideFillLayout},
                                                        sizeof(shader::SecondTypeGuideFillParams)));
    return createGatherState(r);
}

Status createBackwardState(CausticResources::Impl& r, const rhi::BindingLayoutHandle& sceneLayout) {
    return sceneTraceState(*r.device, "backward_trace/backward.rgen", sizeof(shader::BackwardParams), sceneLayout,
                           r.backwardLayout, r.backwardState, r.backwardTable);
}

}  // namespace caustics
