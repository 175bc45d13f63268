#pragma once
// The filter's tile passes' shader resources, declared once (docs/shaders.md, "Bindings"):
// caustics.filterTiles (the tile state) and caustics.filterTiles.list (the list and the slot map).
#include "bindings/shader_binding.h"

namespace caustics::shader_bindings {

inline constexpr Binding kCausticFilterTilesBindingList[] = {
    {"camera", Kind::ConstantBuffer, 0, 0, "CameraConstants"},   // scene/camera.glsl, camera.hlsli
    {"current", Kind::SampledTexture, 0, 1, "float4"},           // this frame, unfiltered (caustics.resolve)
    {"gLinearDepth", Kind::SampledTexture, 0, 2, "float4"},
    {"gObjectId", Kind::SampledTexture, 0, 3, "uint"},
    {"previousTiles", Kind::SampledTexture, 0, 4, "uint"},       // last frame's tile state
    {"tileState", Kind::StorageTexture, 0, 5, "uint", ImageFormat::R32ui},
    {"tileArgs", Kind::StorageBufferRW, 0, 6, "uint"},           // set to (0, 1, 1, 0) for the list pass
    {"specularIndex", Kind::SampledTexture, 0, 7, "uint4"},   // list order: each pixel's entry (common/specular_list.h)
};
inline constexpr Binding kCausticTileListBindingList[] = {
    {"tileState", Kind::StorageTexture, 0, 0, "uint", ImageFormat::R32ui},   // read, and 0 -> 1 for neighbours
    {"tileArgs", Kind::StorageBufferRW, 0, 1, "uint"},                        // (listed, 1, 1, wanted)
    {"tiles", Kind::StorageBufferRW, 0, 2, "uint"},                           // the list, x | y << 16
    {"slotMap", Kind::StorageTexture, 0, 3, "uint", ImageFormat::R32ui},
};

inline constexpr PassBindings kCausticFilterTilesBindings{"caustic_filter_tiles", "passes/caustic_filter/tiles_bindings.h",
                                                          kCausticFilterTilesBindingList, "FilterTilesParams", "params"};
inline constexpr PassBindings kCausticTileListBindings{"caustic_tile_list", "passes/caustic_filter/tiles_bindings.h",
                                                       kCausticTileListBindingList, "TileListParams", "params"};

}  // namespace caustics::shader_bindings
