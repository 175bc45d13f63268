#pragma once
// caustics.temporal's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticTemporalBindingList[] = {
    {"camera", Kind::ConstantBuffer, 0, 0, "CameraConstants"},   // scene/camera.glsl, camera.hlsli
    {"current", Kind::SampledTexture, 0, 1, "float4"},           // this frame, unfiltered (screen)
    {"gLinearDepth", Kind::SampledTexture, 0, 2, "float4"},
    {"gNormal", Kind::SampledTexture, 0, 3, "float4"},
    {"gObjectId", Kind::SampledTexture, 0, 4, "uint"},
    {"historyColor", Kind::SampledTexture, 0, 5, "float4"},      // last frame's pool: rgb mean, a deviation
    {"historyGuides", Kind::SampledTexture, 0, 6, "uint2"},      // last frame's pool (filterPackGuide)
    {"previousSlots", Kind::SampledTexture, 0, 7, "uint"},       // last frame's slot map
    {"tiles", Kind::StorageBufferRO, 0, 8, "uint"},              // the tile list
    {"outColor", Kind::StorageTexture, 0, 9, "float4", ImageFormat::Rgba16f},    // this frame's pool
    {"outGuides", Kind::StorageTexture, 0, 10, "uint2", ImageFormat::Rg32ui},    // this frame's pool
    {"outFilterGuide", Kind::StorageTexture, 0, 11, "uint4", ImageFormat::Rgba32ui},   // the a-trous guide
    {"casterMotion", Kind::StorageBufferRO, 0, 12, "uint"},      // caustics.forward's sums (common/caster_motion.h)
    {"instanceMotion", Kind::StorageBufferRO, 0, 13, "float4"},  // 3 rows per instance (common/caster_motion.h)
    {"specularIndex", Kind::SampledTexture, 0, 14, "uint4"},   // list order: each pixel's entry (common/specular_list.h)
    {"gOptics", Kind::SampledTexture, 0, 15, "float4"},        // merged: which pixels are specular (TemporalParams::confirmRises)
};

inline constexpr PassBindings kCausticTemporalBindings{"caustic_temporal", "passes/caustic_filter/temporal_bindings.h",
                                                       kCausticTemporalBindingList, "TemporalParams", "params"};

}  // namespace caustics::shader_bindings
