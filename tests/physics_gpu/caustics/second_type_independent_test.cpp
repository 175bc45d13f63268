// Second-type caustics (paper 3.3) against the independent reference (tests/reference/second_type):
// exact solids, its own Fresnel, refraction and Beer-Lambert, a floor photon histogram read along camera
// paths (docs/physics.md, "Independent second-type reference"). Issue 18's scenes: a glass ball from
// above and obliquely, a glass plate, a water glass, a metal ring seen through a pane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "independent_cases.h"
#include "independent_metrics.h"
#include "second_type_estimate.h"
#include "second_type_metrics.h"

namespace caustics::test {
namespace {

class SecondTypeIndependent : public GpuTest {};

// Measurement knobs (unset: the tests' values): CAUSTICS_INDEPENDENT_SIZE (px), _FRAMES, _MAP (GPU map
// resolution), _RAYS (per texel), _RADIUS_PERCENT (sphereRadiusScale x 100), _MPHOTONS (reference photons, millions), _BINS,
// _RINGS, _PATHS (per pixel), _WHOLE_IMAGE, _DUMP (independent_metrics.h); CAUSTICS_SECOND_TYPE_SEED.
uint32_t envOr(const char* name, uint32_t fallback) {
    const char* text = std::getenv(name);
    return text ? uint32_t(std::strtoul(text, nullptr, 10)) : fallback;
}

struct Comparison {
    double peakRatio = 0.0, energyRatio = 0.0, peakShift = 0.0;
};

// The independent reference image of case c at size x size (the knobs above; seed seedOffset()).
std::vector<double> referenceLuminance(const IndependentCase& c, uint32_t size, double* floorFlux = nullptr,
                                       uint64_t* pathsOnFloor = nullptr) {
    ref::EstimateOptions o;
    o.width = o.height = size;
    o.photons = uint64_t(envOr("CAUSTICS_INDEPENDENT_MPHOTONS", 8)) * 1'000'000ull;
    o.histogramResolution = envOr("CAUSTICS_INDEPENDENT_BINS", 1024);
    o.pathsPerPixel = envOr("CAUSTICS_INDEPENDENT_PATHS", 64);
    o.receiverCentreX = c.receiverX;
    o.receiverCentreZ = c.receiverZ;
    o.receiverHalfSize = c.receiverHalfSize;
    o.radialHistogram = c.axial;
    if (c.axial) o.histogramResolution = envOr("CAUSTICS_INDEPENDENT_RINGS", 16000);
    o.seed = seedOffset();
    ref::FloorHistogram floor = ref::traceFloorPhotons(c.reference, o);
    ref::SecondTypeImage refImage = ref::renderSecondType(c.reference, c.pinhole(), floor, o);
    if (floorFlux) *floorFlux = floor.totalFlux().y;
    if (pathsOnFloor) *pathsOnFloor = refImage.pathsOnFloor;
    return luminances(refImage.radiance);
}

// Peak, energy and peak position of the GPU image g against the reference r (luminance, size x size) in
// case c's region; `what` names the run in the printed line.
Comparison compareImages(IndependentCase c, std::vector<double> g, std::vector<double> r, uint32_t size, const std::string& what) {
    Comparison out;
    // CAUSTICS_INDEPENDENT_WHOLE_IMAGE=1 compares every pixel (how the divergence on coinciding folds was shown).
    if (std::getenv("CAUSTICS_INDEPENDENT_WHOLE_IMAGE")) c.regionFraction = 0.0;
    if (c.regionFraction > 0.0)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                if (std::hypot(x + 0.5 - 0.5 * size, y + 0.5 - 0.5 * size) >= c.regionFraction * 0.5 * size)
                    g[size_t(y) * size + x] = r[size_t(y) * size + x] = 0.0;
    PeakAt pg = peak3x3At(g, size), pr = peak3x3At(r, size);
    out.peakRatio = pg.value / pr.value;
    out.energyRatio = total(g) / total(r);
    // The peak's position: the centroid of the brightest feature, in the same window (4 px around the
    // reference's brightest 3x3 box) of both images.
    // The window is re-centred on the reference's centroid twice (a mean shift), so that a one-pixel hop of
    // the reference's argmax between seeds does not move it.
    double cx = pr.x, cy = pr.y, gx, gy, rx, ry;
    for (int k = 0; k < 2; ++k) featureCentroid(r, size, cx, cy, 4.0, cx, cy);
    featureCentroid(g, size, cx, cy, 4.0, gx, gy);
    featureCentroid(r, size, cx, cy, 4.0, rx, ry);
    out.peakShift = std::hypot(gx - rx, gy - ry);
    std::printf("[ measured ] %s (%u px, %s): GPU/reference 3x3 peak %.4f, energy %.4f, peak at (%.2f, %.2f) vs "
                "(%.2f, %.2f): %.2f px\n",
                c.name.c_str(), size, what.c_str(), out.peakRatio, out.energyRatio, gx, gy, rx, ry, out.peakShift);
    dumpLuminance(c.name + " gpu " + what, g, size);
    dumpLuminance(c.name + " reference", r, size);
    return out;
}

// The converged second type: the mean of `frames` unfiltered frames of 4 rays per texel.
Comparison compare(rhi::IDevice& device, IndependentCase c, uint32_t size, uint32_t frames) {
    CausticsSettings s = secondTypeSettings(envOr("CAUSTICS_INDEPENDENT_MAP", 256), float(envOr("CAUSTICS_INDEPENDENT_RAYS", 4)));
    s.sphereRadiusScale = float(envOr("CAUSTICS_INDEPENDENT_RADIUS_PERCENT", uint32_t(100.0f * CausticsSettings{}.sphereRadiusScale))) / 100.0f;
    auto gpu = averagedRun(device, c.module, c.camera, size, s, frames);
    EXPECT_TRUE(gpu) << gpu.message();
    if (!gpu) return {};
    double flux = 0.0;
    uint64_t paths = 0;
    std::vector<double> r = referenceLuminance(c, size, &flux, &paths);
    std::printf("[ measured ] %s: reference floor flux %.4g lm, %llu paths on the floor\n", c.name.c_str(), flux,
                (unsigned long long)paths);
    return compareImages(c, luminances(gpu.value().secondType), r, size, std::to_string(frames) + " frames averaged");
}

// What a host sees after `frames` frames of a still camera with the filter on, at the sample's defaults
// (512^2 maps, 1 ray per texel): the caustic radiance of the last frame in the pixels that see the glass (a
// first-type photon reaches none of them), second type filtered apart on its own guides or with the camera
// G-buffer; r: the reference (referenceLuminance).
Comparison compareFiltered(rhi::IDevice& device, const IndependentCase& c, const std::vector<double>& r, uint32_t size,
                           uint32_t frames, bool apart) {
    CausticsSettings s = secondTypeSettings(512, 1.0f);
    s.filter = true;
    s.filterSecondTypeApart = apart;
    s.seed = seedOffset() + 1;
    auto gpu = runCaustics(device, c.module, c.camera, size, size, s, frames);
    EXPECT_TRUE(gpu) << gpu.message();
    if (!gpu) return {};
    // Pixels that see the floor directly hold its first-type caustic (the reference has none there): left
    // out. The floor is the receiver the second type's guides name most often.
    const CausticRun& run = gpu.value();
    std::map<uint32_t, size_t> receivers;
    for (uint32_t id : run.guideObjectId)
        if (id != 0u) ++receivers[id];
    uint32_t floorId = 0;
    for (const auto& [id, n] : receivers)
        if (floorId == 0u || n > receivers[floorId]) floorId = id;
    std::vector<double> g = luminances(run.radiance), masked = r;
    for (size_t i = 0; i < g.size(); ++i)
        if (run.objectId[i] == floorId) g[i] = masked[i] = 0.0;
    return compareImages(c, g, masked, size,
                         std::to_string(frames) + " frames filtered" + (apart ? " apart" : " with the camera G-buffer"));
}

// Bounds: the (energy within 5 %, 3x3 peak within 15 %, peak position within 0.5 px) unless said
// otherwise. Measured over the seed offsets 0..3 (CAUSTICS_SECOND_TYPE_SEED, 2026-12-03, with the lobe
// split and the 0.75-footprint gather disk; docs/physics.md "Independent second-type reference"), mean +-
// standard deviation; each comment says how many standard deviations the bound lies from the mean.

// Peak 1.048 +- 0.012 (8.5 sd), energy 0.999 +- 0.001 (36 sd), shift 0.05 +- 0.01 px (45 sd).
TEST_F(SecondTypeIndependent, BallFromAboveMatches) {
    Comparison m = compare(*device, ballFromAbove(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
    EXPECT_NEAR(m.peakRatio, 1.0, 0.15);
    EXPECT_LT(m.peakShift, 0.5);
}

// The first guess at its set-up, where the folds coincide: energy only, inside 0.625 of the half
// image (where the reference moves by 0.2 % from 2,000 to 16,000 rings): 1.017 +- 0.006 (6 sd). The
// peak (at the axis, where both axial caustic lines cross the floor) diverges with the kernel: 0.93-0.99
// over the seeds, not asserted.
TEST_F(SecondTypeIndependent, BallFromAboveWithCoincidingFoldsMatchesInEnergyAwayFromThem) {
    Comparison m = compare(*device, ballFromAboveClose(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
}

// Peak 0.988 +- 0.007 (19 sd), energy 1.002 +- 0.002 (22 sd), shift 0.05 +- 0.02 px (21 sd).
TEST_F(SecondTypeIndependent, BallObliqueMatches) {
    Comparison m = compare(*device, ballOblique(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
    EXPECT_NEAR(m.peakRatio, 1.0, 0.15);
    EXPECT_LT(m.peakShift, 0.5);
}

// Peak 1.017 +- 0.018 (7.4 sd), energy 1.002 +- 0.001 (48 sd), shift 0.01 +- 0.01 px (50 sd).
TEST_F(SecondTypeIndependent, PlateMatches) {
    Comparison m = compare(*device, plate(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
    EXPECT_NEAR(m.peakRatio, 1.0, 0.15);
    EXPECT_LT(m.peakShift, 0.5);
}

// Peak 0.953 +- 0.005 (20 sd; 0.896 +- 0.021 with one lobe picked per event and a one-footprint disk,
// which blurred the bright arcs to 0.84 once the lobe split took the noise away), energy 0.999 +- 0.008
// (6 sd), shift 0.18 +- 0.06 px (5 sd).
TEST_F(SecondTypeIndependent, WaterGlassMatches) {
    Comparison m = compare(*device, waterGlass(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
    EXPECT_NEAR(m.peakRatio, 1.0, 0.15);
    EXPECT_LT(m.peakShift, 0.5);
}

// Peak 0.974 +- 0.011 (11 sd), energy 1.000 +- 0.004 (13 sd), shift 0.27 +- 0.13 px (largest 0.39; the
// issue's 0.5 px lies 1.8 sd above the mean). With one lobe picked per event and a one-footprint disk the
// cusp's centre lay 0.77 +- 0.55 px off and the bound was 2 px.
TEST_F(SecondTypeIndependent, RingThroughPaneMatches) {
    Comparison m = compare(*device, ringThroughPane(), envOr("CAUSTICS_INDEPENDENT_SIZE", 96), envOr("CAUSTICS_INDEPENDENT_FRAMES", 4));
    EXPECT_NEAR(m.energyRatio, 1.0, 0.05);
    EXPECT_NEAR(m.peakRatio, 1.0, 0.15);
    EXPECT_LT(m.peakShift, 0.5);
}

// `image` (size x size) through the a-trous passes' first kernel, 1/16 (1 4 6 4 1) in x then y, edges
// clamped: what one step of the spatial filter costs an image that holds no noise at all.
std::vector<double> b3Blurred(const std::vector<double>& image, uint32_t size) {
    const double taps[5] = {1.0 / 16, 4.0 / 16, 6.0 / 16, 4.0 / 16, 1.0 / 16};
    auto pass = [&](const std::vector<double>& in, bool alongX) {
        std::vector<double> out(in.size(), 0.0);
        const int n = int(size);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                for (int k = -2; k <= 2; ++k) {
                    const int sx = alongX ? std::clamp(x + k, 0, n - 1) : x, sy = alongX ? y : std::clamp(y + k, 0, n - 1);
                    out[size_t(y) * size + size_t(x)] += taps[k + 2] * in[size_t(sy) * size + size_t(sx)];
                }
        return out;
    };
    return pass(pass(image, true), false);
}

// One frame without holes (issue 18): at 1 ray per texel (map 512^2, the sample's default) with the filter on,
// no pixel where the reference exceeds 10 % of its peak is zero, and the filtered single frame is closer to
// the reference (relative L1 over those pixels) than the mean of 4 unfiltered frames.
// maxL1Ratio: the filtered frame's L1 over that of the 4 unfiltered frames must stay below it (1: the issue's
// criterion); maxL1: the filtered frame's own relative L1 must stay below it; minPixels: caustic pixels expected.
void expectOneFilteredFrameWithoutHoles(rhi::IDevice& device, const IndependentCase& c, uint32_t kSize, double maxL1Ratio,
                                        double maxL1, uint32_t minPixels) {
    CausticsSettings s = secondTypeSettings(512, 1.0f);
    s.filter = true;
    s.filterSecondTypeApart = true;
    // Filter knobs for measuring (docs/physics.md "One frame"); the tests run the defaults.
    s.atrousIterations = envOr("CAUSTICS_INDEPENDENT_ATROUS_ITERATIONS", s.atrousIterations);
    s.filterLuminanceSigma = float(envOr("CAUSTICS_INDEPENDENT_SIGMA_PERCENT", uint32_t(100.0f * s.filterLuminanceSigma))) / 100.0f;
    s.seed = seedOffset() + 1;
    auto filtered = runCaustics(device, c.module, c.camera, kSize, kSize, s);
    ASSERT_TRUE(filtered) << filtered.message();
    s.filter = false;
    auto unfiltered = averagedRun(device, c.module, c.camera, kSize, s, 4);
    ASSERT_TRUE(unfiltered) << unfiltered.message();

    ref::EstimateOptions o;
    o.width = o.height = kSize;
    o.photons = 8'000'000;
    o.histogramResolution = c.axial ? 16000 : 1024;
    o.radialHistogram = c.axial;
    o.receiverCentreX = c.receiverX;
    o.receiverCentreZ = c.receiverZ;
    o.receiverHalfSize = c.receiverHalfSize;
    o.seed = seedOffset();
    ref::SecondTypeImage refImage = ref::renderSecondType(c.reference, c.pinhole(), ref::traceFloorPhotons(c.reference, o), o);

    // What the one frame's error is made of (docs/physics.md "One frame"): one unfiltered frame, one frame
    // of four times the photons, and the reference itself through one a-trous kernel without edge stopping.
    auto single = averagedRun(device, c.module, c.camera, kSize, s, 1);
    ASSERT_TRUE(single) << single.message();
    CausticsSettings morePhotons = s;
    morePhotons.raysPerTexel = 4.0f;
    auto singleMorePhotons = averagedRun(device, c.module, c.camera, kSize, morePhotons, 1);
    ASSERT_TRUE(singleMorePhotons) << singleMorePhotons.message();

    std::vector<double> r = luminances(refImage.radiance), f = luminances(filtered.value().radiance),
                        u = luminances(unfiltered.value().secondType), u1 = luminances(single.value().secondType),
                        u1x4 = luminances(singleMorePhotons.value().secondType), rBlurred = b3Blurred(r, kSize);
    const double peak = *std::max_element(r.begin(), r.end());
    uint32_t inside = 0, holes = 0;
    double l1Filtered = 0.0, l1Unfiltered = 0.0, l1Single = 0.0, l1SingleX4 = 0.0, l1Blurred = 0.0, sum = 0.0;
    for (size_t i = 0; i < r.size(); ++i) {
        if (r[i] <= 0.1 * peak) continue;
        ++inside;
        if (f[i] <= 0.0) ++holes;
        l1Filtered += std::abs(f[i] - r[i]);
        l1Unfiltered += std::abs(u[i] - r[i]);
        l1Single += std::abs(u1[i] - r[i]);
        l1SingleX4 += std::abs(u1x4[i] - r[i]);
        l1Blurred += std::abs(rBlurred[i] - r[i]);
        sum += r[i];
    }
    std::printf("[ measured ] %s, one frame, 1 ray per texel: %u of %u caustic pixels zero after the filter; relative L1 filtered "
                "(1 frame) %.4f, unfiltered (4 frames) %.4f\n", c.name.c_str(), holes, inside, l1Filtered / sum, l1Unfiltered / sum);
    std::printf("[ measured ] %s, relative L1 of one unfiltered frame %.4f, of one with 4 rays per texel %.4f; the reference "
                "through one B3 kernel (no edge stopping) %.4f\n", c.name.c_str(), l1Single / sum, l1SingleX4 / sum, l1Blurred / sum);
    dumpLuminance(c.name + " one frame filtered", f, kSize);
    dumpLuminance(c.name + " four frames unfiltered", u, kSize);
    dumpLuminance(c.name + " one frame reference", r, kSize);
    ASSERT_GT(inside, minPixels);
    EXPECT_EQ(holes, 0u);
    EXPECT_LT(l1Filtered, maxL1Ratio * l1Unfiltered);
    EXPECT_LT(l1Filtered / sum, maxL1);
}

// The water glass's one-frame image size: 96 px in CI; CAUSTICS_INDEPENDENT_ONE_FRAME_SIZE=256 measures it at
// the size (docs/physics.md "Folds of the camera path").
uint32_t oneFrameSize() { return envOr("CAUSTICS_INDEPENDENT_ONE_FRAME_SIZE", 96); }

// The ball from above, second type filtered on its own guides (docs/caustics.md "Second-type guides"),
// offsets 0..3 (2026-12-03, lobe split, 0.75-footprint disk): 0 zero pixels of ~2,345 each time; L1 filtered
// 0.0454 / 0.0491 / 0.0467 / 0.0498 against 0.0565 / 0.0563 / 0.0573 / 0.0561 for 4 unfiltered frames (ratio
// 0.845 +- 0.042: the bound 1 lies 3.7 sd away; the filtered L1 0.048 +- 0.002, bound 0.060, 5.8 sd). With one
// lobe picked per event: 0.0742-0.0809 against 0.1261-0.1279 (ratio 0.614 +- 0.019).
TEST_F(SecondTypeIndependent, FilteredSingleFrameHasNoHolesAndBeatsFourUnfilteredFrames) {
    expectOneFilteredFrameWithoutHoles(*device, ballFromAbove(), 96, 1.0, 0.060, 1000);
}

// The water glass, offsets 0..3 (2026-12-03, lobe split, 0.75-footprint disk, fold floor 1/4 of the
// footprint's length, docs/physics.md "Folds of the camera path"): no zero pixel among 590-658; the filtered
// frame's L1 is 0.2132 / 0.2306 / 0.2037 / 0.2042 (0.213 +- 0.013; 0.234 +- 0.021 without the fold floor),
// against 0.1553 / 0.1600 / 0.1509 / 0.1449 (0.153 +- 0.006; was 0.172) for the 4 unfiltered frames: ratio
// 1.39 +- 0.04, the 1 is NOT met: the frame's noise is the camera path's sampling, not the
// photons' (4x the photons: 0.2155 -> 0.2060), and the arcs are so narrow that the noise-free reference
// through one a-trous kernel is already 0.1965 from itself (docs/physics.md "One frame"). Bounds: the filtered L1 0.30 (6.9 sd over
// the mean, under the best frame before the lobe split) and the ratio 1.65 (6.5 sd), which guard the filter
// on this case.
TEST_F(SecondTypeIndependent, FilteredSingleFrameOfTheWaterGlassHasNoHoles) {
    expectOneFilteredFrameWithoutHoles(*device, waterGlass(), oneFrameSize(), 1.65, 0.30, 500);
}

// Issue 18's table, row "filter on, 8 frames": a still camera, 8 frames through the filter at the sample's
// defaults (map 512^2 x 1 ray), the second type filtered with the camera G-buffer (the default) and apart
// on its own guides. Energy within the 5 % in every case; the 3x3 peak of 8 filtered frames is
// still noisy (the brightest box of a noisy image lies above its mean) and, through the water glass, the
// filter lowers the bright arcs a little more than the gather disk does (docs/physics.md "Eight filtered
// frames"), so the peak and position bounds are derived from the seeds, stated per test.
void expectEightFilteredFramesMatch(rhi::IDevice& device, const IndependentCase& c, double peakLow, double peakHigh,
                                    double shiftBound) {
    const std::vector<double> r = referenceLuminance(c, 96);
    for (bool apart : {false, true}) {
        Comparison m = compareFiltered(device, c, r, 96, 8, apart);
        const char* how = apart ? "apart" : "with the camera G-buffer";
        EXPECT_NEAR(m.energyRatio, 1.0, 0.05) << how;
        EXPECT_GT(m.peakRatio, peakLow) << how;
        EXPECT_LT(m.peakRatio, peakHigh) << how;
        EXPECT_LT(m.peakShift, shiftBound) << how;
    }
}

// Offsets 0..3, G-buffer / apart (2026-12-03, lobe split, 0.75-footprint disk): peak 1.063 +- 0.030 / 1.081 +-
// 0.025 (bound 1.20: 4.8 sd over the apart mean), energy 1.000 +- 0.001 both (40 sd), shift 0.05 +- 0.02 / 0.07
// +- 0.01 px (the 0.5 px: 20 sd). With one lobe picked per event: peak 1.091 +- 0.039 / 1.118 +- 0.055.
TEST_F(SecondTypeIndependent, BallFromAboveFilteredEightFramesMatches) {
    expectEightFilteredFramesMatch(*device, ballFromAbove(), 0.85, 1.20, 0.5);
}

// Peak 0.938 +- 0.015 / 0.914 +- 0.019 (2026-12-03, lobe split, 0.75-footprint disk, fold floor; 0.937 /
// 0.920 before the floor; the 15 %: 3.4 sd under the apart mean; with one lobe picked per event and
// a one-footprint disk 0.820 / 0.808, not met), energy 0.998 +- 0.002 both (25 sd), shift 0.26 +- 0.14 /
// 0.18 +- 0.12 px (largest 0.43; the 0.5 px: 1.7 sd over the G-buffer mean, 2.7 over the apart one).
TEST_F(SecondTypeIndependent, WaterGlassFilteredEightFramesMatches) {
    expectEightFilteredFramesMatch(*device, waterGlass(), 0.85, 1.15, 0.5);
}

// Peak 0.992 +- 0.050 / 0.989 +- 0.052 (2026-12-03, lobe split, 0.75-footprint disk; the 15 %: 2.8 sd),
// energy 1.006 +- 0.003 (13 sd), shift 0.35 +- 0.16 / 0.28 +- 0.23 px (largest 0.56: bound 1 px, 3.1 sd over
// the apart mean).
TEST_F(SecondTypeIndependent, RingThroughPaneFilteredEightFramesMatches) {
    expectEightFilteredFramesMatch(*device, ringThroughPane(), 0.85, 1.15, 1.0);
}

}  // namespace
}  // namespace caustics::test
