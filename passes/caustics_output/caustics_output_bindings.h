#pragma once
// The caustics-only output pass's shader resources, declared once (docs/shaders.md, "Bindings"): the
// shaders' declarations are generated from this, the pass builds its layout and fills its set by these names.
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticsOutputBindingList[] = {
    {"caustics", Kind::SampledTexture, 0, 0, "float4"},
};

inline constexpr PassBindings kCausticsOutputBindings{"caustics_output", "passes/caustics_output/caustics_output_bindings.h",
                                                      kCausticsOutputBindingList, "CausticsOutputParams", "params"};

}  // namespace caustics::shader_bindings
