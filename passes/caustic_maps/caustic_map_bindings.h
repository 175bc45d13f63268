#pragma once
// caustics.maps' shader resources (set 1; set 0 is the scene, caustics::SceneBindings), declared once
// (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticMapBindingList[] = {
    {"maps", Kind::StorageBufferRO, 1, 0, "CausticMap", {}, 176},   // common/caustic_map.h
};

inline constexpr PassBindings kCausticMapBindings{"caustic_map", "passes/caustic_maps/caustic_map_bindings.h",
                                                  kCausticMapBindingList, "CausticMapParams", "params"};

}  // namespace caustics::shader_bindings
