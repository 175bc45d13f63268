// Acceleration-structure life cycle: a TLAS of 100,000 instances answers rays like the CPU; after the
// instances move, an update (refit) from a GPU instance buffer answers the moved scene; a compacted
// BLAS is no larger and traces identically.
#include <gtest/gtest.h>

#include <random>

#include "rt_fixture.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

constexpr uint32_t kGridX = 400, kGridY = 250;   // 100,000 instances, one per unit cell
constexpr uint32_t kRays = 2000;
// Same reasoning as the triangle test: GPU float traversal vs double CPU barycentrics.
constexpr double kEdgeEpsilon = 1e-4;

// Instance i sits in cell (i % kGridX, i / kGridX) at a pseudo-random height; `moved` shifts it by up
// to 0.3 and turns it, so a moved quad (reach 0.2 * sqrt 2 from its centre) may overlap its neighbours.
Transform cellTransform(uint32_t i, bool moved) {
    const double cx = double(i % kGridX) + 0.5, cy = double(i / kGridX) + 0.5;
    const double z = double((i * 2654435761u) % 1000) / 500.0;
    if (!moved) return makeTransform(0, 0, 0, {1, 1, 1}, {cx, cy, z});
    const double dx = 0.3 * (double(i % 3) - 1.0), dy = 0.3 * (double((i / 7) % 3) - 1.0);
    return makeTransform(0, 0, 0.1 * double(i % 5), {1, 1, 1}, {cx + dx, cy + dy, z + 0.5});
}

// Vertical rays at random (x, y) over the grid; each can only hit instances of its own cell or of the 8
// around it (the CPU reference tests those nine).
RayList gridRays(std::vector<std::vector<uint32_t>>& candidates) {
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> x(0.0, kGridX), y(0.0, kGridY);
    RayList rays;
    for (uint32_t r = 0; r < kRays; ++r) {
        const double px = x(rng), py = y(rng);
        rays.add({px, py, 10.0}, {0, 0, -1}, 0.0f, 100.0f);
        std::vector<uint32_t> near;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int cx = int(px) + dx, cy = int(py) + dy;
                if (cx >= 0 && cy >= 0 && cx < int(kGridX) && cy < int(kGridY)) near.push_back(uint32_t(cy) * kGridX + uint32_t(cx));
            }
        }
        candidates.push_back(std::move(near));
    }
    return rays;
}

// Compares GPU hits with the CPU reference; returns the number of rays that hit something.
uint32_t expectMatchesCpu(const std::vector<std::array<uint32_t, 2>>& gpu, const RayList& rays,
                          const std::vector<CpuInstance>& cpu, const std::vector<std::vector<uint32_t>>& candidates) {
    EXPECT_EQ(gpu.size(), size_t(rays.count()));
    if (gpu.size() != rays.count()) return 0;
    uint32_t wrong = 0, hits = 0, ambiguous = 0;
    for (uint32_t r = 0; r < rays.count(); ++r) {
        const CpuHit ref = traceCpu(cpu, rays.origin(r), rays.direction(r), 0.0, 100.0, kEdgeEpsilon,
                                    candidates.empty() ? std::vector<uint32_t>{} : candidates[r]);
        if (ref.ambiguous) {
            ++ambiguous;
            continue;
        }
        hits += ref.hit ? 1 : 0;
        const std::array<uint32_t, 2> want = ref.hit ? std::array{ref.instanceId, ref.primitiveId} : std::array{~0u, ~0u};
        if (gpu[r] != want && ++wrong <= 10)
            ADD_FAILURE() << "ray " << r << ": GPU (" << gpu[r][0] << ", " << gpu[r][1] << "), CPU (" << want[0] << ", "
                          << want[1] << ")";
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_LT(ambiguous, rays.count() / 50);
    return hits;
}

TEST_F(RayTracingTest, HundredThousandInstancesTraceCorrectlyBeforeAndAfterRefit) {
    const CpuMesh quad = makeQuad(0.2f);
    std::vector<BufferHandle> keep;
    AccelStructHandle blas = makeTriangleBlas(dev(), quad, AccelBuildFlags::PreferFastTrace, keep);
    ASSERT_TRUE(blas);
    const uint32_t count = kGridX * kGridY;
    std::vector<CpuInstance> cpu(count);
    std::vector<InstanceDesc> instances(count);
    for (uint32_t i = 0; i < count; ++i) {
        cpu[i] = {&quad, cellTransform(i, false), i};
        writeTransform(cpu[i].transform, instances[i]);
        instances[i].instanceId = i;
        instances[i].blasAddress = blas->deviceAddress();
    }
    AccelStructDesc tlasDesc;
    tlasDesc.isTopLevel = true;
    tlasDesc.maxInstances = count;
    tlasDesc.flags = AccelBuildFlags::AllowUpdate | AccelBuildFlags::PreferFastBuild;
    auto tlas = dev().createAccelStruct(tlasDesc);
    ASSERT_TRUE(tlas) << tlas.message();
    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.buildBottomLevel(blas);
        cmd.barrier(AccelStructBarrier{blas, ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        cmd.buildTopLevel(tlas.value(), instances);
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
    }));
    std::vector<std::vector<uint32_t>> candidates;
    const RayList rays = gridRays(candidates);
    const uint32_t hitsBefore = expectMatchesCpu(traceRayList(dev(), tlas.value(), rays), rays, cpu, candidates);
    EXPECT_GT(hitsBefore, kRays / 20) << "quads cover 16% of the grid; too few hits means a broken scene";

    // Move every instance and refit from a GPU buffer of InstanceDesc (buildTopLevelFromBuffer).
    for (uint32_t i = 0; i < count; ++i) {
        cpu[i].transform = cellTransform(i, true);
        writeTransform(cpu[i].transform, instances[i]);
    }
    BufferHandle instanceBuffer = makeUploadBuffer(dev(), instances, BufferUsage::AccelStructInput, "moved instances");
    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructRead, ResourceState::AccelStructWrite});
        cmd.buildTopLevelFromBuffer(tlas.value(), instanceBuffer, 0, count, /*update=*/true);
        cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
    }));
    const uint32_t hitsAfter = expectMatchesCpu(traceRayList(dev(), tlas.value(), rays), rays, cpu, candidates);
    EXPECT_GT(hitsAfter, kRays / 20);
}

TEST_F(RayTracingTest, CompactedBlasIsNoLargerAndTracesIdentically) {
    const CpuMesh terrain = makeTerrain(32, 0.2f);
    std::vector<BufferHandle> keep;
    AccelStructHandle blas = makeTriangleBlas(dev(), terrain, AccelBuildFlags::AllowCompaction | AccelBuildFlags::PreferFastTrace, keep);
    ASSERT_TRUE(blas);
    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.buildBottomLevel(blas);
        cmd.barrier(AccelStructBarrier{blas, ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
    }));
    auto compacted = dev().compactAccelStruct(blas);
    ASSERT_TRUE(compacted) << compacted.message();
    EXPECT_LE(compacted.value()->storageBytes(), blas->storageBytes());
    EXPECT_NE(compacted.value()->deviceAddress(), blas->deviceAddress());

    // One TLAS over each version, the same rays through both.
    auto tlasOver = [&](const AccelStructHandle& bottom) -> AccelStructHandle {
        AccelStructDesc desc;
        desc.isTopLevel = true;
        desc.maxInstances = 1;
        auto tlas = dev().createAccelStruct(desc);
        EXPECT_TRUE(tlas) << tlas.message();
        if (!tlas) return nullptr;
        InstanceDesc instance;
        instance.instanceId = 5;
        instance.blasAddress = bottom->deviceAddress();
        EXPECT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
            cmd.buildTopLevel(tlas.value(), std::span(&instance, 1));
            cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        }));
        return tlas.value();
    };
    AccelStructHandle originalTlas = tlasOver(blas), compactedTlas = tlasOver(compacted.value());
    ASSERT_TRUE(originalTlas && compactedTlas);

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.2, 1.2), tilt(-0.3, 0.3);
    RayList rays;
    for (int i = 0; i < 4096; ++i) rays.add({u(rng), u(rng), 3.0}, {tilt(rng), tilt(rng), -1.0}, 0.0f, 100.0f);
    const auto original = traceRayList(dev(), originalTlas, rays);
    const auto fromCompacted = traceRayList(dev(), compactedTlas, rays);
    ASSERT_EQ(original.size(), size_t(rays.count()));
    EXPECT_TRUE(original == fromCompacted) << "the compacted copy must trace bit-identically";
    std::vector<CpuInstance> cpu = {{&terrain, makeTransform(0, 0, 0, {1, 1, 1}, {0, 0, 0}), 5}};
    EXPECT_GT(expectMatchesCpu(original, rays, cpu, {}), kRays / 2);
}

}  // namespace
}  // namespace caustics::test
