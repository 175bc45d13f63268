#pragma once
// direct_lighting's shader resources, declared once (docs/shaders.md, "Bindings"): the camera (set 1,
// the module's camera set) and the G-buffer and output (set 2, the pass's own); set 0 is the scene
// (caustics::SceneBindings).
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kDirectLightingBindingList[] = {
    {"camera", Kind::ConstantBuffer, 1, 0, "CameraConstants"},   // common/camera.h
    {"gNormalRoughness", Kind::SampledTexture, 2, 0, "float4"},
    {"gAlbedoMetallic", Kind::SampledTexture, 2, 1, "float4"},
    {"gLinearDepth", Kind::SampledTexture, 2, 2, "float4"},
    {"gObjectId", Kind::SampledTexture, 2, 3, "uint"},
    {"outRadiance", Kind::StorageTexture, 2, 4, "float4", ImageFormat::Rgba16f},
};

inline constexpr PassBindings kDirectLightingBindings{"direct_lighting", "passes/direct_lighting/direct_lighting_bindings.h",
                                                      kDirectLightingBindingList, "", ""};

}  // namespace caustics::shader_bindings
