#pragma once
// The object-id remap pass's shader resources, declared once (docs/shaders.md, "Bindings").
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kRemapObjectIdsBindingList[] = {
    {"hostObjectId", Kind::SampledTexture, 0, 0, "uint"},
    {"pairs", Kind::StorageBufferRO, 0, 1, "uint2"},   // (hostId, moduleId), sorted by hostId
    {"moduleObjectId", Kind::StorageTexture, 0, 2, "uint", ImageFormat::R32ui},
};

inline constexpr PassBindings kRemapObjectIdsBindings{"remap_object_ids", "passes/gbuffer/remap_object_ids_bindings.h",
                                                      kRemapObjectIdsBindingList, "ObjectIdRemapParams", "params"};

}  // namespace caustics::shader_bindings
