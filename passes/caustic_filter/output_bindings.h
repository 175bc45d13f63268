#pragma once
// caustics.filterOutput's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticFilterOutputBindingList[] = {
    {"temporalColor", Kind::SampledTexture, 0, 0, "float4"},   // pool
    {"temporalGuides", Kind::SampledTexture, 0, 1, "uint2"},   // pool: n
    {"tiles", Kind::StorageBufferRO, 0, 2, "uint"},            // the tile list
    {"radiance", Kind::StorageTexture, 0, 3, "float4", ImageFormat::Rgba32f},   // caustics.radiance, in place
    {"specularIndex", Kind::SampledTexture, 0, 4, "uint4"},   // list order: each pixel's entry (common/specular_list.h)
};

inline constexpr PassBindings kCausticFilterOutputBindings{"caustic_filter_output", "passes/caustic_filter/output_bindings.h",
                                                           kCausticFilterOutputBindingList, "FilterOutputParams", "params"};

}  // namespace caustics::shader_bindings
