#pragma once
// caustics.photonPlan's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kPhotonPlanBindingList[] = {
    {"mapWords", Kind::StorageBufferRO, 0, 0, "float"},                   // CausticMapGpu[], as words
    {"plans", Kind::StorageBufferRW, 0, 1, "CausticLayerPlan", {}, 32},   // common/layer_plan.h
    {"args", Kind::StorageBufferRW, 0, 2, "uint"},                        // the forward grid (x, 1, 1)
};

inline constexpr PassBindings kPhotonPlanBindings{"photon_plan", "passes/caustic_maps/photon_plan_bindings.h",
                                                  kPhotonPlanBindingList, "PhotonPlanParams", "params"};

}  // namespace caustics::shader_bindings
