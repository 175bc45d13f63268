// Heap aliasing (virtual buffers placed at the same offset share memory) and timestamp queries.
#include <cstring>

#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

TEST_F(GpuTest, VirtualBuffersAtTheSameHeapOffsetSeeEachOthersWrites) {
    constexpr uint64_t kBytes = 4096;
    BufferDesc desc = BufferDesc().setByteSize(kBytes).setVirtual(true);
    MemoryRequirements req = device->memoryRequirements(desc);
    ASSERT_GE(req.size, kBytes);
    auto heap = device->createHeap(HeapDesc{req.size * 4, "heap"});
    ASSERT_TRUE(heap.ok()) << heap.message();
    auto a = device->createBuffer(BufferDesc(desc).setDebugName("alias a"));
    auto b = device->createBuffer(BufferDesc(desc).setDebugName("alias b"));
    ASSERT_TRUE(a.ok() && b.ok());
    const uint64_t offset = req.alignment * 2;   // not at 0, to exercise the offset
    ASSERT_TRUE(device->bindMemory(a.value(), heap.value(), offset).ok());
    ASSERT_TRUE(device->bindMemory(b.value(), heap.value(), offset).ok());

    BufferHandle readback = createReadback(kBytes);
    runCommands([&](ICommandList& cmd) {
        cmd.barrier(BufferBarrier{a.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.fillBuffer(a.value(), 0x600DF00Du);
        // Both handles name the same memory: order the fill before the copy through either.
        const BufferBarrier handoff[] = {{a.value(), ResourceState::CopyDest, ResourceState::CopySource},
                                         {b.value(), ResourceState::CopyDest, ResourceState::CopySource}};
        cmd.barriers({}, handoff);
        cmd.copyBuffer(readback, 0, b.value(), 0, kBytes);
    });
    std::vector<uint8_t> bytes = readBuffer(readback, kBytes);
    for (uint64_t i = 0; i < kBytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, &bytes[i], 4);
        ASSERT_EQ(v, 0x600DF00Du) << "at byte " << i;
    }
}

TEST_F(GpuTest, BindMemoryRefusesAPlacementPastTheHeapEnd) {
    BufferDesc desc = BufferDesc().setByteSize(4096).setVirtual(true).setDebugName("too far");
    auto heap = device->createHeap(HeapDesc{8192, "small heap"});
    auto buffer = device->createBuffer(desc);
    ASSERT_TRUE(heap.ok() && buffer.ok());
    Status bound = device->bindMemory(buffer.value(), heap.value(), 8192);
    ASSERT_FALSE(bound.ok());
    EXPECT_NE(bound.message().find("too far"), std::string::npos) << bound.message();
}

TEST_F(GpuTest, TimestampsAroundADispatchAreAvailableAndOrdered) {
    auto layout = device->createBindingLayout(BindingLayoutDesc().add(0, BindingType::StorageBufferRW));
    ASSERT_TRUE(layout.ok());
    ComputePipelineDesc pd;
    pd.shader.code = testShader("rhi_core/noop.comp");
    pd.bindings.layouts = {layout.value()};
    auto pipeline = device->createComputePipeline(pd);
    ASSERT_TRUE(pipeline.ok()) << pipeline.message();
    auto buffer = device->createBuffer(BufferDesc().setByteSize(64 * 64 * 4).setDebugName("counters"));
    ASSERT_TRUE(buffer.ok());
    auto set = device->createBindingSet(BindingSetDesc().add(BindingSetItem::storageBuffer(0, buffer.value())),
                                        layout.value());
    auto pool = device->createTimestampPool(2);
    ASSERT_TRUE(set.ok() && pool.ok());

    runCommands([&](ICommandList& cmd) {
        cmd.resetTimestamps(pool.value(), 0, 2);
        cmd.barrier(BufferBarrier{buffer.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.fillBuffer(buffer.value(), 0);
        cmd.barrier(BufferBarrier{buffer.value(), ResourceState::CopyDest, ResourceState::UnorderedAccess});
        cmd.beginMarker("timed dispatch");
        cmd.writeTimestamp(pool.value(), 0);
        cmd.setComputePipeline(pipeline.value());
        cmd.setBindingSet(0, set.value());
        cmd.dispatch(64);
        cmd.writeTimestamp(pool.value(), 1);
        cmd.endMarker();
    });
    std::vector<std::optional<double>> t = device->readTimestamps(pool.value(), 0, 2);
    ASSERT_EQ(t.size(), 2u);
    ASSERT_TRUE(t[0].has_value());
    ASSERT_TRUE(t[1].has_value());
    EXPECT_GE(*t[1] - *t[0], 0.0);
}

}  // namespace
}  // namespace caustics::test
