#pragma once
// caustics.backward's shader resources (set 1; set 0 is the scene, caustics::SceneBindings), declared
// once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kBackwardBindingList[] = {
    {"camera", Kind::ConstantBuffer, 1, 0, "CameraConstants"},                          // common/camera.h
    {"spheres", Kind::StorageBufferRW, 1, 3, "CausticSphere", ImageFormat::None, 64},   // common/caustic_hit.h
    {"sphereAabbs", Kind::StorageBufferRW, 1, 4, "float"},   // min xyz, max xyz per slot: the sphere BLAS's input
    {"stats", Kind::StorageBufferRW, 1, 5, "uint"},          // common/caustic_stats.h
    {"specularPixels", Kind::StorageBufferRO, 1, 6, "uint"}, // caustics.specularPixels' list
};

inline constexpr PassBindings kBackwardBindings{"backward", "passes/backward_trace/backward_bindings.h",
                                                kBackwardBindingList, "BackwardParams", "params"};

}  // namespace caustics::shader_bindings
