#pragma once
// caustics.emitters' shader resources (set 1; set 0 is the scene, caustics::SceneBindings), declared
// once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kEmittersBindingList[] = {
    {"maps", Kind::StorageBufferRO, 1, 0, "CausticMap", {}, 176},        // common/caustic_map.h
    {"mapObjectIds", Kind::SampledTexture, 1, 1, "uint", {}, 0, true},   // one layer per map
    {"emitters", Kind::StorageBufferRW, 1, 2, "uint"},                   // packEmitter, layer x mapSize^2
    {"plans", Kind::StorageBufferRW, 1, 3, "CausticLayerPlan", {}, 32},  // common/layer_plan.h
    {"stats", Kind::StorageBufferRW, 1, 4, "uint"},                      // common/caustic_stats.h
    {"owners", Kind::StorageBufferRO, 1, 5, "uint"},                     // instance -> layer, per light row
};

inline constexpr PassBindings kEmittersBindings{"emitters", "passes/caustic_maps/emitters_bindings.h",
                                                kEmittersBindingList, "EmittersParams", "params"};

}  // namespace caustics::shader_bindings
