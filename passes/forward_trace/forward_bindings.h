#pragma once
// caustics.forward's shader resources (set 1; set 0 is the scene, caustics::SceneBindings), declared
// once (docs/shaders.md, "Bindings"). The three variants differ only in the radiance word: float
// (float atomics), uint (32-bit fixed point) or uint64_t (64-bit fixed point; docs/caustics.md,
// "Fixed point").
#include <array>

#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

constexpr std::array<Binding, 12> forwardBindingList(std::string_view radianceWord, uint32_t radianceStride) {
    return {{
        {"camera", Kind::ConstantBuffer, 1, 0, "CameraConstants"},          // common/camera.h
        {"maps", Kind::StorageBufferRO, 1, 1, "CausticMap", {}, 176},       // common/caustic_map.h
        {"emitters", Kind::StorageBufferRO, 1, 2, "uint"},                  // packEmitter, layer x mapSize^2
        {"gLinearDepth", Kind::SampledTexture, 1, 3, "float4"},
        {"gObjectId", Kind::SampledTexture, 1, 4, "uint"},
        {"radianceWords", Kind::StorageBufferRW, 1, 5, radianceWord, {}, radianceStride},   // 3 per pixel
        {"hits", Kind::StorageBufferRW, 1, 6, "CausticHitRecord", {}, 64},  // common/caustic_hit.h
        {"stats", Kind::StorageBufferRW, 1, 7, "uint"},                     // common/caustic_stats.h
        {"plans", Kind::StorageBufferRW, 1, 8, "CausticLayerPlan", {}, 32}, // common/layer_plan.h
        {"owners", Kind::StorageBufferRO, 1, 9, "uint"},                    // instance -> layer, per light row
        // Caster motion (common/caster_motion.h): 3 rows per instance, 4 words per pixel.
        {"instanceMotion", Kind::StorageBufferRO, 1, 10, "float4"},
        {"casterMotion", Kind::StorageBufferRW, 1, 11, "uint"},
    }};
}

inline constexpr auto kForwardBindingList = forwardBindingList("float", 4);
inline constexpr auto kForwardFixedBindingList = forwardBindingList("uint", 4);
inline constexpr auto kForwardFixed64BindingList = forwardBindingList("uint64_t", 8);

inline constexpr PassBindings kForwardBindings{"forward", "passes/forward_trace/forward_bindings.h",
                                               kForwardBindingList, "ForwardParams", "params"};
inline constexpr PassBindings kForwardFixedBindings{"forward_fixed", "passes/forward_trace/forward_bindings.h",
                                                    kForwardFixedBindingList, "ForwardParams", "params"};
inline constexpr PassBindings kForwardFixed64Bindings{"forward_fixed64", "passes/forward_trace/forward_bindings.h",
                                                      kForwardFixed64BindingList, "ForwardParams", "params"};

}  // namespace caustics::shader_bindings
