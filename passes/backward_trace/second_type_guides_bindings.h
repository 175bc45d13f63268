#pragma once
// The second-type guide pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kSecondTypeGuidesBindingList[] = {
    {"camera", Kind::ConstantBuffer, 0, 0, "CameraConstants"},                     // caustics.camera (common/camera.h)
    {"spheres", Kind::StorageBufferRO, 0, 1, "CausticSphere", ImageFormat::None, 64},   // caustics.spheres (common/caustic_hit.h)
    {"counters", Kind::StorageBufferRO, 0, 2, "uint"},                           // caustics.stats
    {"depthMotion", Kind::StorageTexture, 0, 3, "float4", ImageFormat::Rgba16f},
    {"normal", Kind::StorageTexture, 0, 4, "float4", ImageFormat::Rgba16f},
    {"sphereObjectId", Kind::StorageTexture, 0, 5, "uint", ImageFormat::R32ui},
    {"gLinearDepth", Kind::SampledTexture, 0, 6, "float4"},      // the camera G-buffer's (the glass)
    {"gObjectId", Kind::SampledTexture, 0, 7, "uint"},
    {"instanceMotion", Kind::StorageBufferRO, 0, 8, "float4"},   // 3 rows per instance (common/caster_motion.h)
    {"specularIndex", Kind::SampledTexture, 0, 9, "uint4"},   // each pixel's list entry (common/specular_list.h)
};

inline constexpr PassBindings kSecondTypeGuidesBindings{"second_type_guides", "passes/backward_trace/second_type_guides_bindings.h",
                                                        kSecondTypeGuidesBindingList, "SecondTypeGuideParams", "params"};

}  // namespace caustics::shader_bindings
