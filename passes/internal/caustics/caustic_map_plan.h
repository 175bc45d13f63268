#pragma once
// CPU planning of the caustic visibility maps (paper section 3.2, Figure 3): which lights can form
// caustics, and one texture-array layer per (light, cluster of specular objects) it reaches, each
// layer's light-space frustum fitted to its cluster (caustics/specular_clusters.h), so a texel's
// footprint on an object does not depend on where other objects stand (docs/caustics.md, "Layers per
// cluster"):
//   spot        perspective, aimed at the cluster's bounding sphere, half-angle clipped to the cone
//   point       perspective fitted to the cluster's sphere; when the light is inside it, a wide frustum
//               (kWideHalfAngle) aimed at its centre (documented coverage loss; a cube map would waste
//               5/6 of its texels on most frames)
//   directional orthographic, fitted laterally to the cluster's sphere (a cascade per cluster), depth
//               range to the scene
// A light's layers share its emission: a photon belongs to the layer whose cluster holds the first
// specular instance it meets (instanceLayers), so overlapping frusta never count a direction twice.
// A layer whose receivers the camera cannot see (caustics/caustic_importance.h) gets no map; the
// photon budget is split over the others by their view coverage. A light that reaches no specular
// instance (cone, range, frustum) is skipped before anything is rasterised or traced, and each map
// rasterises only the specular instances whose bounding sphere touches its frustum (with
// `drawOccluders`, the other instances there too; docs/caustics.md, "Cost" and "Maps without occluders").
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/caustic_importance.h"
#include "caustics/scene/scene.h"
#include "common/caustic_stats.h"

namespace caustics {

// Lights with a statistics slot (shaders/common/caustic_stats.h).
using shader::kMaxCausticLights;
// Layers of the map array: the emitter list packs the layer in 6 bits (common/caustic_map.h).
inline constexpr uint32_t kMaxCausticLayers = 64;
inline constexpr float kWideHalfAngle = 1.3089969f;   // 75 degrees

// std430 mirror: shaders/common/caustic_map.h (176 bytes).
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
    float range = 0.0f;         // KHR_lights_punctual range (m), 0 = infinite: deposits get its window
    float photons = 0.0f;       // photons this layer emits per frame; 0: raysPerTexel at every emitting texel
    uint32_t cluster = 0;       // the layer's number among its light's layers (random key, ownership)
    uint32_t ownerRow = 0;      // row of CausticMapPlan::instanceLayers holding this light's ownership
};
static_assert(sizeof(CausticMapGpu) == 176);

struct SpecularBounds {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
    std::vector<glm::vec4> instanceSpheres;   // xyz centre, w radius, one per specular instance
    std::vector<uint32_t> specularInstances;  // parallel to instanceSpheres: the scene instance index
    std::vector<glm::vec3> instanceLo, instanceHi;   // parallel to instanceSpheres: world bounding boxes
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
    // Parallel to maps: the specular instances the layer owns, and the part of the image their caustic's
    // receivers cover (1 when planned without a view).
    std::vector<std::vector<uint32_t>> layerInstances;
    std::vector<float> coverage;
    // Ownership, one row of instanceCount entries per light with layers (CausticMapGpu::ownerRow):
    // cluster + 1 of the layer owning that scene instance, 0 where no layer of the light does.
    uint32_t instanceCount = 0;
    std::vector<uint32_t> instanceLayers;
    // Clusters a light reaches whose caustic cannot reach the view (no layer, no photons).
    uint32_t hiddenClusters = 0;
    // Clusters merged into a neighbour's layer to stay within kMaxCausticLayers.
    uint32_t capMerges = 0;
    uint64_t photonBudget = 0;   // the sum of CausticMapGpu::photons (0: per-texel emission)
};

struct CausticPlanOptions {
    bool drawOccluders = false;   // CausticsSettings::mapOccluders
    // The camera; none: every cluster counts as seen, with coverage 1 (tools, unit tests).
    const CausticView* view = nullptr;
    float receiverReach = 4.0f;   // CausticsSettings::causticReceiverReach
    uint64_t photons = 0;         // per frame, split by coverage; 0: raysPerTexel per emitting texel
};

// Does the bounding sphere (xyz centre, w radius) touch the volume map m rasterises? Perspective: the
// cone circumscribing the square frustum; orthographic: the cylinder around the square, in front of
// the map plane. Conservative: a `true` may still rasterise nothing.
bool mapFrustumTouchesSphere(const CausticMapGpu& m, glm::vec4 sphere);

// drawOccluders: CausticsSettings::mapOccluders. The map only chooses the texels that emit; the forward
// ray starts at the light and finds the true first hit, so a map without occluders emits from a
// superset of the texels and the estimator stays unbiased (photons that meet an occluder end there).
CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, const CausticPlanOptions& options);
CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, bool drawOccluders = false);

}  // namespace caustics
