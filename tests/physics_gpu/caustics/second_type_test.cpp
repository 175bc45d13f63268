// Second-type caustics (paper 3.3) on the GPU against estimates that share no formula with the gather:
// the CPU second-type reference (a floor photon histogram read along camera paths through the ball),
// the slab transmittance of a glass plate, and a thin wall that no gather disk may reach across.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_harness.h"
#include "caustics/reference/second_type_reference.h"
#include "gpu_test.h"
#include "image_analysis.h"
#include "second_type_scenes.h"

namespace caustics::test {
namespace {

class SecondType : public GpuTest {};

CausticsSettings secondTypeSettings(uint32_t map, float rays) {
    CausticsSettings s;
    s.mapResolution = map;
    s.raysPerTexel = rays;
    s.filter = false;
    s.maxSpecularDepth = 8;
    s.russianRoulette = false;
    s.maxStoredHits = 1u << 20;   // 80 MB of CausticHit: under lavapipe's 128 MB storage-buffer range
    return s;
}

// Mean of the images of `frames` independent GPU frames (seeds 1..frames); the run of the last one
// is returned with the means in firstType / secondType.
Result<CausticRun> averagedRun(rhi::IDevice& device, const scene::Scene& scene, const scene::Camera& cam, uint32_t size,
                               CausticsSettings s, uint32_t frames) {
    CausticRun mean;
    for (uint32_t k = 0; k < frames; ++k) {
        s.seed = 1 + k;
        CAUSTICS_TRY(CausticRun run, runCaustics(device, scene, cam, size, size, s));
        if (k == 0) {
            mean = run;
            mean.firstType.assign(run.firstType.size(), glm::vec3(0.0f));
            mean.secondType.assign(run.secondType.size(), glm::vec3(0.0f));
        }
        for (size_t i = 0; i < run.firstType.size(); ++i) {
            mean.firstType[i] += run.firstType[i] / float(frames);
            mean.secondType[i] += run.secondType[i] / float(frames);
        }
        mean.stats = run.stats;
        mean.spheres = run.spheres;
    }
    return mean;
}

float centreDistance(uint32_t x, uint32_t y, uint32_t size) {
    return std::hypot(float(x) + 0.5f - 0.5f * size, float(y) + 0.5f - 0.5f * size);
}

// Largest 3x3 box mean of luminance among pixels closer than `radius` to the image centre.
float peak3x3(const std::vector<glm::vec3>& img, uint32_t size, float radius) {
    float best = 0.0f;
    for (uint32_t y = 1; y + 1 < size; ++y)
        for (uint32_t x = 1; x + 1 < size; ++x) {
            if (centreDistance(x, y, size) >= radius) continue;
            float sum = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) sum += luminance(img[size_t(y + dy) * size + x + dx]);
            best = std::max(best, sum / 9.0f);
        }
    return best;
}

// Sum of luminance over pixels closer than `radius` to the image centre.
double energy(const std::vector<glm::vec3>& img, uint32_t size, float radius) {
    double sum = 0.0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
            if (centreDistance(x, y, size) < radius) sum += luminance(img[size_t(y) * size + x]);
    return sum;
}

// Mean luminance in 1-pixel-wide rings around the image centre.
std::vector<double> radialProfile(const std::vector<glm::vec3>& img, uint32_t size) {
    std::vector<double> sum(size / 2, 0.0), count(size / 2, 0.0);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            float r = std::hypot(float(x) + 0.5f - 0.5f * size, float(y) + 0.5f - 0.5f * size);
            if (size_t(r) < sum.size()) {
                sum[size_t(r)] += luminance(img[size_t(y) * size + x]);
                count[size_t(r)] += 1.0;
            }
        }
    for (size_t i = 0; i < sum.size(); ++i) sum[i] /= std::max(count[i], 1.0);
    return sum;
}

// The ball's caustic seen from above through the ball (issue 10's "second type" view): a central spike
// on a plateau and a bright fold ring near the ball's rim. The CPU estimate traces 64 jittered camera
// paths per pixel through the ball and reads a 512^2-bin photon histogram of the floor (4 M photons,
// 2.3 mm bins against a 4.6 mm pixel footprint at the centre); the GPU image is the mean of 4 frames
// at the default radius (one footprint width). Bounds: 3x3 peak and energy within 10 % (the task's).
// Measured 2026-11-30 (docs/physics.md): peak 0.985, energy 0.996; with 2 footprint widths peak 0.70
// (the disk blurs the spike), energy 0.989; with the old unfolded radius peak 0.194, energy 1.004.
TEST_F(SecondType, GlassBallSeenFromAboveMatchesTheCpuHistogramEstimate) {
    constexpr uint32_t kSize = 128;
    scene::Scene scene = ballFromAboveScene();
    scene::Camera cam = ballFromAboveCamera();
    auto gpu = averagedRun(*device, scene, cam, kSize, secondTypeSettings(256, 4.0f), 4);
    ASSERT_TRUE(gpu) << gpu.message();

    reference::SecondTypeReferenceOptions o;
    o.width = o.height = kSize;
    o.samplesPerPixel = 64;
    o.maxDepth = 8;
    o.receiverHalfSize = 0.6f;
    o.histogramResolution = 512;
    o.photonsPerLight = 4'000'000;
    auto cpu = reference::renderSecondTypeReference(scene, cam, o);
    ASSERT_TRUE(cpu) << cpu.message();
    ASSERT_GT(cpu.value().pathsOnReceiver, 10000u);

    const std::vector<glm::vec3>& g = gpu.value().secondType;
    const std::vector<glm::vec3>& c = cpu.value().image.pixels;
    // Compared inside 0.6 of the ball's image radius: the caustic (spike, plateau, fold ring) lies
    // there, and the ball's rim, where grazing refraction squeezes whole regions into a pixel, stays out.
    const float ballImageRadius =
        std::tan(std::asin(0.4f / (cam.eye.y - 0.55f))) / std::tan(0.5f * cam.verticalFovRadians) * 0.5f * float(kSize);
    const float region = 0.6f * ballImageRadius;
    float peakRatio = peak3x3(g, kSize, region) / peak3x3(c, kSize, region);
    double energyRatio = energy(g, kSize, region) / energy(c, kSize, region);
    std::printf("[ measured ] ball from above: GPU/CPU 3x3 peak %.4f, energy %.4f (within %.1f px), gather hits %u\n", peakRatio,
                energyRatio, region, gpu.value().stats[kStatGatherHits]);
    EXPECT_NEAR(peakRatio, 1.0, 0.10);
    EXPECT_NEAR(energyRatio, 1.0, 0.10);

    // The fold ring: the CPU profile's brightest ring outside the central spike; the GPU profile must
    // have a local maximum within 2 px of it (higher than 4 px inwards and outwards).
    std::vector<double> pg = radialProfile(g, kSize), pc = radialProfile(c, kSize);
    size_t fold = 6;
    for (size_t r = 6; r + 6 < pc.size(); ++r)
        if (pc[r] > pc[fold]) fold = r;
    std::printf("[ measured ] fold ring radius (CPU) %zu px\n", fold);
    bool found = false;
    for (size_t r = fold - 2; r <= fold + 2; ++r) found = found || (pg[r] > pg[r - 4] && pg[r] > pg[r + 4]);
    EXPECT_TRUE(found) << "no GPU fold ring near radius " << fold << " px";
}

// The ball's caustic seen through a 1 cm glass plate that fills the view, against the same caustic
// seen directly (first type, no plate): a camera path through a slab carries the slab transmittance
// (1 - R) / (1 + R) with R = ((n-1)/(n+1))^2 (Born & Wolf 1.6; 0.9231 at n = 1.5, near-normal view),
// and a plate of IOR 1.0 changes nothing. Compared over the pixels that see the floor directly in the
// run without the plate. Bounds: 2 % and 1 % (the task's). Measured 2026-11-30 (6 frames each, map
// 256^2 x 8 rays): 0.9260 against 0.9231 and 1.0010 against 1.
void expectPlateFactor(rhi::IDevice& device, float ior, double expected, double tolerance) {
    constexpr uint32_t kSize = 96;
    scene::Camera cam = sideCausticCamera();
    scene::Scene direct = sideCausticScene();
    scene::Scene plated = sideCausticScene();
    addPlateInFrontOfCamera(plated, cam, ior);
    CausticsSettings s = secondTypeSettings(256, 8.0f);
    auto a = averagedRun(device, direct, cam, kSize, s, 6);
    ASSERT_TRUE(a) << a.message();
    auto b = averagedRun(device, plated, cam, kSize, s, 6);
    ASSERT_TRUE(b) << b.message();
    double seenDirectly = 0.0, seenThroughPlate = 0.0;
    uint32_t pixels = 0;
    for (size_t i = 0; i < size_t(kSize) * kSize; ++i) {
        if (a.value().objectId[i] != 1u) continue;  // the floor, seen directly without the plate
        seenDirectly += luminance(a.value().firstType[i]);
        seenThroughPlate += luminance(b.value().secondType[i]);
        ++pixels;
    }
    ASSERT_GT(seenDirectly, 0.0);
    double ratio = seenThroughPlate / seenDirectly;
    std::printf("[ measured ] plate IOR %.2f: through plate / direct %.4f (expected %.4f) over %u pixels\n", ior, ratio, expected, pixels);
    EXPECT_NEAR(ratio, expected, tolerance * expected);
}

TEST_F(SecondType, GlassPlateScalesTheCausticByTheSlabTransmittance) {
    const double r = std::pow(0.5 / 2.5, 2.0);
    expectPlateFactor(*device, 1.5f, (1.0 - r) / (1.0 + r), 0.02);
}

TEST_F(SecondType, IndexMatchedPlateLeavesTheCausticUnchanged) {
    expectPlateFactor(*device, 1.0f, 1.0, 0.01);
}

// Caustic photons land only on the wall's +x side; the floor on the -x side, seen (like the +x side)
// through a glass plate, must gather nothing. The radius scale 4 makes the disks (~3 cm) wider than the
// 2 cm wall, so only the wall probes keep the disks at the wall's foot on their own side. Measured
// 2026-11-30: far side exactly 0 over 209 pixels (disks there up to 4.5 cm), lit foot 48 over 209.
TEST_F(SecondType, NoCausticLeaksThroughAThinWall) {
    constexpr uint32_t kSize = 96;
    scene::Scene scene = thinWallScene();
    scene::Camera cam = thinWallCamera();
    addPlateInFrontOfCamera(scene, cam, 1.5f);
    CausticsSettings s = secondTypeSettings(256, 4.0f);
    s.sphereRadiusScale = 4.0f;
    auto run = runCaustics(*device, scene, cam, kSize, kSize, s);
    ASSERT_TRUE(run) << run.message();
    const CausticRun& r = run.value();
    double lit = 0.0, shadowSide = 0.0;
    uint32_t litPixels = 0, shadowPixels = 0;
    float largest = 0.0f;
    for (const CausticSphere& sp : r.spheres) {
        if (sp.radius <= 0.0f || sp.objectId != 1u || std::abs(sp.centre.z) > 0.4f) continue;
        float lum = luminance(r.secondType[sp.pixel]);
        if (sp.centre.x > 0.01f && sp.centre.x < 0.06f) { lit += lum; ++litPixels; }
        if (sp.centre.x < -0.01f && sp.centre.x > -0.06f) {
            shadowSide += lum;
            ++shadowPixels;
            largest = std::max(largest, sp.radius);
        }
    }
    std::printf("[ measured ] thin wall: lit foot %.4g over %u px, far side %.4g over %u px (largest disk on the far side %.4f m)\n", lit,
                litPixels, shadowSide, shadowPixels, largest);
    ASSERT_GT(litPixels, 50u);
    ASSERT_GT(shadowPixels, 50u);
    EXPECT_GT(lit, 0.0);
    EXPECT_EQ(shadowSide, 0.0);
}

}  // namespace
}  // namespace caustics::test
