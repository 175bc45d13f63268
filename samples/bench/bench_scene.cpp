#include "bench_scene.h"

#include <algorithm>
#include <cmath>

#include "caustics/caustic_map_plan.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::bench {

namespace {

enum class RingAim { AtSpecular, AwayFromSpecular };

void addRing(scene::Scene& scene, uint32_t count, RingAim aim) {
    const SpecularBounds bounds = computeSpecularBounds(scene);
    if (bounds.empty() || count == 0) return;
    scene::Light model;
    model.type = scene::LightType::Spot;
    model.intensity = 100.0f;
    for (const scene::Light& l : scene.lights)
        if (l.type == scene::LightType::Spot) {
            model.color = l.color;
            model.intensity = l.intensity;
            break;
        }
    const float ring = 3.0f * bounds.radius;
    const float height = 2.5f * bounds.radius;
    for (uint32_t i = 0; i < count; ++i) {
        const float angle = 6.2831853f * (float(i) + 0.5f) / float(count);
        scene::Light l = model;
        l.name = (aim == RingAim::AtSpecular ? "bench ring light " : "bench culled ring light ") + std::to_string(i);
        l.position = bounds.centre + glm::vec3(ring * std::cos(angle), height, ring * std::sin(angle));
        const glm::vec3 toCentre = bounds.centre - l.position;
        const float distance = glm::length(toCentre);
        // Away: the cone axis points from the specular centre outwards; the half-angle stays <= 1.2 rad,
        // so every specular instance (within bounds.radius of the centre, >= 180 - asin(1 / 3.9) = 165
        // degrees off axis since the ring lies 3.9 radii out) is outside it.
        l.direction = (aim == RingAim::AtSpecular ? 1.0f : -1.0f) * toCentre / distance;
        l.outerConeAngle = std::min(1.2f, 1.5f * std::asin(std::min(1.0f, bounds.radius / distance)));
        l.innerConeAngle = 0.8f * l.outerConeAngle;
        scene.lights.push_back(l);
    }
}

}  // namespace

void addRingLights(scene::Scene& scene, uint32_t count) { addRing(scene, count, RingAim::AtSpecular); }

void addCulledRingLights(scene::Scene& scene, uint32_t count) { addRing(scene, count, RingAim::AwayFromSpecular); }

const char* viewName(BenchView view) { return view == BenchView::Visible ? "visible" : "away"; }

scene::Camera benchCamera(const scene::Scene& scene, BenchView view) {
    scene::Camera camera = scene.cameras.empty() ? scene::Camera{} : scene.cameras.front();
    if (view == BenchView::Away) camera.target = camera.eye - (camera.target - camera.eye);
    return camera;
}

void sceneBox(const scene::Scene& scene, float boxMin[3], float boxMax[3]) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const scene::Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) continue;
        for (const glm::vec3& p : scene.meshes[inst.mesh].positions) {
            const glm::vec3 w = glm::vec3(inst.transform * glm::vec4(p, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    if (lo.x > hi.x) lo = hi = glm::vec3(0.0f);
    for (int i = 0; i < 3; ++i) {
        boxMin[i] = lo[i];
        boxMax[i] = hi[i];
    }
}

Result<scene::Scene> loadBenchScene(const std::string& name, uint32_t extraLights, uint32_t culledLights) {
    CAUSTICS_TRY(scene::Scene sc, scene::makeBuiltin(name));
    addRingLights(sc, extraLights);
    addCulledRingLights(sc, culledLights);
    return sc;
}

}  // namespace caustics::bench
