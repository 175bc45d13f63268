// View coverage of a cluster's receivers (caustics/caustic_importance.h).
#include "caustics/caustic_importance.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

namespace {

// Whether the sphere can be seen at all: false behind the eye or outside the clip volume's side planes
// (Gribb & Hartmann 2001, from the rows of viewProj; they hold for any depth convention, reversed or
// infinite far, which only moves z).
bool sphereMayBeSeen(const CausticView& view, glm::vec3 c, float r) {
    if (glm::dot(c - view.eye, view.forward) < -r) return false;   // behind the eye
    const glm::mat4 m = glm::transpose(view.viewProj);   // m[i] = row i of viewProj
    for (int axis = 0; axis < 2; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec4 plane = m[3] + sign * m[axis];
            const float len = glm::length(glm::vec3(plane));
            if (len <= 0.0f) continue;
            plane /= len;
            if (glm::dot(glm::vec3(plane), c) + plane.w < -r) return false;
        }
    }
    return true;
}

// viewCoverage's and imageCoverage's common cases: 1 with the eye inside, 0 where it cannot be seen.
std::optional<float> trivialCoverage(const CausticView& view, glm::vec3 c, float r, float distance) {
    if (distance <= r) return 1.0f;
    if (!sphereMayBeSeen(view, c, r)) return 0.0f;
    return std::nullopt;
}

}  // namespace

float viewCoverage(const CausticView& view, glm::vec4 sphere) {
    const glm::vec3 c(sphere);
    const float r = sphere.w;
    const float distance = glm::length(c - view.eye);
    if (const std::optional<float> trivial = trivialCoverage(view, c, r, distance)) return *trivial;
    // Angular radius asin(r / d); the projected disk's radius on the image plane is tan of it, in
    // units of the half image height tanHalfFovY.
    const float tanAngle = r / std::sqrt(std::max(distance * distance - r * r, 1e-20f));
    const float radiusPx = tanAngle / view.tanHalfFovY * 0.5f * float(view.height);
    const float covered = 3.14159265f * radiusPx * radiusPx / (float(view.width) * float(view.height));
    return std::clamp(covered, 0.0f, 1.0f);
}

float imageCoverage(const CausticView& view, glm::vec4 sphere) {
    const glm::vec3 c(sphere);
    const float r = sphere.w;
    const float distance = glm::length(c - view.eye);
    if (const std::optional<float> trivial = trivialCoverage(view, c, r, distance)) return *trivial;
    // The sphere's image on the plane at focal distance 1 is a conic section of its tangent cone: with
    // angular radius alpha = asin(r / d) and its centre theta off the view axis, an ellipse of area
    // pi sin^2(alpha) cos(alpha) / (cos^2(theta) - sin^2(alpha))^(3/2) (pi tan^2 alpha on the axis).
    const float sinAlpha = r / distance;
    const float cosAlpha = std::sqrt(std::max(1.0f - sinAlpha * sinAlpha, 0.0f));
    const float cosTheta = glm::dot(c - view.eye, view.forward) / (distance * std::max(glm::length(view.forward), 1e-20f));
    const float conic = cosTheta * cosTheta - sinAlpha * sinAlpha;
    if (cosTheta <= 0.0f || conic <= 1e-6f) return 1.0f;   // the cone reaches the image plane's horizon
    const float area = 3.14159265f * sinAlpha * sinAlpha * cosAlpha / (conic * std::sqrt(conic));
    const float aspect = float(view.width) / float(view.height);
    return std::clamp(area / (4.0f * view.tanHalfFovY * view.tanHalfFovY * aspect), 0.0f, 1.0f);
}

float imageCoverageOfBox(const CausticView& view, glm::vec3 lo, glm::vec3 hi) {
    // The screen rectangle around the projected corners, clipped to the image: exact at the border.
    glm::vec2 minNdc(1e30f), maxNdc(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        const glm::vec4 clip = view.viewProj * glm::vec4(p, 1.0f);
        if (clip.w <= 1e-6f) return 1.0f;   // a corner at or behind the eye: no bounded rectangle
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        minNdc = glm::min(minNdc, ndc);
        maxNdc = glm::max(maxNdc, ndc);
    }
    const glm::vec2 size = glm::max(glm::min(maxNdc, glm::vec2(1.0f)) - glm::max(minNdc, glm::vec2(-1.0f)), glm::vec2(0.0f));
    return std::clamp(size.x * size.y / 4.0f, 0.0f, 1.0f);
}

double imageCoverageSum(const CausticView& view, std::span<const glm::vec4> spheres, std::span<const glm::vec3> lo,
                        std::span<const glm::vec3> hi) {
    double sum = 0.0;
    for (size_t i = 0; i < spheres.size(); ++i) {
        float covered = imageCoverage(view, spheres[i]);
        // Both bound the object's image; a long or flat object fills its box's rectangle better.
        if (i < lo.size() && i < hi.size()) covered = std::min(covered, imageCoverageOfBox(view, lo[i], hi[i]));
        sum += covered;
    }
    return std::min(sum, 1.0);
}

}  // namespace caustics
