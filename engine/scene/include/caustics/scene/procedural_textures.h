#pragma once
// Small procedural textures (sRGB RGBA8) so the built-in scenes have texture detail without files.
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::scene {

// Square tiles with grout lines; `jitter` varies each tile's brightness.
Texture makeTileTexture(uint32_t size, const glm::vec3& tileColor, const glm::vec3& groutColor, uint32_t tiles,
                        float jitter, uint32_t seed);
// Value-noise stone / plaster.
Texture makeNoiseTexture(uint32_t size, const glm::vec3& color, float amplitude, uint32_t seed);
// Wood-grain stripes (table top).
Texture makeWoodTexture(uint32_t size, const glm::vec3& light, const glm::vec3& dark, uint32_t seed);
// 1x1 texture of one colour (the missing-image replacement is white).
Texture makeSolidTexture(const glm::vec3& color, const std::string& name);

}  // namespace caustics::scene
