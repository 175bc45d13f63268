#include "caustics/camera_constants.h"

#include <cmath>
#include <string>

namespace caustics {

Result<CameraConstants> makeCameraConstants(const glm::mat4& view, const glm::mat4& proj, uint32_t width,
                                            uint32_t height, uint32_t frameIndex, const glm::mat4* prevViewProj) {
    CAUSTICS_TRY(ProjectionInfo p, analyzeProjection(proj, width, height));
    // The view must be rigid (rotation + translation): its rows 0..2 are the camera's world axes.
    const glm::mat3 r(view);
    const glm::mat3 shouldBeIdentity = glm::transpose(r) * r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(shouldBeIdentity[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-3f)
                return makeError("CameraView::view is not a rigid transform (rotation + translation): its 3x3 part "
                                 "is not orthonormal (entry [" + std::to_string(i) + "][" + std::to_string(j) + "])");
    if (view[0][3] != 0.0f || view[1][3] != 0.0f || view[2][3] != 0.0f || view[3][3] != 1.0f)
        return makeError("CameraView::view has a projective last row; expected (0, 0, 0, 1)");

    CameraConstants c;
    c.view = view;
    c.proj = proj;
    c.viewProj = proj * view;
    c.invViewProj = glm::inverse(c.viewProj);
    c.prevViewProj = prevViewProj ? *prevViewProj : c.viewProj;

    // Rows of the view's rotation are the camera's right, up and backward axes in world space.
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
    const glm::vec3 back(view[0][2], view[1][2], view[2][2]);
    const glm::mat4 inverseView = glm::inverse(view);
    c.eye = glm::vec4(glm::vec3(inverseView[3]), p.jitterPixels.x);
    c.forward = glm::vec4(-back, p.tanHalfFovY);
    c.right = glm::vec4(right, p.aspect);
    c.up = glm::vec4(up, p.jitterPixels.y);
    c.clip = glm::vec4(p.nearPlane, std::isinf(p.farPlane) ? 0.0f : p.farPlane, 1.0f / float(width), 1.0f / float(height));
    c.frame = glm::uvec4(width, height, frameIndex, p.reversedZ ? 1u : 0u);
    return c;
}

Result<CameraConstants> makeCameraConstants(const scene::Camera& camera, uint32_t width, uint32_t height,
                                            uint32_t frameIndex, const glm::mat4* prevViewProj) {
    if (!(camera.verticalFovRadians > 0.0f && camera.verticalFovRadians < 3.1f))
        return makeError("scene::Camera::verticalFovRadians " + std::to_string(camera.verticalFovRadians) +
                         " is outside (0, 3.1)");
    if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane))
        return makeError("scene::Camera: nearPlane must be > 0 and farPlane > nearPlane");
    if (!(glm::length(camera.target - camera.eye) > 0.0f) ||
        !(glm::length(glm::cross(camera.target - camera.eye, camera.up)) > 0.0f))
        return makeError("scene::Camera: eye == target, or up is parallel to the view direction");
    if (width < 1 || height < 1) return makeError("makeCameraConstants: image size is 0");
    CameraView v = cameraViewMatrices(camera, width, height);
    return makeCameraConstants(v.view, v.proj, width, height, frameIndex, prevViewProj);
}

}  // namespace caustics
