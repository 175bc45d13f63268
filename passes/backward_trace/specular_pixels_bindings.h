#pragma once
// caustics.specularPixels' shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kSpecularPixelsBindingList[] = {
    {"gObjectId", Kind::SampledTexture, 0, 0, "uint"},
    {"gOptics", Kind::SampledTexture, 0, 1, "float4"},
    {"specularPixels", Kind::StorageBufferRW, 0, 2, "uint"},   // pixel indices, cut at the sphere capacity
    {"args", Kind::StorageBufferRW, 0, 3, "uint"},             // (count, 1, 1) of the backward pass's grid
    {"stats", Kind::StorageBufferRW, 0, 4, "uint"},            // common/caustic_stats.h
    // Each tile's run of the list (common/specular_list.h) when the second type is kept in list order.
    {"specularIndex", Kind::StorageTexture, 0, 5, "uint4", ImageFormat::Rgba32ui},
};

inline constexpr PassBindings kSpecularPixelsBindings{"specular_pixels", "passes/backward_trace/specular_pixels_bindings.h",
                                                      kSpecularPixelsBindingList, "SpecularPixelParams", "params"};

}  // namespace caustics::shader_bindings
