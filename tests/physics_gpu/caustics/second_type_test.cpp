// Second-type caustics (paper 3.3) on the GPU against estimates that share no formula with the gather:
// the CPU second-type reference (a floor photon histogram read along camera paths through the ball),
// the slab transmittance of a glass plate, and a thin wall that no gather disk may reach across.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "caustic_harness.h"
#include "caustics/reference/second_type_reference.h"
#include "gpu_test.h"
#include "image_analysis.h"
#include "second_type_metrics.h"
#include "second_type_scenes.h"

namespace caustics::test {
namespace {

class SecondType : public GpuTest {};

// The ball's caustic seen from above through the ball (issue 10's "second type" view): a central spike
// on a plateau and a bright fold ring near the ball's rim. The CPU estimate traces 64 jittered camera
// paths per pixel through the ball and reads a 512^2-bin photon histogram of the floor (4 M photons,
// 2.3 mm bins against a 4.6 mm pixel footprint at the centre); the GPU image is the mean of 4 frames
// at the default radius (one footprint width). Bounds: 3x3 peak and energy within 10 % (the task's).
// Measured 2026-11-30 (docs/physics.md): peak 0.985, energy 0.996; with 2 footprint widths peak 0.70
// (the disk blurs the spike), energy 0.989; with the old unfolded radius peak 0.194, energy 1.004.
// Seed-to-seed (CAUSTICS_SECOND_TYPE_SEED offsets 0..7, 2026-12-01): peak 1.045 +- 0.038 (0.985-1.092),
// energy 1.030 +- 0.023 (0.996-1.053); the test's own seeds (offset 0) give the lowest of both. The 10 %
// bounds are the and kept; they are only 1.4 (peak) and 3.1 (energy) standard deviations above
// the mean: another seed set could fail the peak (offset 6 reached 1.092). Which side (GPU gather or CPU
// histogram) carries the spread is not measured yet.
TEST_F(SecondType, GlassBallSeenFromAboveMatchesTheCpuHistogramEstimate) {
    constexpr uint32_t kSize = 128;
    scene::Scene scene = ballFromAboveScene();
    scene::Camera cam = ballFromAboveCamera();
    auto gpu = averagedRun(*device, scene, cam, kSize, secondTypeSettings(256, 4.0f), 4);
    ASSERT_TRUE(gpu) << gpu.message();

    auto cpu = cpuSecondTypeEstimate(scene, cam, kSize, glm::vec2(0.0f), 0.6f);
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

    // With the filter on (4 frames of a still camera, as the ring test): the filter keeps the energy of
    // the unfiltered estimate (issue 10's filter bound, 3 %) and the spike (3x3 peak within 20 % of the CPU
    // estimate, the filter test's bound).
    // Measured (lavapipe, 2026-12-01, the test seeds): peak 0.963, energy 1.004 (unfiltered 0.985 / 0.996).
    CausticsSettings filtering = secondTypeSettings(256, 4.0f);
    filtering.filter = true;
    filtering.seed = seedOffset() + 1;
    const std::vector<scene::Camera> still(4, cam);
    auto filtered = runCaustics(*device, scene, still, kSize, kSize, filtering);
    ASSERT_TRUE(filtered) << filtered.message();
    const std::vector<glm::vec3>& fr = filtered.value().radiance;
    const float filteredPeak = peak3x3(fr, kSize, region) / peak3x3(c, kSize, region);
    const double filteredEnergy = energy(fr, kSize, region) / energy(c, kSize, region);
    std::printf("[ measured ] ball from above, filtered (4 frames): GPU/CPU 3x3 peak %.4f, energy %.4f\n",
                filteredPeak, filteredEnergy);
    EXPECT_NEAR(filteredPeak, 1.0, 0.20);
    EXPECT_NEAR(filteredEnergy / energyRatio, 1.0, 0.03);

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

// The floor (object 1) as the second type shows it through the plate of `plated` over the first type
// seen directly in `direct` (no plate), summed over the pixels that see the floor in `direct`, the
// means of `frames` frames each; 0 (and a test failure) when a run fails or the floor got no light.
double throughPlateOverDirect(rhi::IDevice& device, const scene::Scene& direct, const scene::Scene& plated,
                              const scene::Camera& cam, uint32_t size, const CausticsSettings& s, uint32_t frames,
                              uint32_t& pixels) {
    auto a = averagedRun(device, direct, cam, size, s, frames);
    auto b = averagedRun(device, plated, cam, size, s, frames);
    EXPECT_TRUE(a && b) << (a ? b.message() : a.message());
    if (!a || !b) return 0.0;
    double seenDirectly = 0.0, seenThroughPlate = 0.0;
    pixels = 0;
    for (size_t i = 0; i < size_t(size) * size; ++i) {
        if (a.value().objectId[i] != 1u) continue;  // the floor, seen directly without the plate
        seenDirectly += luminance(a.value().firstType[i]);
        seenThroughPlate += luminance(b.value().secondType[i]);
        ++pixels;
    }
    EXPECT_GT(seenDirectly, 0.0);
    return seenDirectly > 0.0 ? seenThroughPlate / seenDirectly : 0.0;
}

// The ball's caustic seen through a 1 cm glass plate that fills the view, against the same caustic
// seen directly (first type, no plate): a camera path through a slab carries the slab transmittance
// (1 - R) / (1 + R) with R = ((n-1)/(n+1))^2 (Born & Wolf 1.6; 0.9231 at n = 1.5, near-normal view),
// and a plate of IOR 1.0 changes nothing. Compared over the pixels that see the floor directly in the
// run without the plate. Bounds: 2 % and 1 % (the task's). Measured 2026-11-30 (6 frames each, map
// 256^2 x 8 rays): 0.9260 against 0.9231 and 1.0010 against 1. Seed-to-seed (offsets 0..7, 2026-12-01):
// 0.9235 +- 0.0013 (ratio to the expected 1.0004 +- 0.0014) and 1.0009 +- 0.0002: the 2 % and 1 % bounds
// are 14 and 45 standard deviations from the mean, so they test the physics, not the sampling.
void expectPlateFactor(rhi::IDevice& device, float ior, double expected, double tolerance, float thickness = 0.01f,
                       uint32_t frames = 6) {
    constexpr uint32_t kSize = 96;
    scene::Camera cam = sideCausticCamera();
    scene::Scene direct = sideCausticScene();
    scene::Scene plated = sideCausticScene();
    addPlateInFrontOfCamera(plated, cam, ior, thickness);
    uint32_t pixels = 0;
    const double ratio = throughPlateOverDirect(device, direct, plated, cam, kSize, secondTypeSettings(256, 8.0f), frames, pixels);
    std::printf("[ measured ] plate IOR %.2f, %.0f mm (0: thin-walled): through plate / direct %.4f (expected %.4f) over %u pixels\n",
                ior, 1000.0f * thickness, ratio, expected, pixels);
    EXPECT_NEAR(ratio, expected, tolerance * expected);
}

TEST_F(SecondType, GlassPlateScalesTheCausticByTheSlabTransmittance) {
    const double r = std::pow(0.5 / 2.5, 2.0);
    expectPlateFactor(*device, 1.5f, (1.0 - r) / (1.0 + r), 0.02);
}

TEST_F(SecondType, IndexMatchedPlateLeavesTheCausticUnchanged) {
    expectPlateFactor(*device, 1.0f, 1.0, 0.01);
}

// The same view through a thin-walled pane (one quad, thickness 0: docs/physics.md "Thin-walled glass"):
// the backward path meets one surface, which must pass the two faces' (1 - R)/(1 + R), not one face's
// 1 - R (0.96, 4 % more). 2 frames instead of 6. Seed-to-seed (CAUSTICS_SECOND_TYPE_SEED offsets 0..7,
// 2026-12-02): 0.9220 +- 0.0037, ratio to the expected 0.9989 +- 0.0040 (0.9917-1.0042); bound 2 %, as the
// plate's: 5 standard deviations, and one face's 1 - R would read 4 % high, 10 of them.
TEST_F(SecondType, ThinWalledPaneScalesTheCausticByTheTwoFaceTransmittance) {
    const double r = std::pow(0.5 / 2.5, 2.0);
    expectPlateFactor(*device, 1.5f, (1.0 - r) / (1.0 + r), 0.02, 0.0f, 2);
}

// A floor of "specular" optics (smooth, partly transmissive or metallic > 0.5) keeps a diffuse base:
// glTF's dielectric base layer, which photons pick with its chance c = (1 - metallic)(1 - F)(1 - t) and
// leave their flux on, so the first type seen directly shows rho E_base / pi. Through an index-matched
// plate a camera path reaches that base after two events and must show the same radiance: its own
// chance of picking the base is not a second factor c (docs/physics.md "A diffuse base behind glass").
// The floor is 1.2 m square: it is a caster in the caustic maps too (a specular instance), and a small
// one leaves the ball most of their photons. Measured (lavapipe, CAUSTICS_SECOND_TYPE_SEED offsets 0..3,
// 2026-12-03): transmission 0.5 split 0.9926 +- 0.0028, one lobe per event (8 frames) 1.0057 +- 0.0031,
// metallic 0.6 split 0.9893 +- 0.0021; with the same photons the two lobe modes differ by +0.5 +- 1.3 %
// over offsets 0..7 (the sampled mode's lobe noise). Before the camera path's 1 / chance weight: 0.446,
// 0.461 and 0.372 (the chance (1 - metallic)(1 - F)(1 - t) counted twice). Bound 5 %: over 10 sd of the
// split runs, 4 of the sampled mode's per-offset spread, and 10 times nearer than the error it catches.
void expectDiffuseBaseUnchangedByIndexMatchedPlate(rhi::IDevice& device, float transmission, float metallic, bool splitLobes,
                                                    uint32_t frames) {
    constexpr uint32_t kSize = 96;
    scene::Camera cam = sideCausticCamera();
    scene::Scene direct = sideCausticScene(1.2f);
    scene::Material& floor = direct.materials[0];
    floor.roughness = 0.0f;
    floor.transmission = transmission;
    floor.metallic = metallic;
    floor.ior = 1.5f;
    floor.thickness = 0.0f;   // transmissive: a thin-walled pane (one quad)
    ASSERT_TRUE(floor.isSpecular());
    scene::Scene plated = direct;
    addPlateInFrontOfCamera(plated, cam, 1.0f);
    CausticsSettings s = secondTypeSettings(256, 8.0f);
    s.secondTypeSplitLobes = splitLobes;
    uint32_t pixels = 0;
    const double ratio = throughPlateOverDirect(device, direct, plated, cam, kSize, s, frames, pixels);
    std::printf("[ measured ] floor transmission %.2f metallic %.2f, lobes %s: through an index-matched plate / direct %.4f over %u pixels\n",
                transmission, metallic, splitLobes ? "split" : "sampled", ratio, pixels);
    EXPECT_NEAR(ratio, 1.0, 0.05);
}

TEST_F(SecondType, PartlyTransmissiveFloorSeenThroughAnIndexMatchedPlateKeepsItsDiffuseBase) {
    expectDiffuseBaseUnchangedByIndexMatchedPlate(*device, 0.5f, 0.0f, true, 6);
}

TEST_F(SecondType, PartlyTransmissiveFloorKeepsItsDiffuseBaseWithOneLobePerEvent) {
    expectDiffuseBaseUnchangedByIndexMatchedPlate(*device, 0.5f, 0.0f, false, 8);
}

TEST_F(SecondType, PartlyMetallicFloorSeenThroughAnIndexMatchedPlateKeepsItsDiffuseBase) {
    expectDiffuseBaseUnchangedByIndexMatchedPlate(*device, 0.0f, 0.6f, true, 6);
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
