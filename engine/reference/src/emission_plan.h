#pragma once
// Per light, the emission maps the reference tracer shoots photons through: the same texel grids and
// flux normalisation the GPU caustic visibility maps use (shaders/common/emission.h).
#include <cstdint>
#include <vector>

#include "caustics/scene/scene.h"
#include "world.h"

namespace caustics::reference {

struct EmissionMap {
    bool orthographic = false;
    glm::vec3 origin{0.0f};      // perspective: light position; orthographic: map centre
    glm::vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
    float tanHalfAngle = 1.0f;   // perspective
    float halfExtent = 1.0f;     // orthographic
    uint32_t size = 1;           // size x size texels, one photon each
};

struct EmissionPlan {
    std::vector<EmissionMap> maps;
    uint64_t photonCount() const;
};

// fitToSpecular: aim the maps at the specular geometry only (valid in caustics-only mode: a photon
// whose first hit is diffuse never contributes there).
EmissionPlan planEmission(const scene::Light& light, const WorldScene& world, uint64_t photons, bool fitToSpecular);

}  // namespace caustics::reference
