#pragma once
// The composite pass's shader resources, declared once (docs/shaders.md, "Bindings"): the shaders'
// declarations are generated from this, the pass builds its layout and fills its set by these names.
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCompositeBindingList[] = {
    {"direct", Kind::SampledTexture, 0, 0, "float4"},
    {"caustics", Kind::SampledTexture, 0, 1, "float4"},
    {"albedoMetallic", Kind::SampledTexture, 0, 2, "float4"},
    {"normalRoughness", Kind::SampledTexture, 0, 3, "float4"},
    {"linearDepth", Kind::SampledTexture, 0, 4, "float4"},
    {"display", Kind::StorageTexture, 0, 5, "float4", ImageFormat::Rgba8},
    {"hdr", Kind::StorageTexture, 0, 6, "float4", ImageFormat::Rgba32f},
};

inline constexpr PassBindings kCompositeBindings{"composite", "passes/composite/composite_bindings.h",
                                                 kCompositeBindingList, "CompositeParams", "params"};

}  // namespace caustics::shader_bindings
