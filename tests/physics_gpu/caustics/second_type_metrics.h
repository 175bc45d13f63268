#pragma once
// Shared by the second-type physics tests (second_type_test.cpp, second_type_ring_test.cpp): their
// settings, the mean of several GPU frames, and the image measures compared with the CPU estimate.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "caustic_harness.h"
#include "caustics/reference/second_type_reference.h"
#include "image_analysis.h"

namespace caustics::test {

// CAUSTICS_SECOND_TYPE_SEED=N shifts every seed of these tests by N (GPU frames N+1.., the CPU estimate N):
// how the seed-to-seed noise quoted at each bound was measured (docs/physics.md). Unset: N = 0.
inline uint32_t seedOffset() {
    const char* text = std::getenv("CAUSTICS_SECOND_TYPE_SEED");
    return text ? uint32_t(std::strtoul(text, nullptr, 10)) : 0u;
}

// The CPU second-type estimate as the tests run it: 64 jittered camera paths per pixel, 8 specular events,
// a 512^2-bin histogram of 4 M photons over the floor square of half-size `halfSize` around `centre`.
inline Result<reference::SecondTypeReference> cpuSecondTypeEstimate(const scene::Scene& scene, const scene::Camera& cam,
                                                                    uint32_t size, glm::vec2 centre, float halfSize) {
    reference::SecondTypeReferenceOptions o;
    o.width = o.height = size;
    o.samplesPerPixel = 64;
    o.maxDepth = 8;
    o.receiverCentre = centre;
    o.receiverHalfSize = halfSize;
    o.histogramResolution = 512;
    o.photonsPerLight = 4'000'000;
    o.seed = seedOffset();
    return reference::renderSecondTypeReference(scene, cam, o);
}

inline CausticsSettings secondTypeSettings(uint32_t map, float rays) {
    CausticsSettings s;
    s.mapResolution = map;
    s.raysPerTexel = rays;
    s.filter = false;
    s.maxSpecularDepth = 8;
    s.russianRoulette = false;
    s.maxStoredHits = 1u << 20;   // 64 MB of CausticHit: under lavapipe's 128 MB storage-buffer range
    return s;
}

// Mean of the images of `frames` independent GPU frames (seeds seedOffset() + 1, + 2, ...); the run of the last one
// is returned with the means in firstType / secondType.
inline Result<CausticRun> averagedRun(rhi::IDevice& device, const scene::Scene& scene, const scene::Camera& cam, uint32_t size,
                               CausticsSettings s, uint32_t frames) {
    CausticRun mean;
    for (uint32_t k = 0; k < frames; ++k) {
        s.seed = seedOffset() + 1 + k;
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

inline float centreDistance(uint32_t x, uint32_t y, uint32_t size) {
    return std::hypot(float(x) + 0.5f - 0.5f * size, float(y) + 0.5f - 0.5f * size);
}

// Largest 3x3 box mean of luminance among pixels closer than `radius` to the image centre.
inline float peak3x3(const std::vector<glm::vec3>& img, uint32_t size, float radius) {
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
inline double energy(const std::vector<glm::vec3>& img, uint32_t size, float radius) {
    double sum = 0.0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
            if (centreDistance(x, y, size) < radius) sum += luminance(img[size_t(y) * size + x]);
    return sum;
}

// Mean luminance in 1-pixel-wide rings around the image centre.
inline std::vector<double> radialProfile(const std::vector<glm::vec3>& img, uint32_t size) {
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

}  // namespace caustics::test
