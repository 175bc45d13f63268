#pragma once
// caustics.atrous.N's shader resources, declared once (docs/shaders.md, "Bindings"): the pairs pass
// writes each pixel's 12 packed pair weights and adds them to the weight sums W_q (caustic_atrous_pairs),
// the iterations before the last write the pool (caustic_atrous), the last writes caustics.radiance
// (caustic_atrous_last).
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticAtrousPairsBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},   // pool: rgb radiance, a deviation of the mean
    {"guides", Kind::SampledTexture, 0, 1, "uint4"},     // pool: filterPackAtrousGuide (caustics.temporal)
    {"slotMap", Kind::SampledTexture, 0, 2, "uint"},     // this frame's pool tile per screen tile
    {"tiles", Kind::StorageBufferRO, 0, 3, "uint"},      // the tile list, x | y << 16
    {"outPairs", Kind::StorageTexture, 0, 4, "uint4", ImageFormat::Rgba32ui},   // pool: atrousPackWeight x 12
    {"weightSums", Kind::StorageBufferRW, 0, 5, "uint"},   // caustics.atrous.sums: W_q x 2^30 per pool texel (atrousSumIndex)
};
// The shares passes read no guide: the pairs hold every edge test (atrous_thread.h).
inline constexpr Binding kCausticAtrousBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},
    {"slotMap", Kind::SampledTexture, 0, 1, "uint"},
    {"tiles", Kind::StorageBufferRO, 0, 2, "uint"},
    {"weightSums", Kind::StorageBufferRW, 0, 3, "uint"},   // reads this iteration's region, zeroes the next's
    {"pairs", Kind::SampledTexture, 0, 4, "uint4"},
    {"outColor", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba16f},   // pool
};
inline constexpr Binding kCausticAtrousLastBindingList[] = {
    {"inColor", Kind::SampledTexture, 0, 0, "float4"},
    {"slotMap", Kind::SampledTexture, 0, 1, "uint"},
    {"tiles", Kind::StorageBufferRO, 0, 2, "uint"},
    {"weightSums", Kind::StorageBufferRO, 0, 3, "uint"},
    {"pairs", Kind::SampledTexture, 0, 4, "uint4"},
    {"outColor", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba32f},   // screen: caustics.radiance
    {"specularIndex", Kind::SampledTexture, 0, 6, "uint4"},   // list order: each pixel's entry (common/specular_list.h)
};

inline constexpr PassBindings kCausticAtrousPairsBindings{"caustic_atrous_pairs", "passes/caustic_filter/atrous_bindings.h",
                                                          kCausticAtrousPairsBindingList, "AtrousParams", "params"};
inline constexpr PassBindings kCausticAtrousBindings{"caustic_atrous", "passes/caustic_filter/atrous_bindings.h",
                                                     kCausticAtrousBindingList, "AtrousParams", "params"};
inline constexpr PassBindings kCausticAtrousLastBindings{"caustic_atrous_last", "passes/caustic_filter/atrous_bindings.h",
                                                         kCausticAtrousLastBindingList, "AtrousParams", "params"};

}  // namespace caustics::shader_bindings
