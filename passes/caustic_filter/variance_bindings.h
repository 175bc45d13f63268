#pragma once
// caustics.variance's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticVarianceBindingList[] = {
    {"current", Kind::SampledTexture, 0, 0, "float4"},          // this frame, unfiltered (screen)
    {"temporalColor", Kind::SampledTexture, 0, 1, "float4"},    // pool: rgb mean, a per-frame deviation
    {"temporalGuides", Kind::SampledTexture, 0, 2, "uint2"},    // pool: the history guides (n)
    {"gObjectId", Kind::SampledTexture, 0, 3, "uint"},
    {"slotMap", Kind::SampledTexture, 0, 4, "uint"},            // this frame's
    {"tiles", Kind::StorageBufferRO, 0, 5, "uint"},             // the tile list
    {"outColor", Kind::StorageTexture, 0, 6, "float4", ImageFormat::Rgba16f},   // pool
    {"gNormal", Kind::SampledTexture, 0, 7, "float4"},          // .w: photon weights (VarianceParams)
    {"weightSums", Kind::StorageBufferRW, 0, 8, "uint"},        // caustics.atrous.sums: zeroes the first region
    {"specularIndex", Kind::SampledTexture, 0, 9, "uint4"},   // list order: each pixel's entry (common/specular_list.h)
};

inline constexpr PassBindings kCausticVarianceBindings{"caustic_variance", "passes/caustic_filter/variance_bindings.h",
                                                       kCausticVarianceBindingList, "VarianceParams", "params"};

}  // namespace caustics::shader_bindings
