#pragma once
// Test double of a device and command list for execute(): objects are plain fakes, and the command
// list writes one line per call so tests can check what the graph recorded and in which order.
// Timestamps read back as index * 1 ms, so every timed pass measures exactly 1 ms.
#include <map>
#include <string>
#include <vector>

#include "fake_memory_sizer.h"
#include "fake_rhi_objects.h"
#include "caustics/rhi/device.h"

namespace caustics::rg::test {

class FakeHeap final : public rhi::IHeap {
public:
    explicit FakeHeap(rhi::HeapDesc d) : desc_(std::move(d)) {}
    const rhi::HeapDesc& desc() const override { return desc_; }

private:
    rhi::HeapDesc desc_;
};

class FakeTimestampPool final : public rhi::ITimestampPool {
public:
    explicit FakeTimestampPool(uint32_t n) : n_(n) {}
    uint32_t capacity() const override { return n_; }

private:
    uint32_t n_;
};

class RecordingCommandList final : public rhi::ICommandList {
public:
    std::vector<std::string> calls;
    // Every barrier as recorded, with its stages (calls keeps the states only).
    std::vector<rhi::TextureBarrier> textureBarriers;
    std::vector<rhi::BufferBarrier> bufferBarriers;
    bool timestamps = true;   // false: a host's list wrapped with allowTimestamps = false
    bool recordsTimestamps() const override { return timestamps; }

    void begin() override {}
    void end() override {}
    void barriers(std::span<const rhi::TextureBarrier> t, std::span<const rhi::BufferBarrier> b,
                  std::span<const rhi::AccelStructBarrier> a) override {
        textureBarriers.insert(textureBarriers.end(), t.begin(), t.end());
        bufferBarriers.insert(bufferBarriers.end(), b.begin(), b.end());
        for (const auto& x : t)
            calls.push_back("barrier " + x.texture->desc().debugName + " " + rhi::resourceStateName(x.before) + "->" +
                            rhi::resourceStateName(x.after));
        for (const auto& x : b)
            calls.push_back("barrier " + x.buffer->desc().debugName + " " + rhi::resourceStateName(x.before) + "->" +
                            rhi::resourceStateName(x.after));
        for (const auto& x : a)
            calls.push_back(std::string("barrier as ") + rhi::resourceStateName(x.before) + "->" +
                            rhi::resourceStateName(x.after));
    }
    void writeBuffer(const rhi::BufferHandle&, const void*, uint64_t, uint64_t) override {}
    void copyBuffer(const rhi::BufferHandle&, uint64_t, const rhi::BufferHandle&, uint64_t, uint64_t) override {}
    void fillBuffer(const rhi::BufferHandle&, uint32_t, uint64_t, uint64_t) override {}
    void writeTexture(const rhi::TextureHandle&, uint32_t, uint32_t, const void*, uint64_t) override {}
    void copyTexture(const rhi::TextureHandle&, const rhi::TextureRegion&, const rhi::TextureHandle&,
                     const rhi::TextureRegion&) override {}
    void copyTextureToBuffer(const rhi::BufferHandle&, uint64_t, const rhi::TextureHandle&, uint32_t,
                             uint32_t) override {}
    void clearTextureFloat(const rhi::TextureHandle&, const float[4]) override {}
    void clearTextureUint(const rhi::TextureHandle&, const uint32_t[4]) override {}
    void setComputePipeline(const rhi::ComputePipelineHandle&) override {}
    void dispatch(uint32_t, uint32_t, uint32_t) override { calls.push_back("dispatch"); }
    void dispatchIndirect(const rhi::BufferHandle&, uint64_t) override { calls.push_back("dispatchIndirect"); }
    void beginRendering(const rhi::RenderingDesc&) override {}
    void endRendering() override {}
    void setGraphicsPipeline(const rhi::GraphicsPipelineHandle&) override {}
    void setViewport(float, float, float, float) override {}
    void setVertexBuffer(uint32_t, const rhi::BufferHandle&, uint64_t) override {}
    void setIndexBuffer(const rhi::BufferHandle&, uint64_t) override {}
    void draw(uint32_t, uint32_t, uint32_t, uint32_t) override {}
    void drawIndexed(uint32_t, uint32_t, uint32_t, int32_t, uint32_t) override {}
    void setRayTracingState(const rhi::StateObjectHandle&, const rhi::ShaderTableHandle&) override {}
    void dispatchRays(uint32_t, uint32_t, uint32_t) override {}
    void dispatchRaysIndirect(const rhi::BufferHandle&, uint64_t) override {}
    void buildBottomLevel(const rhi::AccelStructHandle&, bool) override {}
    void buildTopLevel(const rhi::AccelStructHandle&, std::span<const rhi::InstanceDesc>, bool) override {}
    void buildTopLevelFromBuffer(const rhi::AccelStructHandle&, const rhi::BufferHandle&, uint64_t, uint32_t,
                                 bool) override {}
    void setBindingSet(uint32_t, const rhi::BindingSetHandle&) override {}
    void setPushConstants(const void*, uint32_t) override {}
    void resetTimestamps(const rhi::TimestampPoolHandle&, uint32_t, uint32_t) override {}
    void writeTimestamp(const rhi::TimestampPoolHandle&, uint32_t index) override {
        calls.push_back("timestamp " + std::to_string(index));
    }
    void beginMarker(std::string_view name) override { calls.push_back("begin " + std::string(name)); }
    void endMarker() override { calls.push_back("end"); }
};

class RecordingDevice final : public rhi::IDevice {
public:
    int texturesCreated = 0;
    int buffersCreated = 0;
    int heapsCreated = 0;
    int timestampPoolsCreated = 0;
    std::map<const void*, uint64_t> boundOffsets;

    rhi::Backend backend() const override { return rhi::Backend::Vulkan; }
    const rhi::Capabilities& capabilities() const override { return caps_; }
    Result<rhi::BufferHandle> createBuffer(const rhi::BufferDesc& d) override {
        ++buffersCreated;
        return rhi::BufferHandle(std::make_shared<FakeBuffer>(d));
    }
    Result<rhi::TextureHandle> createTexture(const rhi::TextureDesc& d) override {
        ++texturesCreated;
        return rhi::TextureHandle(std::make_shared<FakeTexture>(d));
    }
    Result<rhi::SamplerHandle> createSampler(const rhi::SamplerDesc&) override { return unsupported(); }
    Result<rhi::HeapHandle> createHeap(const rhi::HeapDesc& d) override {
        ++heapsCreated;
        return rhi::HeapHandle(std::make_shared<FakeHeap>(d));
    }
    rhi::MemoryRequirements memoryRequirements(const rhi::TextureDesc& d) override { return sizer_.requirements(d); }
    rhi::MemoryRequirements memoryRequirements(const rhi::BufferDesc& d) override { return sizer_.requirements(d); }
    Status bindMemory(const rhi::TextureHandle& t, const rhi::HeapHandle&, uint64_t offset) override {
        boundOffsets[t.get()] = offset;
        return okStatus();
    }
    Status bindMemory(const rhi::BufferHandle& b, const rhi::HeapHandle&, uint64_t offset) override {
        boundOffsets[b.get()] = offset;
        return okStatus();
    }
    Result<rhi::BindingLayoutHandle> createBindingLayout(const rhi::BindingLayoutDesc&) override { return unsupported(); }
    Result<rhi::BindingSetHandle> createBindingSet(const rhi::BindingSetDesc&, const rhi::BindingLayoutHandle&) override {
        return unsupported();
    }
    Result<rhi::ComputePipelineHandle> createComputePipeline(const rhi::ComputePipelineDesc&) override {
        return unsupported();
    }
    Result<rhi::GraphicsPipelineHandle> createGraphicsPipeline(const rhi::GraphicsPipelineDesc&) override {
        return unsupported();
    }
    Result<rhi::AccelStructHandle> createAccelStruct(const rhi::AccelStructDesc&) override { return unsupported(); }
    Result<rhi::AccelStructHandle> compactAccelStruct(const rhi::AccelStructHandle&) override { return unsupported(); }
    Result<rhi::StateObjectHandle> createStateObject(const rhi::StateObjectDesc&) override { return unsupported(); }
    Result<rhi::ShaderTableHandle> createShaderTable(const rhi::ShaderTableDesc&) override { return unsupported(); }
    Result<rhi::TimestampPoolHandle> createTimestampPool(uint32_t count) override {
        ++timestampPoolsCreated;
        return rhi::TimestampPoolHandle(std::make_shared<FakeTimestampPool>(count));
    }
    std::vector<std::optional<double>> readTimestamps(const rhi::TimestampPoolHandle&, uint32_t first,
                                                      uint32_t count) override {
        std::vector<std::optional<double>> v;
        for (uint32_t i = 0; i < count; ++i) v.push_back(double(first + i) * 1e6);
        return v;
    }
    Result<rhi::CommandListHandle> createCommandList() override {
        return rhi::CommandListHandle(std::make_shared<RecordingCommandList>());
    }
    Result<uint64_t> submit(std::span<const rhi::CommandListHandle>) override { return uint64_t(1); }
    Status waitForFence(uint64_t) override { return okStatus(); }
    Status waitIdle() override { return okStatus(); }
    Status readBuffer(const rhi::BufferHandle&, void*, uint64_t, uint64_t) override { return okStatus(); }

private:
    static Error unsupported() { return makeError("recording device: not supported"); }
    rhi::Capabilities caps_;
    FakeMemorySizer sizer_;
};

}  // namespace caustics::rg::test
