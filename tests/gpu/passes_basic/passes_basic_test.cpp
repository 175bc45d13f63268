// G-buffer and direct lighting of a tiny scene, checked against CPU expectations (lavapipe, validation
// on: any validation warning or error fails the test through GpuTest).
//
// Scene: a white-ish Lambertian floor (y = 0, 4 x 4 m, albedo 0.5, KHR_materials_specular 0 so the
// BRDF is exactly albedo / pi), a box (0.5 m cube on the floor centred at x = -1) and one point light
// of 10 cd at (1, 2, 0). Camera 5 m above the origin looking straight down, 60 degree field of view.
#include <gtest/gtest.h>

#include <cmath>

#include "common/camera.h"
#include "gpu_test.h"
#include "module_harness.h"
#include "caustics/scene/mesh_builder.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr float kAlbedo = 0.5f;
constexpr float kIntensity = 10.0f;   // candela
const glm::vec3 kLight{1.0f, 2.0f, 0.0f};
const glm::vec3 kBoxCentre{-1.0f, 0.25f, 0.0f};

scene::Scene makeTinyScene() {
    scene::Scene s;
    s.name = "passes_basic tiny scene";
    scene::Material floor;
    floor.baseColor = glm::vec3(kAlbedo);
    floor.specular = 0.0f;
    floor.roughness = 1.0f;
    scene::Material box = floor;
    box.baseColor = glm::vec3(0.8f, 0.2f, 0.2f);
    s.materials = {floor, box};
    scene::Mesh plane = scene::makePlane(2.0f, 2.0f);
    plane.material = 0;
    scene::Mesh cube = scene::makeBox(glm::vec3(0.25f));
    cube.material = 1;
    s.meshes = {plane, cube};
    s.instances.push_back({0, glm::mat4(1.0f), 1});
    glm::mat4 t(1.0f);
    t[3] = glm::vec4(kBoxCentre, 1.0f);
    s.instances.push_back({1, t, 2});
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = kLight;
    light.intensity = kIntensity;
    s.lights = {light};
    return s;
}

scene::Camera topCamera() {
    scene::Camera c;
    c.eye = {0.0f, 5.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 0.0f, -1.0f};
    c.verticalFovRadians = glm::radians(60.0f);
    return c;
}

shader::PinholeCamera pinhole(const scene::Camera& c) {
    return shader::makePinholeCamera(c.eye, c.target, c.up, c.verticalFovRadians, float(kSize), float(kSize));
}

// The pixel whose centre sees world point p.
glm::uvec2 pixelOf(const scene::Camera& c, glm::vec3 p) {
    shader::CameraProjection proj = shader::projectToCamera(pinhole(c), p);
    return glm::uvec2(glm::floor(proj.pixel));
}

// Where the ray through the centre of pixel (x, y) meets the floor y = 0.
glm::vec3 floorPointOfPixel(const scene::Camera& c, glm::uvec2 pixel) {
    glm::vec3 d = shader::cameraRayDirection(pinhole(c), glm::vec2(pixel) + 0.5f);
    return c.eye + d * (-c.eye.y / d.y);
}

class PassesBasic : public GpuTest {
protected:
    RenderedFrame render(CausticsAov aov) {
        CausticsSettings settings;
        settings.causticsEnabled = false;   // these tests are about the G-buffer and direct light only
        settings.aov = aov;
        auto frame = renderFrame(device, makeTinyScene(), settings, topCamera(), kSize, kSize);
        EXPECT_TRUE(frame.ok()) << (frame.ok() ? "" : frame.message());
        return frame.ok() ? std::move(frame).value() : RenderedFrame{};
    }
    static size_t at(glm::uvec2 p) { return size_t(p.y) * kSize + p.x; }
};

TEST_F(PassesBasic, GBufferObjectIdsAreInstanceIndexPlusOneAndZeroOnBackground) {
    RenderedFrame f = render(CausticsAov::Direct);
    ASSERT_EQ(f.objectId.size(), size_t(kSize) * kSize);
    scene::Camera cam = topCamera();
    EXPECT_EQ(f.objectId[at(pixelOf(cam, {1.0f, 0.0f, 1.0f}))], 1u);                // floor
    EXPECT_EQ(f.objectId[at(pixelOf(cam, {kBoxCentre.x, 0.5f, kBoxCentre.z}))], 2u); // box top
    EXPECT_EQ(f.objectId[at({0, 0})], 0u);   // corner: the view is 5.8 m wide, the floor 4 m
}

TEST_F(PassesBasic, GBufferLinearDepthIsDistanceAlongTheCameraAxis) {
    RenderedFrame f = render(CausticsAov::Direct);
    ASSERT_EQ(f.linearDepth.size(), size_t(kSize) * kSize);
    scene::Camera cam = topCamera();
    // The camera looks straight down: linear depth = 5 on the floor, 4.5 on the box top, whatever the
    // pixel. Tolerance 1e-4 m: float interpolation of a few-metre value.
    EXPECT_NEAR(f.linearDepth[at(pixelOf(cam, {1.0f, 0.0f, 1.0f}))], 5.0f, 1e-4f);
    EXPECT_NEAR(f.linearDepth[at(pixelOf(cam, {0.5f, 0.0f, -1.5f}))], 5.0f, 1e-4f);
    EXPECT_NEAR(f.linearDepth[at(pixelOf(cam, {kBoxCentre.x, 0.5f, kBoxCentre.z}))], 4.5f, 1e-4f);
    EXPECT_EQ(f.linearDepth[at({0, 0})], 0.0f);
}

TEST_F(PassesBasic, GBufferNormalFacesTheViewer) {
    RenderedFrame f = render(CausticsAov::Direct);
    ASSERT_EQ(f.normalRoughness.size(), size_t(kSize) * kSize * 4);
    size_t i = at(pixelOf(topCamera(), {1.0f, 0.0f, 1.0f}));
    // Half-float storage: 1e-3.
    EXPECT_NEAR(f.normalRoughness[4 * i + 1], 1.0f, 1e-3f);
    EXPECT_NEAR(f.normalRoughness[4 * i + 3], 1.0f, 1e-3f);   // roughness
}

TEST_F(PassesBasic, LambertianFloorUnderPointLightMatchesAnalyticRadiance) {
    RenderedFrame f = render(CausticsAov::Direct);
    ASSERT_EQ(f.hdr.size(), size_t(kSize) * kSize * 4);
    scene::Camera cam = topCamera();
    for (glm::vec3 target : {glm::vec3(1.0f, 0, 0.5f), glm::vec3(0.3f, 0, -1.2f), glm::vec3(1.5f, 0, 1.5f),
                             glm::vec3(-0.2f, 0, 0.9f)}) {
        glm::uvec2 p = pixelOf(cam, target);
        glm::vec3 x = floorPointOfPixel(cam, p);
        glm::vec3 toLight = kLight - x;
        float d2 = glm::dot(toLight, toLight);
        float cosTheta = toLight.y / std::sqrt(d2);
        // L = E * albedo / pi with E = I cos(theta) / d^2 (KHR_lights_punctual: candela -> lux).
        float expected = kIntensity * cosTheta / d2 * kAlbedo / 3.14159265f;
        // 1 %: the direct image is RGBA16F (relative step 2^-11) and the shading point is rebuilt from
        // linear depth in float; nothing else differs from the formula.
        EXPECT_NEAR(f.hdr[4 * at(p) + 0], expected, 0.01f * expected) << "pixel " << p.x << "," << p.y;
        EXPECT_NEAR(f.hdr[4 * at(p) + 2], expected, 0.01f * expected) << "pixel " << p.x << "," << p.y;
    }
}

TEST_F(PassesBasic, FloorBehindTheBoxIsInShadow) {
    RenderedFrame f = render(CausticsAov::Direct);
    ASSERT_EQ(f.hdr.size(), size_t(kSize) * kSize * 4);
    scene::Camera cam = topCamera();
    // The segment from (-1.6, 0, 0) to the light passes through the box (it is at y = 0.27 < 0.5 where
    // it crosses the box's face x = -1.25): exactly zero, there is no ambient term.
    glm::uvec2 shadowed = pixelOf(cam, {-1.6f, 0.0f, 0.0f});
    EXPECT_EQ(f.hdr[4 * at(shadowed)], 0.0f);
    // The same distance on the lit side is clearly bright.
    glm::uvec2 lit = pixelOf(cam, {-1.6f, 0.0f, 1.2f});
    EXPECT_GT(f.hdr[4 * at(lit)], 0.05f);
}

TEST_F(PassesBasic, ModuleRefusesAbsurdSettingsNamingTheField) {
    auto scene = makeTinyScene();
    auto gpu = scene::GpuScene::create(*device, scene);
    ASSERT_TRUE(gpu.ok()) << gpu.message();
    CausticsSettings bad;
    bad.maxSpecularDepth = 1000;
    auto module = CausticsModule::create(device, scene, *gpu, bad);
    ASSERT_FALSE(module.ok());
    EXPECT_NE(module.message().find("maxSpecularDepth"), std::string::npos) << module.message();
}

TEST_F(PassesBasic, SceneWithoutInstancesIsRefusedNamingTheScene) {
    scene::Scene scene = makeTinyScene();
    scene.name = "empty level";
    scene.instances.clear();
    auto gpu = scene::GpuScene::create(*device, scene);
    if (!gpu.ok()) {   // refusing at upload is as good, if the message says why
        EXPECT_NE(gpu.message().find("instance"), std::string::npos) << gpu.message();
        return;
    }
    auto module = CausticsModule::create(device, scene, *gpu);
    ASSERT_FALSE(module.ok());
    EXPECT_NE(module.message().find("'empty level' has no mesh instances"), std::string::npos) << module.message();
}

TEST_F(PassesBasic, SceneWithoutLightsRendersBlackDirectLight) {
    scene::Scene s = makeTinyScene();
    s.lights.clear();
    CausticsSettings settings;
    settings.aov = CausticsAov::Direct;
    auto f = renderFrame(device, s, settings, topCamera(), kSize, kSize);
    ASSERT_TRUE(f.ok()) << f.message();
    float maxValue = 0.0f;
    for (size_t i = 0; i < f->hdr.size(); i += 4) maxValue = std::max(maxValue, f->hdr[i]);
    EXPECT_EQ(maxValue, 0.0f);
}

}  // namespace
}  // namespace caustics::test
