// Memory aliasing: transients alive at the same time never share bytes; others may.
#include <gtest/gtest.h>

#include <random>

#include "fake_memory_sizer.h"
#include "caustics/render_graph/memory_aliasing.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {
namespace {
using test::FakeMemorySizer;
using test::texDesc;

bool rangesDisjoint(uint64_t aOff, uint64_t aSize, uint64_t bOff, uint64_t bSize) {
    return aOff + aSize <= bOff || bOff + bSize <= aOff;
}

// Checks the aliasing invariant on a compiled plan; returns the number of pairs checked.
int expectNoLiveOverlap(const CompiledPlan& plan) {
    int pairs = 0;
    for (size_t a = 0; a < plan.heapOffset.size(); ++a) {
        if (!plan.heapOffset[a]) continue;
        EXPECT_EQ(*plan.heapOffset[a] % plan.memory[a].alignment, 0u);
        EXPECT_LE(*plan.heapOffset[a] + plan.memory[a].size, plan.heapSize);
        for (size_t b = a + 1; b < plan.heapOffset.size(); ++b) {
            if (!plan.heapOffset[b] || !plan.lifetimes[a].overlaps(plan.lifetimes[b])) continue;
            ++pairs;
            EXPECT_TRUE(rangesDisjoint(*plan.heapOffset[a], plan.memory[a].size, *plan.heapOffset[b],
                                       plan.memory[b].size))
                << "resources " << a << " and " << b << " are alive together but share memory";
        }
    }
    return pairs;
}

TEST(RenderGraphAliasing, ResourcesWithDisjointLifetimesShareMemory) {
    // a -> b -> c chain: a dies when b is written... a and c never live together.
    RenderGraph g;
    RgTexture a, b, c;
    g.addPass("a", [&](PassBuilder& pb) {
        a = pb.write(pb.createTexture("a", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("b", [&](PassBuilder& pb) {
        pb.read(a);
        b = pb.write(pb.createTexture("b", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("c", [&](PassBuilder& pb) {
        pb.read(b);
        c = pb.write(pb.createTexture("c", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(c);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    const CompiledPlan& plan = *g.plan();
    const uint64_t size = 128 * 128 * 4;
    EXPECT_EQ(plan.heapSize, 2 * size) << "three equal textures, at most two alive at once";
    EXPECT_EQ(*plan.heapOffset[a.index], *plan.heapOffset[c.index]);
    expectNoLiveOverlap(plan);
}

TEST(RenderGraphAliasing, ActivationInSharedMemoryWaitsForEarlierUsers) {
    // c takes over a's memory: its first barrier must be an aliasing barrier; b has its own range.
    RenderGraph g;
    RgTexture a, b, c;
    g.addPass("a", [&](PassBuilder& pb) {
        a = pb.write(pb.createTexture("a", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("b", [&](PassBuilder& pb) {
        pb.read(a);
        b = pb.write(pb.createTexture("b", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("c", [&](PassBuilder& pb) {
        pb.read(b);
        c = pb.write(pb.createTexture("c", texDesc(128, 128)), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.markOutput(c);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    auto activation = [&](uint32_t pass, RgTexture t) {
        for (const PlannedBarrier& pb : g.plan()->findPass(pass)->barriers)
            if (pb.resource == t.index && pb.activation) return pb;
        ADD_FAILURE() << "no activation barrier";
        return PlannedBarrier{};
    };
    EXPECT_TRUE(activation(2, c).aliasing);
    EXPECT_TRUE(activation(0, a).aliasing) << "a's range is reused by c (next frame a follows c)";
    EXPECT_FALSE(activation(1, b).aliasing);
}

TEST(RenderGraphAliasing, OutputTransientIsNotReusedAfterItsLastPass) {
    RenderGraph g;
    RgTexture out;
    g.addPass("produce", [&](PassBuilder& pb) {
        out = pb.write(pb.createTexture("out", texDesc()), Access::StorageWrite);
        return [](PassContext&) {};
    });
    g.addPass("later", [&](PassBuilder& pb) {
        pb.write(pb.createTexture("scratch", texDesc()), Access::StorageWrite);
        pb.setSideEffects();
        return [](PassContext&) {};
    });
    g.markOutput(out);
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_EQ(g.plan()->lifetimes[out.index].last, 1u);
    EXPECT_EQ(expectNoLiveOverlap(*g.plan()), 1);
}

TEST(RenderGraphAliasing, HostVisibleBufferStaysOutOfTheHeap) {
    RenderGraph g;
    g.addPass("readback", [&](PassBuilder& pb) {
        pb.write(pb.createBuffer("rb", test::bufDesc().setMemory(rhi::MemoryType::Readback)), Access::CopyDest);
        pb.setSideEffects();
        return [](PassContext&) {};
    });
    ASSERT_TRUE(g.compile(FakeMemorySizer()).ok());
    EXPECT_FALSE(g.plan()->heapOffset[0].has_value());
    EXPECT_EQ(g.plan()->heapSize, 0u);
}

TEST(RenderGraphAliasing, RandomGraphsNeverOverlapLiveResources) {
    std::mt19937 rng(1234);   // fixed seed: failures reproduce
    int totalPairs = 0;
    for (int iteration = 0; iteration < 200; ++iteration) {
        RenderGraph g;
        std::vector<RgTexture> textures;
        std::vector<RgBuffer> buffers;
        int passCount = 2 + int(rng() % 14);
        for (int p = 0; p < passCount; ++p) {
            g.addPass("p" + std::to_string(p), [&](PassBuilder& b) {
                // Read a few earlier resources (the latest versions), then create one or two new ones.
                for (int k = 0; k < 2 && !textures.empty(); ++k) b.read(textures[rng() % textures.size()]);
                if (!buffers.empty() && rng() % 2) b.read(buffers[rng() % buffers.size()]);
                uint32_t side = 16u << (rng() % 4);
                textures.push_back(b.write(b.createTexture("t", texDesc(side, side)), Access::StorageWrite));
                if (rng() % 3 == 0)
                    buffers.push_back(b.write(b.createBuffer("b", test::bufDesc(100 + rng() % 5000)),
                                              Access::StorageWrite));
                if (rng() % 5 == 0) b.setSideEffects();
                return [](PassContext&) {};
            });
        }
        g.markOutput(textures.back());
        FakeMemorySizer sizer(64u << (rng() % 4));
        ASSERT_TRUE(g.compile(sizer).ok());
        totalPairs += expectNoLiveOverlap(*g.plan());
    }
    EXPECT_GT(totalPairs, 100) << "the random graphs must actually exercise overlapping lifetimes";
}

TEST(MemoryAliasing, RandomIntervalsGetDisjointRangesWhenAliveTogether) {
    std::mt19937 rng(99);
    for (int iteration = 0; iteration < 300; ++iteration) {
        std::vector<AliasRequest> requests(1 + rng() % 20);
        for (AliasRequest& r : requests) {
            r.size = 1 + rng() % 10000;
            r.alignment = 1ull << (rng() % 9);
            uint32_t a = rng() % 12, b = rng() % 12;
            r.lifetime = {std::min(a, b), std::max(a, b)};
        }
        AliasPlacement placement = placeAliased(requests);
        for (size_t i = 0; i < requests.size(); ++i) {
            EXPECT_EQ(placement.offsets[i] % requests[i].alignment, 0u);
            EXPECT_LE(placement.offsets[i] + requests[i].size, placement.heapSize);
            for (size_t j = i + 1; j < requests.size(); ++j) {
                if (!requests[i].lifetime.overlaps(requests[j].lifetime)) continue;
                EXPECT_TRUE(rangesDisjoint(placement.offsets[i], requests[i].size, placement.offsets[j],
                                           requests[j].size));
            }
        }
    }
}

}  // namespace
}  // namespace caustics::rg
