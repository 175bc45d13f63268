#pragma once
// Small helpers the physics tests use to read radiance images: projections of world points and the
// brightest pixel in a region.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "common/camera.h"
#include "caustics/scene/scene.h"

namespace caustics::test {

inline shader::PinholeCamera pinhole(const scene::Camera& c, uint32_t w, uint32_t h) {
    return shader::makePinholeCamera(c.eye, c.target, c.up, c.verticalFovRadians, float(w), float(h));
}

inline float luminance(const glm::vec3& v) { return 0.2126f * v.x + 0.7152f * v.y + 0.0722f * v.z; }

struct Peak {
    int x = -1, y = -1;
    float value = 0.0f;
};

// Brightest pixel (by luminance) of `img` among pixels where `inside(x, y)` holds.
template <typename Pred>
Peak brightest(const std::vector<glm::vec3>& img, uint32_t w, uint32_t h, Pred inside) {
    Peak p;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            if (inside(x, y) && luminance(img[size_t(y) * w + x]) > p.value) p = {int(x), int(y), luminance(img[size_t(y) * w + x])};
    return p;
}

// Point on the plane y = 0 seen through the centre of pixel (x, y); false if the ray misses it.
inline bool planePoint(const shader::PinholeCamera& cam, uint32_t x, uint32_t y, glm::vec3& p) {
    glm::vec3 d = shader::cameraRayDirection(cam, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
    if (d.y >= -1e-6f) return false;
    p = cam.eye + d * (-cam.eye.y / d.y);
    return true;
}

}  // namespace caustics::test
