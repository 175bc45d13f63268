// View coverage of a cluster's receivers (caustics/caustic_importance.h).
#include "caustics/caustic_importance.h"

#include <algorithm>
#include <cmath>

namespace caustics {

CausticView causticViewOf(const CameraConstants& camera) {
    CausticView v;
    v.viewProj = camera.viewProj;
    v.eye = glm::vec3(camera.eye);
    v.forward = glm::vec3(camera.forward);
    v.tanHalfFovY = camera.forward.w > 0.0f ? camera.forward.w : 1.0f;
    v.width = std::max(camera.frame.x, 1u);
    v.height = std::max(camera.frame.y, 1u);
    return v;
}

glm::vec4 causticReceiverSphere(glm::vec4 cluster, float reach) {
    return glm::vec4(glm::vec3(cluster), cluster.w * (1.0f + std::max(reach, 0.0f)));
}

float viewCoverage(const CausticView& view, glm::vec4 sphere) {
    const glm::vec3 c(sphere);
    const float r = sphere.w;
    const float distance = glm::length(c - view.eye);
    if (distance <= r) return 1.0f;
    if (glm::dot(c - view.eye, view.forward) < -r) return 0.0f;   // behind the eye
    // Side planes of the clip volume (-w <= x, y <= w) from the rows of viewProj (Gribb & Hartmann
    // 2001); they hold for any depth convention (reversed or infinite far), which only moves z.
    const glm::mat4 m = glm::transpose(view.viewProj);   // m[i] = row i of viewProj
    for (int axis = 0; axis < 2; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec4 plane = m[3] + sign * m[axis];
            const float len = glm::length(glm::vec3(plane));
            if (len <= 0.0f) continue;
            plane /= len;
            if (glm::dot(glm::vec3(plane), c) + plane.w < -r) return 0.0f;
        }
    }
    // Angular radius asin(r / d); the projected disk's radius on the image plane is tan of it, in
    // units of the half image height tanHalfFovY.
    const float tanAngle = r / std::sqrt(std::max(distance * distance - r * r, 1e-20f));
    const float radiusPx = tanAngle / view.tanHalfFovY * 0.5f * float(view.height);
    const float covered = 3.14159265f * radiusPx * radiusPx / (float(view.width) * float(view.height));
    return std::clamp(covered, 0.0f, 1.0f);
}

}  // namespace caustics
