// Analytic optics checks of the first-type caustics (paper 3.2) on the GPU, and of the CPU reference
// on the same scenes: ball-lens focus, slab and thin-pane transmittance, the ring's nephroid cusp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "image_analysis.h"
#include "test_scenes.h"
#include "caustics/reference/reference_tracer.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 128;

CausticsSettings opticsSettings(uint32_t map, float rays) {
    CausticsSettings s;
    s.mapResolution = map;
    s.raysPerTexel = rays;
    s.filter = false;
    s.secondType = false;
    s.maxSpecularDepth = 8;
    s.russianRoulette = false;
    s.maxStoredHits = 1u << 18;
    return s;
}

class CausticOptics : public GpuTest {};

// Ball lens (Hecht, Optics, 5th ed., sec. 6.2 thick lenses): the paraxial focus of a sphere of index n
// and radius R lies f = nR / (2(n - 1)) from its centre. The plane is put through that point (sphere
// centre at height f) and the camera looks under the sphere at it; the brightest pixel must be the
// focus point's pixel within one pixel, in the GPU image and in the CPU reference image.
TEST_F(CausticOptics, GlassSphereFocusesAtTheParaxialFocus) {
    const float n = 1.5f, radius = 0.4f, f = n * radius / (2.0f * (n - 1.0f));
    scene::AnalyticSceneDesc d;
    d.radius = radius;
    d.ior = n;
    d.height = f;
    d.tessellation = 96;
    scene::Scene scene = scene::makeGlassSphereScene(d);
    scene::Camera cam;
    cam.eye = {0.0f, 0.12f, 1.2f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.verticalFovRadians = glm::radians(25.0f);
    auto run = runCaustics(*device, scene, cam, kSize, kSize, opticsSettings(128, 4.0f));
    ASSERT_TRUE(run) << run.message();
    auto proj = shader::projectToCamera(pinhole(cam, kSize, kSize), glm::vec3(0.0f));
    ASSERT_TRUE(proj.valid);
    auto all = [](uint32_t, uint32_t) { return true; };
    Peak gpu = brightest(run.value().firstType, kSize, kSize, all);
    ASSERT_GT(gpu.value, 0.0f);
    EXPECT_LE(std::abs(float(gpu.x) + 0.5f - proj.pixel.x), 1.0f);
    EXPECT_LE(std::abs(float(gpu.y) + 0.5f - proj.pixel.y), 1.0f);
    std::printf("[ measured ] GPU focal peak pixel (%d, %d), paraxial focus projects to (%.2f, %.2f)\n", gpu.x, gpu.y, proj.pixel.x, proj.pixel.y);

    reference::ReferenceOptions o;
    o.width = o.height = kSize;
    o.photonsPerLight = 128 * 128 * 4;
    o.maxDepth = 8;
    auto ref = reference::renderCausticsReference(scene, cam, o);
    ASSERT_TRUE(ref) << ref.message();
    Peak cpu = brightest(ref.value().pixels, kSize, kSize, all);
    EXPECT_LE(std::abs(float(cpu.x) + 0.5f - proj.pixel.x), 1.0f);
    EXPECT_LE(std::abs(float(cpu.y) + 0.5f - proj.pixel.y), 1.0f);
}

// Thin slab at normal incidence: each interface reflects R = ((n-1)/(n+1))^2; with all internal
// reflections the slab transmits T = (1 - R) / (1 + R) (Born & Wolf 1.6; 0.9231 for n = 1.5). The
// plane under the slab receives E = T E_light, i.e. radiance T E_light albedo / pi. 2 % tolerance
// (the task's bound; measured Monte Carlo noise of the mean is ~0.3 %).
TEST_F(CausticOptics, GlassSlabTransmitsTheFresnelFractionOfTheFlux) {
    scene::AnalyticSceneDesc d;
    d.height = 0.6f;
    d.thickness = 0.05f;
    scene::Scene scene = scene::makeGlassSlabScene(d);
    scene::Camera cam;
    cam.eye = {0.0f, 0.45f, 2.2f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.verticalFovRadians = glm::radians(40.0f);
    auto run = runCaustics(*device, scene, cam, kSize, kSize, opticsSettings(128, 1.0f));
    ASSERT_TRUE(run) << run.message();
    const float r = std::pow((d.ior - 1.0f) / (d.ior + 1.0f), 2.0f);
    const double expected = (1.0 - r) / (1.0 + r) * d.lightIlluminance * d.planeAlbedo / 3.14159265358979;
    auto pc = pinhole(cam, kSize, kSize);
    double sum = 0.0;
    uint32_t count = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            glm::vec3 p;
            // Well inside the slab's shadow (|x|, |z| < 0.7 of the 1 m half-size) and seen directly.
            if (!planePoint(pc, x, y, p) || std::abs(p.x) > 0.7f || std::abs(p.z) > 0.7f) continue;
            if (run.value().objectId[size_t(y) * kSize + x] == 0) continue;
            sum += run.value().firstType[size_t(y) * kSize + x].y;
            ++count;
        }
    ASSERT_GT(count, 500u);
    std::printf("[ measured ] slab transmission ratio GPU/Fresnel %.4f over %u pixels\n", sum / count / expected, count);
    EXPECT_NEAR(sum / count / expected, 1.0, 0.02) << "mean " << sum / count << " expected " << expected;
}

// Polished ring under light at 30 degrees elevation: the reflected rays' horizontal projections form
// a nephroid whose cusp lies R/2 from the centre towards the lit wall's far side (the paraxial focus
// of a concave mirror of radius R). The brightest pixel on the axis line must be within 2 pixel
// footprints of x = -R/2.
TEST_F(CausticOptics, MetalRingShowsTheNephroidCuspAtHalfTheRadius) {
    scene::Scene scene = scene::makeMetalRingScene();
    const float radius = 0.5f;
    scene::Camera cam;
    cam.eye = {0.0f, 2.5f, 0.001f};
    cam.target = {0.0f, 0.0f, 0.0f};
    cam.up = {0.0f, 0.0f, -1.0f};
    cam.verticalFovRadians = glm::radians(30.0f);
    auto run = runCaustics(*device, scene, cam, kSize, kSize, opticsSettings(128, 4.0f));
    ASSERT_TRUE(run) << run.message();
    auto pc = pinhole(cam, kSize, kSize);
    auto nearAxis = [&](uint32_t x, uint32_t y) {
        glm::vec3 p;
        return planePoint(pc, x, y, p) && std::abs(p.z) < 0.03f && p.x > -0.45f && p.x < 0.0f;
    };
    const float footprint = 2.0f * cam.eye.y * std::tan(0.5f * cam.verticalFovRadians) / float(kSize);
    for (int which = 0; which < 2; ++which) {
        std::vector<glm::vec3> img = run.value().firstType;
        if (which == 1) {
            reference::ReferenceOptions o;
            o.width = o.height = kSize;
            o.photonsPerLight = 128 * 128 * 4;
            auto ref = reference::renderCausticsReference(scene, cam, o);
            ASSERT_TRUE(ref) << ref.message();
            img = ref.value().pixels;
        }
        Peak p = brightest(img, kSize, kSize, nearAxis);
        ASSERT_GE(p.x, 0);
        glm::vec3 world;
        ASSERT_TRUE(planePoint(pc, uint32_t(p.x), uint32_t(p.y), world));
        std::printf("[ measured ] %s cusp at x = %.4f (analytic %.4f, footprint %.4f)\n", which ? "CPU" : "GPU", world.x, -0.5f * radius, footprint);
        EXPECT_NEAR(world.x, -0.5f * radius, 2.0f * footprint) << (which ? "CPU reference" : "GPU");
    }
}

// Thin-walled glass (docs/physics.md "Thin-walled glass"): a pane without KHR_materials_volume is two
// faces with their inner reflections summed, so the floor behind it receives E cos(theta) T',
// T' = mean over s, p of (1 - r) / (1 + r), the closed form the independent reference reproduces
// (IndependentReference.ThinPaneTransmitsOneMinusROverOnePlusRPerPolarisation).
class CausticThinPane : public GpuTest {};

constexpr float kPaneHeight = 0.3f, kAlbedo = 0.8f;
constexpr uint32_t kFloorId = 1;   // the G-buffer's object id: instance index + 1

double paneTransmittance(double theta, double ior) {
    double ci = std::cos(theta), st = std::sin(theta) / ior, ct = std::sqrt(1.0 - st * st);
    double as = (ci - ior * ct) / (ci + ior * ct), ap = (ior * ci - ct) / (ior * ci + ct);
    double rs = as * as, rp = ap * ap;
    return 0.5 * ((1.0 - rs) / (1.0 + rs) + (1.0 - rp) / (1.0 + rp));
}

// A 1 x 1 m thin-walled pane (thickness 0) 0.3 m over a Lambertian floor, 1 lux at theta from the
// vertical in the x-y plane.
scene::Scene paneScene(float ior, float theta) {
    scene::Scene s;
    physics::addObject(s, physics::makeQuadY(0.0f, -4.0f, 4.0f, -4.0f, 4.0f), physics::diffuseMaterial(kAlbedo));
    scene::Material glass = physics::glassMaterial(ior);
    glass.thickness = 0.0f;   // thin-walled
    glass.doubleSided = true;
    physics::addObject(s, physics::makeQuadY(kPaneHeight, -0.5f, 0.5f, -0.5f, 0.5f), glass);
    s.lights.push_back(physics::directionalLight({std::sin(theta), -std::cos(theta), 0.0f}, 1.0f));
    return s;
}

// The camera sits under the pane and looks at the floor in its shadow (shifted 0.3 tan(theta) by the
// unbent light); the first type's mean over floor pixels well inside the shadow (0.35 m of its centre)
// over rho E cos(theta) / pi is T'. Seed-to-seed noise of one frame's ratio, measured over seeds 1-8
// (CAUSTICS_PANE_FRAMES=8 prints each): 0.9989 +- 0.0022 at 0 degrees, 1.0004 +- 0.0042 at 60. The
// test averages 2 frames at 0 degrees and 4 at 60 (sd of the mean 0.0016 and 0.0022); bound 1 %, 6 and 4.6 of
// those sd. At 60 degrees the unpolarised shortcut (1 - R)/(1 + R) would read 0.986 and one face's 1 - R
// 1.074; at 0 degrees one face would read 1.040.
TEST_F(CausticThinPane, FloorBehindThePaneReceivesTheTwoFaceTransmittance) {
    const char* framesEnv = std::getenv("CAUSTICS_PANE_FRAMES");
    const float ior = 1.5f;
    for (float deg : {0.0f, 60.0f}) {
        const float theta = glm::radians(deg), shift = kPaneHeight * std::tan(theta);
        const uint32_t frames = framesEnv ? uint32_t(std::atoi(framesEnv)) : (deg < 30.0f ? 2u : 4u);
        scene::Scene scene = paneScene(ior, theta);
        scene::Camera cam;
        cam.eye = {shift, 0.2f, 0.55f};
        cam.target = {shift, 0.0f, 0.0f};
        cam.verticalFovRadians = glm::radians(50.0f);
        const double expected = paneTransmittance(theta, ior) * std::cos(theta) * kAlbedo / 3.14159265358979;
        auto pc = pinhole(cam, kSize, kSize);
        double meanRatio = 0.0;
        for (uint32_t frame = 0; frame < frames; ++frame) {
            CausticsSettings settings = opticsSettings(256, 4.0f);
            settings.seed = 1 + frame;
            auto run = runCaustics(*device, scene, cam, kSize, kSize, settings);
            ASSERT_TRUE(run) << run.message();
            double sum = 0.0;
            uint32_t count = 0;
            for (uint32_t y = 0; y < kSize; ++y)
                for (uint32_t x = 0; x < kSize; ++x) {
                    glm::vec3 p;
                    if (!planePoint(pc, x, y, p) || std::abs(p.x - shift) > 0.35f || std::abs(p.z) > 0.35f) continue;
                    if (run.value().objectId[size_t(y) * kSize + x] != kFloorId) continue;
                    sum += run.value().firstType[size_t(y) * kSize + x].y;
                    ++count;
                }
            ASSERT_GT(count, 1000u);
            double ratio = sum / count / expected;
            meanRatio += ratio / frames;
            std::printf("[ measured ] thin pane at %2.0f deg, seed %u: GPU / (rho E cos T' / pi) = %.4f over %u pixels (T' %.5f)\n",
                        deg, settings.seed, ratio, count, paneTransmittance(theta, ior));
        }
        std::printf("[ measured ] thin pane at %2.0f deg: mean of %u frames %.4f\n", deg, frames, meanRatio);
        EXPECT_NEAR(meanRatio, 1.0, 0.01) << "theta " << deg;
    }
}

}  // namespace
}  // namespace caustics::test
