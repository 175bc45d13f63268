#include "bench_scene.h"

#include <algorithm>
#include <cmath>

#include "caustics/caustic_map_plan.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::bench {

void addRingLights(scene::Scene& scene, uint32_t count) {
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
        l.name = "bench ring light " + std::to_string(i);
        l.position = bounds.centre + glm::vec3(ring * std::cos(angle), height, ring * std::sin(angle));
        const glm::vec3 toCentre = bounds.centre - l.position;
        const float distance = glm::length(toCentre);
        l.direction = toCentre / distance;
        l.outerConeAngle = std::min(1.2f, 1.5f * std::asin(std::min(1.0f, bounds.radius / distance)));
        l.innerConeAngle = 0.8f * l.outerConeAngle;
        scene.lights.push_back(l);
    }
}

const char* viewName(BenchView view) { return view == BenchView::Visible ? "visible" : "away"; }

scene::Camera benchCamera(const scene::Scene& scene, BenchView view) {
    scene::Camera camera = scene.cameras.empty() ? scene::Camera{} : scene.cameras.front();
    if (view == BenchView::Away) camera.target = camera.eye - (camera.target - camera.eye);
    return camera;
}

Result<scene::Scene> loadBenchScene(const std::string& name, uint32_t extraLights) {
    CAUSTICS_TRY(scene::Scene sc, scene::makeBuiltin(name));
    addRingLights(sc, extraLights);
    return sc;
}

}  // namespace caustics::bench
