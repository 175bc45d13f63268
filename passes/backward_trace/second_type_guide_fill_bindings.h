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
};

inline constexpr PassBindings kSecondTypeGuideFillBindings{"second_type_guide_fill",
                                                           "passes/backward_trace/second_type_guide_fill_bindings.h",
                                                           kSecondTypeGuideFillBindingList, "SecondTypeGuideFillParams", "params"};

}  // namespace caustics::shader_bindings
