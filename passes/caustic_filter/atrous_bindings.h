#pragma once
// caustics.atrous.N's shader resources, declared once (docs/shaders.md, "Bindings"): the weights pass
// writes W_q (caustic_atrous_weights), the iterations before the last write the pool (caustic_atrous),
// the last writes caustics.radiance (caustic_atrous_last).
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticAtrousWeightsBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},   // pool: rgb radiance, a deviation of the mean
    {"guides", Kind::SampledTexture, 0, 1, "uint4"},     // pool: filterPackAtrousGuide (caustics.temporal)
    {"slotMap", Kind::SampledTexture, 0, 2, "uint"},     // this frame's pool tile per screen tile
    {"tiles", Kind::StorageBufferRO, 0, 3, "uint"},      // the tile list, x | y << 16
    {"outSums", Kind::StorageTexture, 0, 4, "float4", ImageFormat::R32f},   // pool: W_q
};
inline constexpr Binding kCausticAtrousBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},
    {"guides", Kind::SampledTexture, 0, 1, "uint4"},
    {"slotMap", Kind::SampledTexture, 0, 2, "uint"},
    {"tiles", Kind::StorageBufferRO, 0, 3, "uint"},
    {"sums", Kind::SampledTexture, 0, 4, "float4"},      // pool: W_q (caustics.atrous.N.weights)
    {"outColor", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba16f},   // pool
};
inline constexpr Binding kCausticAtrousLastBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},
    {"guides", Kind::SampledTexture, 0, 1, "uint4"},
    {"slotMap", Kind::SampledTexture, 0, 2, "uint"},
    {"tiles", Kind::StorageBufferRO, 0, 3, "uint"},
    {"sums", Kind::SampledTexture, 0, 4, "float4"},
    {"outColor", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba32f},   // screen: caustics.radiance
};

inline constexpr PassBindings kCausticAtrousWeightsBindings{"caustic_atrous_weights", "passes/caustic_filter/atrous_bindings.h",
                                                            kCausticAtrousWeightsBindingList, "AtrousParams", "params"};
inline constexpr PassBindings kCausticAtrousBindings{"caustic_atrous", "passes/caustic_filter/atrous_bindings.h",
                                                     kCausticAtrousBindingList, "AtrousParams", "params"};
inline constexpr PassBindings kCausticAtrousLastBindings{"caustic_atrous_last", "passes/caustic_filter/atrous_bindings.h",
                                                         kCausticAtrousLastBindingList, "AtrousParams", "params"};

}  // namespace caustics::shader_bindings
