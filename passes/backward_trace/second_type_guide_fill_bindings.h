#pragma once
// The second-type guide fill pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kSecondTypeGuideFillBindingList[] = {
    {"sphereObjectId", Kind::SampledTexture, 0, 0, "uint"},   // written from the spheres (0: no sphere)
    {"cameraObjectId", Kind::SampledTexture, 0, 1, "uint"},   // the camera G-buffer's
    // Written from the spheres where sphereObjectId is set, completed here in place.
    {"depthMotion", Kind::StorageTexture, 0, 2, "float4", ImageFormat::Rgba16f},
    {"normal", Kind::StorageTexture, 0, 3, "float4", ImageFormat::Rgba16f},
    {"objectId", Kind::StorageTexture, 0, 4, "uint", ImageFormat::R32ui},
    // List order (common/specular_list.h): each tile's run of the list, the list (pixel indices) and its
    // length (the backward pass's grid, (count, 1, 1)).
    {"specularIndex", Kind::SampledTexture, 0, 5, "uint4"},
    {"specularPixels", Kind::StorageBufferRO, 0, 6, "uint"},
    {"listCount", Kind::StorageBufferRO, 0, 7, "uint"},
    // The glass pass (a pixel whose receiver agrees with too few neighbours is filtered on the glass the
    // camera sees): the camera and its G-buffer's depth and normal, and the instances' motion rows.
    {"camera", Kind::ConstantBuffer, 0, 8, "CameraConstants"},   // caustics.camera (common/camera.h)
    {"cameraLinearDepth", Kind::SampledTexture, 0, 9, "float4"},
    {"cameraNormal", Kind::SampledTexture, 0, 10, "float4"},
    {"instanceMotion", Kind::StorageBufferRO, 0, 11, "float4"},   // 3 rows per instance (common/caster_motion.h)
    // The screen layout: which pixels are specular (traced), from the G-buffer's optics.
    {"cameraOptics", Kind::SampledTexture, 0, 12, "float4"},
};

inline constexpr PassBindings kSecondTypeGuideFillBindings{"second_type_guide_fill",
                                                           "passes/backward_trace/second_type_guide_fill_bindings.h",
                                                           kSecondTypeGuideFillBindingList, "SecondTypeGuideFillParams", "params"};

}  // namespace caustics::shader_bindings
