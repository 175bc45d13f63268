#pragma once
// The grid-from-count pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kGridFromCountBindingList[] = {
    {"counters", Kind::StorageBufferRO, 0, 0, "uint"},   // caustics.stats
    {"grid", Kind::StorageBufferRW, 0, 1, "uint"},       // (x, 1, 1) of the indirect dispatch
};

inline constexpr PassBindings kGridFromCountBindings{"grid_from_count", "passes/caustic_maps/grid_from_count_bindings.h",
                                                     kGridFromCountBindingList, "GridFromCountParams", "params"};

}  // namespace caustics::shader_bindings
