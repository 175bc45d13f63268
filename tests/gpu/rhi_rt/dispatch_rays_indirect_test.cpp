// ICommandList::dispatchRaysIndirect: the grid comes from a buffer the GPU reads at execution
// (written on the GPU timeline here, as caustics.emitters writes the forward grid); every launch of
// exactly that grid runs once and sees that launch size.
#include <gtest/gtest.h>

#include "rt_fixture.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

TEST_F(RayTracingTest, IndirectDispatchRunsTheGridReadFromTheBuffer) {
    if (!dev().capabilities().rayTracingIndirect) GTEST_SKIP() << "no rayTracingPipelineTraceRaysIndirect";
    auto layout = dev().createBindingLayout(BindingLayoutDesc().setVisibility(ShaderStage::AllRayTracing)
                                                .add(0, BindingType::StorageBufferRW));
    ASSERT_TRUE(layout) << layout.message();
    StateObjectHandle so = makeHitInfoStateObject(dev(), "rt/launch_grid.rgen", layout.value(), 0);
    ASSERT_TRUE(so);
    ShaderTableHandle table = makeHitInfoTable(dev(), so);
    ASSERT_TRUE(table);

    // A larger grid sits in front so that the offset is exercised: the test must see (7, 3, 2).
    const uint32_t grids[6] = {50, 50, 50, 7, 3, 2};
    auto args = dev().createBuffer(BufferDesc().setByteSize(sizeof(grids))
                                       .setUsage(BufferUsage::Indirect | BufferUsage::CopyDest)
                                       .setDebugName("indirect grid"));
    ASSERT_TRUE(args) << args.message();
    constexpr uint32_t kLaunches = 7 * 3 * 2, kSlots = 4 + 64;
    BufferHandle out = makeOutputBuffer(dev(), kSlots * 4, "launches");
    BufferHandle readback = makeReadbackBuffer(dev(), kSlots * 4);
    auto set = dev().createBindingSet(BindingSetDesc().add(BindingSetItem::storageBuffer(0, out)), layout.value());
    ASSERT_TRUE(set) << set.message();

    ASSERT_TRUE(runAndWait(dev(), [&](ICommandList& cmd) {
        cmd.barrier(BufferBarrier{args.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.writeBuffer(args.value(), grids, sizeof(grids));
        cmd.barrier(BufferBarrier{args.value(), ResourceState::CopyDest, ResourceState::IndirectArgument});
        recordClear(cmd, out);
        cmd.setRayTracingState(so, table);
        cmd.setBindingSet(0, set.value());
        cmd.dispatchRaysIndirect(args.value(), 12);
        recordReadback(cmd, out, readback, kSlots * 4);
    }));
    auto got = readBack<uint32_t>(dev(), readback, kSlots);
    ASSERT_EQ(got.size(), size_t(kSlots));
    EXPECT_EQ(got[0], kLaunches);
    EXPECT_EQ(got[1], 7u);
    EXPECT_EQ(got[2], 3u);
    EXPECT_EQ(got[3], 2u);
    for (uint32_t i = 0; i < kSlots - 4; ++i) EXPECT_EQ(got[4 + i], i < kLaunches ? i + 1 : 0u) << "slot " << i;
}

TEST_F(RayTracingTest, IndirectDispatchWithoutIndirectUsageIsAnError) {
    auto layout = dev().createBindingLayout(BindingLayoutDesc().setVisibility(ShaderStage::AllRayTracing)
                                                .add(0, BindingType::StorageBufferRW));
    ASSERT_TRUE(layout) << layout.message();
    StateObjectHandle so = makeHitInfoStateObject(dev(), "rt/launch_grid.rgen", layout.value(), 0);
    ShaderTableHandle table = makeHitInfoTable(dev(), so);
    ASSERT_TRUE(so && table);
    BufferHandle notIndirect = makeOutputBuffer(dev(), 16, "plain storage");
    auto cmd = dev().createCommandList();
    ASSERT_TRUE(cmd) << cmd.message();
    cmd.value()->begin();
    cmd.value()->setRayTracingState(so, table);
    cmd.value()->dispatchRaysIndirect(notIndirect, 0);
    cmd.value()->end();
    auto submitted = dev().submit(cmd.value());
    ASSERT_FALSE(submitted);
    EXPECT_NE(submitted.message().find("BufferUsage::Indirect"), std::string::npos) << submitted.message();
}

}  // namespace
}  // namespace caustics::test
