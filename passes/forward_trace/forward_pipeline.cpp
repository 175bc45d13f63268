// caustics.forward's pipeline: its binding layout (set 1, from forward_bindings.h) and its ray-tracing
// state over the scene (forward*.rgen + scene_trace's trace.rmiss / trace.rchit), the variant the device's atomics
// allow (docs/caustics.md, "Fixed point").
#include "caustic_maps/caustic_internal.h"
#include "forward_trace/forward_bindings.h"
#include "forward_trace/shaders/forward.h"
#include "module/pass_bindings.h"

namespace caustics {

static_assert(sizeof(shader::ForwardParams) == kForwardPushBytes);

const shader_bindings::PassBindings& forwardBindings(const CausticResources::Impl& r) {
    return r.floatAtomics   ? shader_bindings::kForwardBindings
           : r.int64Atomics ? shader_bindings::kForwardFixed64Bindings
                            : shader_bindings::kForwardFixedBindings;
}

Status createForwardLayout(CausticResources::Impl& r) {
    CAUSTICS_TRY(r.forwardLayout, createPassBindingLayout(*r.device, forwardBindings(r), 1, rhi::ShaderStage::All));
    return okStatus();
}

Status createForwardState(CausticResources::Impl& r, const rhi::BindingLayoutHandle& sceneLayout) {
    const char* rayGen = r.floatAtomics   ? "forward_trace/forward.rgen"
                         : r.int64Atomics ? "forward_trace/forward_fixed64.rgen"
                                          : "forward_trace/forward_fixed.rgen";
    return sceneTraceState(*r.device, rayGen, kForwardPushBytes, sceneLayout, r.forwardLayout, r.forwardState,
                           r.forwardTable);
}

}  // namespace caustics
