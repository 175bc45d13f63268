#include "caustics/camera_constants.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace caustics {

CameraConstants makeCameraConstants(const scene::Camera& camera, uint32_t width, uint32_t height,
                                    uint32_t frameIndex, const glm::mat4* prevViewProj) {
    CameraConstants c;
    float aspect = float(width) / float(height);
    c.view = glm::lookAtRH(camera.eye, camera.target, camera.up);
    // Vulkan clip space: depth 0..1 (ZO) and y pointing down, hence the flipped [1][1].
    c.proj = glm::perspectiveRH_ZO(camera.verticalFovRadians, aspect, camera.nearPlane, camera.farPlane);
    c.proj[1][1] = -c.proj[1][1];
    c.viewProj = c.proj * c.view;
    c.invViewProj = glm::inverse(c.viewProj);
    c.prevViewProj = prevViewProj ? *prevViewProj : c.viewProj;

    glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::vec3 up = glm::cross(right, forward);
    c.eye = glm::vec4(camera.eye, 0.0f);
    c.forward = glm::vec4(forward, std::tan(0.5f * camera.verticalFovRadians));
    c.right = glm::vec4(right, aspect);
    c.up = glm::vec4(up, 0.0f);
    c.clip = glm::vec4(camera.nearPlane, camera.farPlane, 1.0f / float(width), 1.0f / float(height));
    c.frame = glm::uvec4(width, height, frameIndex, 0u);
    return c;
}

}  // namespace caustics
