#include "camera_setup.h"

#include <algorithm>
#include <cmath>

namespace caustics::sample {

SceneBounds computeSceneBounds(const scene::Scene& s) {
    SceneBounds b;
    b.min = glm::vec3(INFINITY);
    b.max = glm::vec3(-INFINITY);
    std::vector<std::pair<glm::vec3, glm::vec3>> meshBoxes(s.meshes.size(), {glm::vec3(INFINITY), glm::vec3(-INFINITY)});
    for (size_t m = 0; m < s.meshes.size(); ++m)
        for (const glm::vec3& p : s.meshes[m].positions) {
            meshBoxes[m].first = glm::min(meshBoxes[m].first, p);
            meshBoxes[m].second = glm::max(meshBoxes[m].second, p);
        }
    for (const scene::Instance& inst : s.instances) {
        if (inst.mesh >= meshBoxes.size()) continue;
        auto [lo, hi] = meshBoxes[inst.mesh];
        if (lo.x > hi.x) continue;
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 p{(corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z};
            glm::vec3 w = glm::vec3(inst.transform * glm::vec4(p, 1.0f));
            if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) continue;
            b.min = glm::min(b.min, w);
            b.max = glm::max(b.max, w);
            b.empty = false;
        }
    }
    if (b.empty) b.min = b.max = glm::vec3(0.0f);
    return b;
}

scene::Camera framingCamera(const SceneBounds& bounds, float verticalFovRadians) {
    scene::Camera c;
    c.verticalFovRadians = verticalFovRadians;
    float radius = std::max(bounds.radius(), 1e-3f);
    // Distance at which the bounding sphere fits the vertical field of view, plus a margin.
    float distance = 1.1f * radius / std::sin(0.5f * verticalFovRadians);
    glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
    c.target = bounds.centre();
    c.eye = c.target + distance * direction;
    return c;
}

glm::vec3 robustUp(const glm::vec3& forward, const glm::vec3& preferredUp) {
    glm::vec3 f = glm::normalize(forward);
    glm::vec3 up = glm::normalize(preferredUp);
    // lookAt needs cross(forward, up) != 0; below ~0.06 degrees of parallel the basis loses precision.
    if (glm::length(glm::cross(f, up)) > 1e-3f) return up;
    return f.y < 0.0f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
}

void fitClipPlanes(scene::Camera& camera, const SceneBounds& bounds) {
    if (bounds.empty) return;
    // 24-bit-class depth precision holds for far/near up to ~1e5 (reversed or not); stay well inside.
    constexpr float kMaxFarOverNear = 1e5f;
    float farthest = glm::length(bounds.centre() - camera.eye) + bounds.radius();
    float far = std::max(camera.farPlane, 1.01f * farthest);
    camera.farPlane = far;
    camera.nearPlane = std::max(camera.nearPlane, far / kMaxFarOverNear);
}

scene::Camera cameraFromOptions(const scene::Scene& s, const CliOptions& o) {
    SceneBounds bounds = computeSceneBounds(s);
    scene::Camera camera = s.cameras.empty() ? framingCamera(bounds, 0.785398f) : s.cameras.front();
    if (o.camera) {
        camera.eye = o.camera->eye;
        camera.target = o.camera->target;
        camera.verticalFovRadians = o.camera->verticalFovDegrees * 3.14159265f / 180.0f;
        camera.up = o.camera->up.value_or(glm::vec3(0.0f, 1.0f, 0.0f));
    }
    camera.up = robustUp(camera.target - camera.eye, camera.up);
    fitClipPlanes(camera, bounds);
    return camera;
}

}  // namespace caustics::sample
