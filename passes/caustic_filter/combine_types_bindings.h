#pragma once
// The filter's combine pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCombineTypesBindingList[] = {
    {"firstType", Kind::SampledTexture, 0, 0, "float4"},    // filtered on the camera G-buffer
    {"secondType", Kind::SampledTexture, 0, 1, "float4"},   // filtered on its own guides
    {"radiance", Kind::StorageTexture, 0, 2, "float4", ImageFormat::Rgba32f},
    {"specularIndex", Kind::SampledTexture, 0, 3, "uint4"},   // list order: each tile's run (common/specular_list.h)
};

inline constexpr PassBindings kCombineTypesBindings{"combine_types", "passes/caustic_filter/combine_types_bindings.h",
                                                    kCombineTypesBindingList, "CombineTypesParams", "params"};

}  // namespace caustics::shader_bindings
