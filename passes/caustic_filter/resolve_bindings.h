#pragma once
// caustics.resolve's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticResolveBindingList[] = {
    {"firstWords", Kind::StorageBufferRO, 0, 0, "uint"},    // first type's radiance buffer (or both types)
    {"secondWords", Kind::StorageBufferRO, 0, 1, "uint"},   // second type's
    {"outFirst", Kind::StorageTexture, 0, 2, "float4", ImageFormat::Rgba32f},
    {"outSecond", Kind::StorageTexture, 0, 3, "float4", ImageFormat::Rgba32f},
    {"outCombined", Kind::StorageTexture, 0, 4, "float4", ImageFormat::Rgba32f},   // caustics.radiance
};

inline constexpr PassBindings kCausticResolveBindings{"caustic_resolve", "passes/caustic_filter/resolve_bindings.h",
                                                      kCausticResolveBindingList, "ResolveParams", "params"};

}  // namespace caustics::shader_bindings
