// Nephroid caustic of a polished ring: parallel light reflected inside a circular mirror of radius a
// forms a nephroid whose cusp lies a/2 from the centre, on the side the light travels towards
// (the caustic point of a ray reflected at incidence angle i lies a cos(i)/2 from the mirror; i = 0 on
// the axis). With the light at elevation e, a vertical wall keeps the vertical direction component,
// so in top view every reflected ray follows its 2D path and reaches the floor a horizontal distance
// z / tan(e) after reflecting at height z: the floor caustic is the same nephroid, and its cusp is
// lit by rays reflected at z = (a/2) tan(e), which the band must contain (docs/physics.md).
#include <cmath>

#include <gtest/gtest.h>

#include "test_scenes.h"

using namespace caustics;
using namespace caustics::physics;

TEST(MetalRing, NephroidCuspLiesHalfARadiusFromCentre) {
    const float a = 1.0f, height = 0.3f, elevation = glm::radians(20.0f);
    ASSERT_LT(0.5f * a * std::tan(elevation), height);  // the cusp ray hits the band
    scene::Scene s;
    addObject(s, makeQuadY(0.0f, -3.0f, 3.0f, -3.0f, 3.0f), diffuseMaterial(0.8f));
    addObject(s, makeCylinderBand(a, 0.0f, height, 512), mirrorMetal(0.9f));
    s.lights.push_back(directionalLight({std::cos(elevation), -std::sin(elevation), 0.0f}, 1.0f));
    scene::Camera cam;
    cam.eye = {0.0f, 5.0f, 0.0f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 0.0f, -1.0f};
    cam.verticalFovRadians = 2.0f * std::atan(1.2f / 5.0f);
    reference::ReferenceOptions o;
    // Odd size: a pixel row is centred on the symmetry axis. Near the cusp the fold arms run at
    // x - a/2 = 0.75 a (z/a)^(2/3) (expand the nephroid for small incidence angles), so rows that
    // straddle the axis would see the arms' crossing 3 pixels beyond the cusp instead of the cusp.
    o.width = o.height = 255;
    o.photonsPerLight = 4'000'000;
    o.maxDepth = 3;
    o.threads = 2;
    auto image = reference::renderCausticsReference(s, cam, o);
    ASSERT_TRUE(image.ok()) << image.message();

    // Brightest pixel inside 0.8 a (away from the wall's foot). No smoothing: a box filter would
    // pull the maximum into the cusp's interior, where the three ray sheets overlap.
    std::vector<glm::vec3> floorPoint(size_t(o.width) * o.height, glm::vec3(1e9f));
    double footprint = 0;
    forEachPixelOnPlane(cam, o.width, o.height, 0.0f, [&](uint32_t x, uint32_t y, glm::vec3 p, float fp) {
        floorPoint[size_t(y) * o.width + x] = p;
        footprint = std::max(footprint, std::sqrt(double(fp)));
    });
    double best = -1;
    glm::vec3 cusp(0.0f);
    for (uint32_t y = 1; y + 1 < o.height; ++y) {
        for (uint32_t x = 1; x + 1 < o.width; ++x) {
            glm::vec3 p = floorPoint[size_t(y) * o.width + x];
            if (glm::length(glm::vec2(p.x, p.z)) > 0.8f * a) continue;
            double sum = image->at(x, y).x;
            if (sum > best) { best = sum; cusp = p; }
        }
    }
    ASSERT_GT(best, 0.0);
    // Tolerance: two pixel footprints (the brief's); the 512-gon's facets move the cusp by < 1e-4 a.
    EXPECT_NEAR(cusp.x, 0.5f * a, 2.0 * footprint) << "cusp at " << cusp.x << "," << cusp.z;
    EXPECT_NEAR(cusp.z, 0.0f, 2.0 * footprint);
}
