// The host camera contract (passes/include/caustics/camera_view.h): projections with jitter, reversed
// Z and an infinite far plane are read back exactly, and their pixel mapping is the shaders' pinhole
// model shifted by the jitter (shaders/common/camera.h, cameraProject).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "caustics/camera_constants.h"
#include "caustics/camera_view.h"
#include "common/camera.h"

namespace caustics {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

scene::Camera testCamera() {
    scene::Camera c;
    c.eye = {1.0f, 2.0f, 3.0f};
    c.target = {0.2f, 0.1f, -0.5f};
    c.verticalFovRadians = 0.9f;
    c.nearPlane = 0.1f;
    c.farPlane = 40.0f;
    return c;
}

struct Variant {
    bool reversedZ, infiniteFar;
};

class ProjectionVariants : public ::testing::TestWithParam<Variant> {};

TEST_P(ProjectionVariants, AnalysisReadsBackFovAspectPlanesJitterAndDepthDirection) {
    const Variant v = GetParam();
    ProjectionOptions o;
    o.reversedZ = v.reversedZ;
    o.infiniteFar = v.infiniteFar;
    o.jitterPixels = {0.3f, -0.45f};
    const scene::Camera cam = testCamera();
    const CameraView view = cameraViewMatrices(cam, kWidth, kHeight, o);
    auto info = analyzeProjection(view.proj, kWidth, kHeight);
    ASSERT_TRUE(info) << info.message();
    // float32 round trips of the matrix entries: relative 1e-5.
    EXPECT_NEAR(info->tanHalfFovY, std::tan(0.5f * cam.verticalFovRadians), 1e-5f);
    EXPECT_NEAR(info->aspect, float(kWidth) / float(kHeight), 1e-5f);
    EXPECT_NEAR(info->nearPlane, cam.nearPlane, 1e-5f * cam.nearPlane);
    if (v.infiniteFar) EXPECT_TRUE(std::isinf(info->farPlane));
    else EXPECT_NEAR(info->farPlane, cam.farPlane, 1e-3f * cam.farPlane);
    EXPECT_EQ(info->reversedZ, v.reversedZ);
    EXPECT_NEAR(info->jitterPixels.x, 0.3f, 1e-5f);
    EXPECT_NEAR(info->jitterPixels.y, -0.45f, 1e-5f);
}

// Depth at the near plane is 0 (standard) or 1 (reversed) and moves towards the other end with distance.
TEST_P(ProjectionVariants, DepthIsZeroOrOneAtTheNearPlaneAndMonotonic) {
    const Variant v = GetParam();
    ProjectionOptions o;
    o.reversedZ = v.reversedZ;
    o.infiniteFar = v.infiniteFar;
    const CameraView view = cameraViewMatrices(testCamera(), kWidth, kHeight, o);
    auto depthAt = [&](float d) {
        glm::vec4 c = view.proj * glm::vec4(0.0f, 0.0f, -d, 1.0f);
        return c.z / c.w;
    };
    EXPECT_NEAR(depthAt(0.1f), v.reversedZ ? 1.0f : 0.0f, 1e-5f);
    if (v.reversedZ) EXPECT_LT(depthAt(5.0f), depthAt(1.0f));
    else EXPECT_GT(depthAt(5.0f), depthAt(1.0f));
}

INSTANTIATE_TEST_SUITE_P(Conventions, ProjectionVariants,
                         ::testing::Values(Variant{false, false}, Variant{false, true}, Variant{true, false},
                                           Variant{true, true}));

// The shaders project with the pinhole model plus the jitter (cameraProject); the rasterizer uses the
// matrix. Both must put a world point at the same pixel, or the first-type splat would test the wrong
// G-buffer pixel. Bound: 1e-3 pixels (float32 rounding over a 160-pixel image).
TEST(CameraConstants, PinholeProjectionPlusJitterEqualsTheMatrixProjection) {
    ProjectionOptions o;
    o.reversedZ = true;
    o.infiniteFar = true;
    o.jitterPixels = {0.37f, -0.21f};
    const CameraView view = cameraViewMatrices(testCamera(), kWidth, kHeight, o);
    auto c = makeCameraConstants(view.view, view.proj, kWidth, kHeight, 0);
    ASSERT_TRUE(c) << c.message();
    shader::PinholeCamera pin;
    pin.eye = glm::vec3(c->eye);
    pin.right = glm::vec3(c->right);
    pin.up = glm::vec3(c->up);
    pin.forward = glm::vec3(c->forward);
    pin.tanHalfFovY = c->forward.w;
    pin.aspect = c->right.w;
    pin.width = float(kWidth);
    pin.height = float(kHeight);
    for (glm::vec3 x : {glm::vec3(0.2f, 0.1f, -0.5f), glm::vec3(0.9f, 0.4f, 0.0f), glm::vec3(-0.3f, 0.5f, -1.2f)}) {
        glm::vec4 clip = c->viewProj * glm::vec4(x, 1.0f);
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        glm::vec2 fromMatrix = (ndc * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight);
        shader::CameraProjection p = shader::projectToCamera(pin, x);
        glm::vec2 fromPinhole = p.pixel + glm::vec2(c->eye.w, c->up.w);
        EXPECT_NEAR(fromMatrix.x, fromPinhole.x, 1e-3f);
        EXPECT_NEAR(fromMatrix.y, fromPinhole.y, 1e-3f);
    }
    EXPECT_EQ(c->frame.w, 1u) << "reversed Z is flagged for the G-buffer pass";
    EXPECT_EQ(c->clip.y, 0.0f) << "an infinite far plane is stored as 0";
}

TEST(CameraConstants, EyeAndAxesComeBackFromTheViewMatrix) {
    const scene::Camera cam = testCamera();
    const CameraView view = cameraViewMatrices(cam, kWidth, kHeight);
    auto c = makeCameraConstants(view.view, view.proj, kWidth, kHeight, 7);
    ASSERT_TRUE(c) << c.message();
    const glm::vec3 forward = glm::normalize(cam.target - cam.eye);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(c->eye[i], cam.eye[i], 1e-5f);
        EXPECT_NEAR(c->forward[i], forward[i], 1e-5f);
    }
    EXPECT_NEAR(glm::dot(glm::vec3(c->up), glm::vec3(0, 1, 0)), std::sqrt(1.0f - forward.y * forward.y), 1e-5f);
    EXPECT_EQ(c->frame.z, 7u);
}

TEST(CameraConstants, OrthographicProjectionIsRefusedNamingTheEntry) {
    glm::mat4 ortho(1.0f);
    ortho[1][1] = -1.0f;
    auto info = analyzeProjection(ortho, kWidth, kHeight);
    ASSERT_FALSE(info);
    EXPECT_NE(info.message().find("proj[3][3]"), std::string::npos) << info.message();
}

TEST(CameraConstants, ProjectionWithoutTheVulkanYFlipIsRefused) {
    CameraView view = cameraViewMatrices(testCamera(), kWidth, kHeight);
    view.proj[1][1] = -view.proj[1][1];
    auto info = analyzeProjection(view.proj, kWidth, kHeight);
    ASSERT_FALSE(info);
    EXPECT_NE(info.message().find("proj[1][1]"), std::string::npos) << info.message();
    EXPECT_NE(info.message().find("y down"), std::string::npos) << info.message();
}

TEST(CameraConstants, ScaledViewMatrixIsRefused) {
    CameraView view = cameraViewMatrices(testCamera(), kWidth, kHeight);
    view.view = glm::mat4(glm::mat3(2.0f)) * view.view;
    auto c = makeCameraConstants(view.view, view.proj, kWidth, kHeight, 0);
    ASSERT_FALSE(c);
    EXPECT_NE(c.message().find("not a rigid transform"), std::string::npos) << c.message();
}

TEST(CameraConstants, DegenerateEyeTargetCameraIsRefusedNamingTheField) {
    scene::Camera cam = testCamera();
    cam.target = cam.eye;
    auto c = makeCameraConstants(cam, kWidth, kHeight, 0);
    ASSERT_FALSE(c);
    EXPECT_NE(c.message().find("eye == target"), std::string::npos) << c.message();
}

}  // namespace
}  // namespace caustics

namespace caustics {
namespace {
// CameraView::jitterPixels given apart: jittering the unjittered projection is the jittered one of
// cameraViewMatrices, and jittering a view-projection shifts every projected point by the jitter.
TEST(HostJitterApart, JitteringTheUnjitteredProjectionGivesTheJitteredOne) {
    scene::Camera cam;
    cam.eye = {0.0f, 1.0f, 3.0f};
    cam.target = {0.0f, 0.5f, 0.0f};
    constexpr uint32_t w = 64, h = 48;
    const glm::vec2 jitter{0.3f, -0.45f};
    const CameraView plain = cameraViewMatrices(cam, w, h);
    const CameraView jittered = cameraViewMatrices(cam, w, h, {.jitterPixels = jitter});
    const glm::mat4 ours = jitterClipMatrix(plain.proj, jitter, w, h);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours[c][r], jittered.proj[c][r], 1e-6f) << c << "," << r;
    // A world point lands jitter pixels away in the jittered view-projection (x right, y down).
    const glm::vec4 p(0.2f, 0.7f, -0.4f, 1.0f);
    const glm::vec4 a = plain.proj * plain.view * p;
    const glm::vec4 b = jitterClipMatrix(plain.proj * plain.view, jitter, w, h) * p;
    EXPECT_NEAR((b.x / b.w - a.x / a.w) * 0.5f * w, jitter.x, 1e-4f);
    EXPECT_NEAR((b.y / b.w - a.y / a.w) * 0.5f * h, jitter.y, 1e-4f);
}
}  // namespace
}  // namespace caustics
