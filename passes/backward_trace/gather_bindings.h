#pragma once
// caustics.gather's shader resources (one set), declared once (docs/shaders.md, "Bindings"). The three
// variants differ only in the radiance word the any-hit adds to: float (float atomics), uint (32-bit
// fixed point) or uint64_t (64-bit fixed point; docs/caustics.md, "Fixed point"); the ray generation,
// miss and intersection shaders include the float one.
#include <array>

#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

constexpr std::array<Binding, 6> gatherBindingList(std::string_view radianceWord, uint32_t radianceStride) {
    return {{
        {"sphereTlas", Kind::AccelStruct, 0, 0, ""},                                       // caustics.sphereTlas
        {"spheres", Kind::StorageBufferRO, 0, 1, "CausticSphere", ImageFormat::None, 64},  // common/caustic_hit.h
        {"hits", Kind::StorageBufferRO, 0, 2, "CausticHitRecord", ImageFormat::None, 64},  // common/caustic_hit.h
        {"stats", Kind::StorageBufferRW, 0, 3, "uint"},                                    // common/caustic_stats.h
        {"radianceWords", Kind::StorageBufferRW, 0, 4, radianceWord, ImageFormat::None, radianceStride},   // 3 per pixel
        // Each pixel's list entry when the second type is kept in list order (common/specular_list.h).
        {"specularIndex", Kind::SampledTexture, 0, 5, "uint4"},
    }};
}

inline constexpr auto kGatherBindingList = gatherBindingList("float", 4);
inline constexpr auto kGatherFixedBindingList = gatherBindingList("uint", 4);
inline constexpr auto kGatherFixed64BindingList = gatherBindingList("uint64_t", 8);

inline constexpr PassBindings kGatherBindings{"gather", "passes/backward_trace/gather_bindings.h", kGatherBindingList,
                                              "GatherParams", "params"};
inline constexpr PassBindings kGatherFixedBindings{"gather_fixed", "passes/backward_trace/gather_bindings.h",
                                                   kGatherFixedBindingList, "GatherParams", "params"};
inline constexpr PassBindings kGatherFixed64Bindings{"gather_fixed64", "passes/backward_trace/gather_bindings.h",
                                                     kGatherFixed64BindingList, "GatherParams", "params"};

}  // namespace caustics::shader_bindings
