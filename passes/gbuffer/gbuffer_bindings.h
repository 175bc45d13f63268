#pragma once
// gbuffer's shader resources, declared once (docs/shaders.md, "Bindings"): the camera (set 1, the
// module's camera set) and the instance drawn (push constants); set 0 is the scene
// (caustics::SceneBindings).
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kGBufferBindingList[] = {
    {"camera", Kind::ConstantBuffer, 1, 0, "CameraConstants"},   // common/camera.h
};

inline constexpr PassBindings kGBufferBindings{"gbuffer", "passes/gbuffer/gbuffer_bindings.h", kGBufferBindingList,
                                               "GBufferParams", "draw"};

}  // namespace caustics::shader_bindings
