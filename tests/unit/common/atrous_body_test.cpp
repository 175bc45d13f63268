// The caustic filter's a-trous body (passes/caustic_filter/shaders/atrous.h) compiled as C++: the
// lattice mapping that lets one pass per iteration keep its apron at 4 points at every step, and the
// spreading weight (docs/caustics.md "Filter", "Cost").
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

#include "caustic_filter/shaders/atrous.h"

namespace caustics::shader {
namespace {

// What the groups of one step-s iteration filter (atrousThread's choice of lattices, on the CPU): every
// listed tile runs its own lattice; the block's first listed tile also runs the lattices whose
// designated tile is not listed. Returns how often each pixel was filtered.
std::map<std::pair<int, int>, int> filteredPixels(const std::vector<std::vector<bool>>& listed, int s, int width,
                                                 int height) {
    const int tilesY = int(listed.size()), tilesX = int(listed[0].size());
    auto isListed = [&](int2 t) { return t.x >= 0 && t.y >= 0 && t.x < tilesX && t.y < tilesY && listed[t.y][t.x]; };
    std::map<std::pair<int, int>, int> count;
    auto run = [&](int2 origin) {
        for (int j = 0; j < kFilterTileSize; ++j)
            for (int i = 0; i < kFilterTileSize; ++i) {
                const int2 p = atrousLatticePixel(origin, int2(i, j), s);
                if (p.x < width && p.y < height && isListed(p / kFilterTileSize)) ++count[{p.x, p.y}];
            }
    };
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            const int2 tile(tx, ty);
            if (!isListed(tile)) continue;
            const int2 block = atrousBlock(tile, s), own = atrousOwnLattice(tile, s);
            run(atrousLatticeOrigin(block, own, s));
            int first = -1;
            for (int i = 0; i < s * s && first < 0; ++i)
                if (isListed(block * s + int2(i % s, i / s))) first = i;
            if (first != own.y * s + own.x) continue;
            for (int i = 0; i < s * s; ++i)
                if (!isListed(block * s + int2(i % s, i / s))) run(atrousLatticeOrigin(block, int2(i % s, i / s), s));
        }
    return count;
}

// Every pixel of a listed tile is filtered exactly once, and no pixel of an unlisted tile, at every step
// up to 32 (atrousIterations 6), on a view whose size is no multiple of the blocks and with random lists
// (a quarter, half and nine tenths of the tiles listed).
TEST(AtrousBody, EveryPixelOfAListedTileIsFilteredExactlyOnceAtEveryStep) {
    const int width = 203, height = 117, tilesX = (width + 7) / 8, tilesY = (height + 7) / 8;
    std::mt19937 rng(7);
    for (double share : {0.25, 0.5, 0.9}) {
        std::bernoulli_distribution pick(share);
        std::vector<std::vector<bool>> listed(tilesY, std::vector<bool>(tilesX));
        size_t pixels = 0;
        for (int ty = 0; ty < tilesY; ++ty)
            for (int tx = 0; tx < tilesX; ++tx)
                if ((listed[ty][tx] = pick(rng)))
                    pixels += size_t(std::min(8, width - 8 * tx)) * size_t(std::min(8, height - 8 * ty));
        for (int s = 1; s <= 32; s *= 2) {
            const auto count = filteredPixels(listed, s, width, height);
            EXPECT_EQ(count.size(), pixels) << "step " << s << ", share " << share;
            for (const auto& [p, n] : count) ASSERT_EQ(n, 1) << "pixel " << p.first << "," << p.second << " step " << s;
        }
    }
}

// A lattice keeps the step between its points: the apron of 4 points covers the sources (2 steps) and
// their receivers (2 more) of every receiver, whatever the step.
TEST(AtrousBody, LatticePointsAreOneStepApartInsideTheirBlock) {
    for (int s : {1, 2, 4, 8}) {
        const int2 tile(5, 3), block = atrousBlock(tile, s), own = atrousOwnLattice(tile, s);
        const int2 origin = atrousLatticeOrigin(block, own, s);
        EXPECT_EQ(atrousLatticePixel(origin, int2(1, 0), s) - origin, int2(s, 0));
        EXPECT_EQ(origin / (kFilterTileSize * s), block);   // the lattice lies in its block
        EXPECT_EQ(block * s + own, tile);                   // and its designated tile is the one it came from
    }
}

// The weights: the B3 kernel's 25 taps sum to 1; on a plane (depth along the gradient), equal normals
// and equal luminance every weight is the kernel tap; a luminance difference of 3 deviations of the
// difference keeps exp(-4.5) of it, a normal 10 degrees off cos(10 deg)^128 (0.14).
TEST(AtrousBody, SpreadWeightIsTheKernelOnAPlaneAndStopsAtEdges) {
    float sum = 0.0f;
    const float2 grad(0.01f, -0.02f);
    const float3 n(0.0f, 0.0f, 1.0f);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int2 offset = int2(dx, dy) * 2;
            const float zp = 5.0f + glm::dot(grad, float2(offset));
            const float w = atrousSpreadWeight(offset, 2, 5.0f, zp, grad, n, n, 1.0f, 1.0f, 0.1f, 0.1f, 1.0f);
            // zp's float rounding (half an ulp at 5, 2.4e-7) over the depth term's scale (>= 0.02): <= 1.2e-5.
            const float tap = atrousKernelTap(std::abs(dx)) * atrousKernelTap(std::abs(dy));
            EXPECT_NEAR(w, tap, 2e-5f * tap);
            sum += w;
        }
    EXPECT_NEAR(sum, 1.0f, 2e-5f);
    const float centre = atrousKernelTap(0) * atrousKernelTap(0);
    // Var_q + Var_p = 0.02, sigma 1: a difference of 3 sqrt(0.02) is 3 deviations.
    const float lum = atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, n, 1.0f, 1.0f + 3.0f * std::sqrt(0.02f), 0.01f,
                                         0.01f, 1.0f);
    EXPECT_NEAR(lum / centre, std::exp(-4.5f), 1e-5f);
    const float c10 = std::cos(glm::radians(10.0f));
    const float3 tilted(std::sin(glm::radians(10.0f)), 0.0f, c10);
    EXPECT_NEAR(atrousSpreadWeight(int2(0), 1, 5.0f, 5.0f, grad, n, tilted, 1.0f, 1.0f, 0.01f, 0.01f, 1.0f) / centre,
                std::pow(c10, 128.0f), 1e-5f);
}

}  // namespace
}  // namespace caustics::shader
