#pragma once
// The second-type guide fill pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kSecondTypeGuideFillBindingList[] = {
    {"sphereDepthMotion", Kind::SampledTexture, 0, 0, "float4"},   // written from the spheres
    {"sphereNormal", Kind::SampledTexture, 0, 1, "float4"},
    {"sphereObjectId", Kind::SampledTexture, 0, 2, "uint"},
    {"cameraObjectId", Kind::SampledTexture, 0, 3, "uint"},        // the camera G-buffer's
    {"depthMotion", Kind::StorageTexture, 0, 4, "float4", ImageFormat::Rgba32f},
    {"normal", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba16f},
    {"objectId", Kind::StorageTexture, 0, 6, "uint", ImageFormat::R32ui},
};

inline constexpr PassBindings kSecondTypeGuideFillBindings{"second_type_guide_fill",
                                                           "passes/backward_trace/second_type_guide_fill_bindings.h",
                                                           kSecondTypeGuideFillBindingList, "SecondTypeGuideFillParams", "params"};

}  // namespace caustics::shader_bindings
