#pragma once
// CPU planning of the caustic visibility maps (paper section 3.2, Figure 3): which lights can form
// caustics, and the light-space frustum of each map, fitted to the specular objects' bounds:
//   spot        perspective, aimed at the specular bounding sphere, half-angle clipped to the cone
//   point       perspective fitted to the specular bounding sphere; when the light is inside the
//               bounds, a wide frustum (kWideHalfAngle) aimed at the specular centroid (documented
//               coverage loss; a cube map would waste 5/6 of its texels on most frames)
//   directional orthographic, fitted laterally to the specular sphere, depth range to the scene
// A light whose frustum contains no specular instance (per-instance bounding spheres) is skipped
// before anything is rasterised or traced, and each map rasterises only the specular instances whose
// bounding sphere touches its frustum (with `drawOccluders`, the other instances there too; the forward
// pass reads nothing else; docs/caustics.md, "Cost" and "Maps without occluders").
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics {

inline constexpr uint32_t kMaxCausticLights = 60;
inline constexpr float kWideHalfAngle = 1.3089969f;   // 75 degrees

// std430 mirror: shaders/vulkan/caustic_maps/caustic_map.glsl (160 bytes).
struct CausticMapGpu {
    glm::vec3 origin{0.0f};   // perspective: light position; orthographic: centre of the map plane
    uint32_t light = 0;       // scene light index
    glm::vec3 right{1, 0, 0};
    float extent = 1.0f;      // perspective: tan(half-angle); orthographic: half-extent (m)
    glm::vec3 up{0, 1, 0};
    uint32_t orthographic = 0;
    glm::vec3 forward{0, 0, -1};
    float nearPlane = 0.01f;
    glm::vec3 intensity{0.0f};  // colour x candela (perspective) or colour x lux (orthographic)
    float cosInner = 1.0f;
    glm::vec3 spotAxis{0, 0, -1};
    float cosOuter = -2.0f;     // <= -1: no cone (point, directional)
    glm::mat4 viewProj{1.0f};   // world -> clip of the raster (Vulkan clip, z 0..1)
};
static_assert(sizeof(CausticMapGpu) == 160);

struct SpecularBounds {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
    std::vector<glm::vec4> instanceSpheres;   // xyz centre, w radius, one per specular instance
    std::vector<glm::vec4> allInstanceSpheres;   // one per scene instance (radius < 0: no geometry)
    std::vector<bool> instanceIsSpecular;        // one per scene instance
    glm::vec3 sceneCentre{0.0f};
    float sceneRadius = 0.0f;
    bool empty() const { return instanceSpheres.empty(); }
};
SpecularBounds computeSpecularBounds(const scene::Scene& scene);

struct CausticMapPlan {
    std::vector<CausticMapGpu> maps;          // one per texture-array layer
    std::vector<uint32_t> skippedLights;      // scene light indices without a map
    std::vector<std::string> skipReasons;     // parallel to skippedLights
    // Parallel to maps: the instances inside its frustum it rasterises (specular ones; all with occluders).
    std::vector<std::vector<uint32_t>> drawnInstances;
};

// Does the bounding sphere (xyz centre, w radius) touch the volume map m rasterises? Perspective: the
// cone circumscribing the square frustum; orthographic: the cylinder around the square, in front of
// the map plane. Conservative: a `true` may still rasterise nothing.
bool mapFrustumTouchesSphere(const CausticMapGpu& m, glm::vec4 sphere);

// drawOccluders: CausticsSettings::mapOccluders. The map only chooses the texels that emit; the forward
// ray starts at the light and finds the true first hit, so a map without occluders emits from a
// superset of the texels and the estimator stays unbiased (photons that meet an occluder end there).
CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, bool drawOccluders = false);

}  // namespace caustics
