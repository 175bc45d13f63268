// The reference tracer end to end on the simplest scene with an analytic answer, plus its modes and
// determinism.
#include <cmath>

#include <gtest/gtest.h>

#include "test_scenes.h"

using namespace caustics;
using namespace caustics::physics;

namespace {
scene::Scene litPlane() {
    scene::Scene s;
    addObject(s, makeQuadY(0.0f, -4.0f, 4.0f, -4.0f, 4.0f), diffuseMaterial(0.5f));
    s.lights.push_back(directionalLight({0.0f, -1.0f, 0.0f}, 2.0f));
    return s;
}
scene::Camera obliqueCamera() {
    scene::Camera c;
    c.eye = {0.5f, 2.5f, 3.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.verticalFovRadians = glm::radians(30.0f);
    return c;
}
}  // namespace

// Light tracing in all-paths mode with no bounces (maxDepth 0) must give L = rho E / pi. Photons are
// jittered-stratified over the map, so errors are below the Poisson bound 1/sqrt(lambda) used here
// per pixel (lambda ~ 500 photons per footprint -> 5 sigma = 22%); the image mean must be within 1%.
TEST(ReferenceTracer, UniformlyLitLambertianPlaneHasRadianceRhoEOverPi) {
    reference::ReferenceOptions o;
    o.width = o.height = 32;
    o.photonsPerLight = 4'000'000;
    o.maxDepth = 0;
    o.threads = 2;
    o.mode = reference::ReferenceMode::AllLightPaths;
    auto image = reference::renderCausticsReference(litPlane(), obliqueCamera(), o);
    ASSERT_TRUE(image.ok()) << image.message();
    const double expected = 0.5 * 2.0 / M_PI;
    double sum = 0;
    int count = 0;
    forEachPixelOnPlane(obliqueCamera(), o.width, o.height, 0.0f, [&](uint32_t x, uint32_t y, glm::vec3 p, float footprint) {
        if (std::abs(p.x) > 3.9f || std::abs(p.z) > 3.9f) return;  // off the plane's edge
        double lambda = double(o.photonsPerLight) * footprint / 64.0;
        double v = image->at(x, y).x;
        EXPECT_NEAR(v / expected, 1.0, 5.0 / std::sqrt(lambda)) << x << "," << y;
        EXPECT_FLOAT_EQ(image->at(x, y).x, image->at(x, y).z);  // grey light on grey surface
        sum += v;
        ++count;
    });
    ASSERT_GT(count, 500);
    EXPECT_NEAR(sum / count / expected, 1.0, 0.01);
}

TEST(ReferenceTracer, CausticsOnlyModeOmitsDirectLight) {
    reference::ReferenceOptions o;
    o.width = o.height = 16;
    o.photonsPerLight = 20'000;
    o.threads = 2;
    auto image = reference::renderCausticsReference(litPlane(), obliqueCamera(), o);
    ASSERT_TRUE(image.ok()) << image.message();
    EXPECT_GT(image->photonsEmitted, 0u);
    EXPECT_EQ(image->photonsSplatted, 0u);
    for (const glm::vec3& p : image->pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST(ReferenceTracer, OccluderBetweenSurfaceAndCameraBlocksSplats) {
    scene::Scene s = litPlane();
    // A box close to the camera fills its whole view; only light reaching the box faces the camera
    // sees could still be splatted, and a light from straight above reaches none of them.
    scene::Camera c = obliqueCamera();
    glm::vec3 mid = c.eye + 0.2f * (c.target - c.eye);
    addObject(s, makeBox(mid - glm::vec3(0.5f), mid + glm::vec3(0.5f)), diffuseMaterial(0.5f));
    reference::ReferenceOptions o;
    o.width = o.height = 16;
    o.photonsPerLight = 200'000;
    o.maxDepth = 0;
    o.threads = 2;
    o.mode = reference::ReferenceMode::AllLightPaths;
    o.visibilityTest = true;
    auto hidden = reference::renderCausticsReference(s, c, o);
    ASSERT_TRUE(hidden.ok());
    o.visibilityTest = false;
    auto seenThrough = reference::renderCausticsReference(s, c, o);
    ASSERT_TRUE(seenThrough.ok());
    // With the test, only the box's own top face (facing the light) can be seen; the floor cannot.
    EXPECT_LT(hidden->photonsSplatted * 4, seenThrough->photonsSplatted);
}

TEST(ReferenceTracer, IsDeterministicForFixedSeedAndThreadCount) {
    scene::Scene s = litPlane();
    addObject(s, makeBox({-0.5f, 0.5f, -0.5f}, {0.5f, 0.6f, 0.5f}), glassMaterial(1.5f));
    reference::ReferenceOptions o;
    o.width = o.height = 24;
    o.photonsPerLight = 50'000;
    o.threads = 2;
    auto a = reference::renderCausticsReference(s, obliqueCamera(), o);
    auto b = reference::renderCausticsReference(s, obliqueCamera(), o);
    o.seed = 1;
    auto c = reference::renderCausticsReference(s, obliqueCamera(), o);
    ASSERT_TRUE(a.ok() && b.ok() && c.ok());
    EXPECT_GT(a->photonsSplatted, 0u);
    EXPECT_EQ(a->pixels, b->pixels);
    EXPECT_NE(a->pixels, c->pixels);
}

TEST(ReferenceTracer, RejectsMeshWithMaterialOutOfRange) {
    scene::Scene s = litPlane();
    s.meshes[0].material = 7;
    reference::ReferenceOptions o;
    auto image = reference::renderCausticsReference(s, obliqueCamera(), o);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.message().find("material"), std::string::npos);
}
