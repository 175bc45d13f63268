#include "caustics/camera_view.h"

#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace caustics {
namespace {

std::string entry(int column, int row) {
    return "proj[" + std::to_string(column) + "][" + std::to_string(row) + "]";
}

}  // namespace

// Clip z of a perspective projection with proj[2][3] = -1 and proj[3][3] = 0, at view distance d
// along the axis (view z = -d): z_ndc(d) = -A + B / d with A = proj[2][2], B = proj[3][2].
// Standard depth (0 near, 1 far): A <= -1, B < 0, near = B / A, far = B / (1 + A) (infinite: A = -1).
// Reversed depth (1 near, 0 far): A >= 0, B > 0, near = B / (1 + A), far = B / A (infinite: A = 0).
Result<ProjectionInfo> analyzeProjection(const glm::mat4& proj, uint32_t width, uint32_t height) {
    if (width < 1 || height < 1) return makeError("analyzeProjection: image size is 0");
    const int zeros[][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 0}, {1, 2}, {1, 3}, {3, 0}, {3, 1}, {3, 3}};
    for (const auto& z : zeros)
        if (proj[z[0]][z[1]] != 0.0f)
            return makeError("CameraView::proj is not a perspective projection: " + entry(z[0], z[1]) + " = " +
                             std::to_string(proj[z[0]][z[1]]) + ", expected 0");
    if (proj[2][3] != -1.0f)
        return makeError("CameraView::proj: " + entry(2, 3) + " = " + std::to_string(proj[2][3]) +
                         ", expected -1 (right-handed view looking down -Z)");
    if (!(proj[0][0] > 0.0f))
        return makeError("CameraView::proj: " + entry(0, 0) + " must be > 0 (x right)");
    if (!(proj[1][1] < 0.0f))
        return makeError("CameraView::proj: " + entry(1, 1) + " must be < 0 (Vulkan clip space, y down: flip y in proj)");
    const float a = proj[2][2], b = proj[3][2];
    ProjectionInfo info;
    info.tanHalfFovY = 1.0f / -proj[1][1];
    info.aspect = -proj[1][1] / proj[0][0];
    info.jitterPixels = glm::vec2(-proj[2][0] * 0.5f * float(width), -proj[2][1] * 0.5f * float(height));
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    if (b > 0.0f) {
        info.reversedZ = true;
        info.nearPlane = b / (1.0f + a);
        info.farPlane = a > 0.0f ? b / a : kInfinity;
        if (a < 0.0f) return makeError("CameraView::proj: reversed depth (" + entry(3, 2) + " > 0) needs " + entry(2, 2) + " >= 0");
    } else if (b < 0.0f && a < 0.0f) {
        info.nearPlane = b / a;
        info.farPlane = a < -1.0f ? b / (1.0f + a) : kInfinity;
        if (a > -1.0f) return makeError("CameraView::proj: " + entry(2, 2) + " > -1 puts the far plane behind the camera");
    } else {
        return makeError("CameraView::proj: " + entry(2, 2) + " and " + entry(3, 2) +
                         " give no depth range in [0, 1] in front of the camera");
    }
    if (!(info.nearPlane > 0.0f) || !(info.farPlane > info.nearPlane))
        return makeError("CameraView::proj: near " + std::to_string(info.nearPlane) + " and far " +
                         std::to_string(info.farPlane) + " are not 0 < near < far");
    return info;
}

CameraView cameraViewMatrices(const scene::Camera& camera, uint32_t width, uint32_t height,
                              const ProjectionOptions& options) {
    CameraView v;
    v.view = glm::lookAtRH(camera.eye, camera.target, camera.up);
    const float t = std::tan(0.5f * camera.verticalFovRadians);
    const float aspect = float(width) / float(std::max(height, 1u));
    const float n = camera.nearPlane, f = camera.farPlane;
    glm::mat4 p(0.0f);
    p[0][0] = 1.0f / (t * aspect);
    p[1][1] = -1.0f / t;   // Vulkan clip space: y down
    p[2][3] = -1.0f;
    if (options.reversedZ) {
        p[2][2] = options.infiniteFar ? 0.0f : n / (f - n);
        p[3][2] = options.infiniteFar ? n : n * f / (f - n);
    } else {
        p[2][2] = options.infiniteFar ? -1.0f : f / (n - f);
        p[3][2] = options.infiniteFar ? -n : n * f / (n - f);
    }
    // A clip-space offset of the projection centre: NDC shift = 2 * pixels / size (see analyzeProjection).
    p[2][0] = -2.0f * options.jitterPixels.x / float(std::max(width, 1u));
    p[2][1] = -2.0f * options.jitterPixels.y / float(std::max(height, 1u));
    v.proj = p;
    return v;
}

glm::mat4 jitterClipMatrix(const glm::mat4& clipMatrix, glm::vec2 jitterPixels, uint32_t width, uint32_t height) {
    glm::mat4 shift(1.0f);
    shift[3][0] = 2.0f * jitterPixels.x / float(std::max(width, 1u));
    shift[3][1] = 2.0f * jitterPixels.y / float(std::max(height, 1u));
    return shift * clipMatrix;
}

}  // namespace caustics
