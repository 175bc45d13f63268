#include "pass_pipeline_recorder.h"

#include <cstring>
#include <map>
#include <memory>

#include "caustic_maps/caustic_internal.h"
#include "caustics_output/caustics_output_pass.h"
#include "caustics/caustic_passes.h"
#include "caustics/caustics_module.h"
#include "recording_device.h"   // tests/unit/render_graph

namespace caustics::test {
namespace {

// A fake whose only state is the desc it was created with.
template <typename Interface, typename Desc>
class DescOnly final : public Interface {
public:
    explicit DescOnly(Desc d) : desc_(std::move(d)) {}
    const Desc& desc() const override { return desc_; }

private:
    Desc desc_;
};

class HostBuffer final : public rhi::IBuffer {
public:
    explicit HostBuffer(rhi::BufferDesc d) : desc_(std::move(d)), bytes_(size_t(desc_.byteSize)) {}
    const rhi::BufferDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return 0x10000; }
    void* mappedData() override { return bytes_.data(); }   // passes fill upload buffers at creation

private:
    rhi::BufferDesc desc_;
    std::vector<uint8_t> bytes_;
};

class FakeAccelStruct final : public rhi::IAccelStruct {
public:
    explicit FakeAccelStruct(rhi::AccelStructDesc d) : desc_(std::move(d)) {}
    const rhi::AccelStructDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return 0x20000; }
    uint64_t storageBytes() const override { return 256; }

private:
    rhi::AccelStructDesc desc_;
};

class FakeStateObject final : public rhi::IStateObject {
public:
    explicit FakeStateObject(rhi::StateObjectDesc d) : desc_(std::move(d)) {}
    const rhi::StateObjectDesc& desc() const override { return desc_; }
    std::vector<uint8_t> shaderIdentifier(const std::string& name) const override {
        return std::vector<uint8_t>(32, uint8_t(name.size()));
    }

private:
    rhi::StateObjectDesc desc_;
};

class FakeBindingSet final : public rhi::IBindingSet {
public:
    FakeBindingSet(rhi::BindingSetDesc d, rhi::BindingLayoutHandle l) : desc_(std::move(d)), layout_(std::move(l)) {}
    const rhi::BindingSetDesc& desc() const override { return desc_; }
    const rhi::BindingLayoutHandle& layout() const override { return layout_; }

private:
    rhi::BindingSetDesc desc_;
    rhi::BindingLayoutHandle layout_;
};

// "forward_trace/forward.rgen.hlsl" (caustics::hlsl::shaderCode) -> "forward_trace/forward.rgen"
std::string passShaderName(const std::string& debugName) {
    std::string n = debugName;
    const std::string prefix = "shaders/d3d12/", suffix = ".hlsl";
    if (n.rfind(prefix, 0) == 0) n = n.substr(prefix.size());
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
        n.resize(n.size() - suffix.size());
    return n;
}

RecordedShader recordShader(const rhi::ShaderCode& code, rhi::ShaderStage stage) {
    return {passShaderName(code.debugName), stage, std::string(code.bytes.begin(), code.bytes.end())};
}

std::vector<rhi::BindingLayoutDesc> layoutDescs(const rhi::PipelineBindings& b) {
    std::vector<rhi::BindingLayoutDesc> out;
    for (const auto& l : b.layouts) out.push_back(l ? l->desc() : rhi::BindingLayoutDesc{});
    return out;
}

class RecordingDevice final : public rhi::IDevice {
public:
    RecordingDevice(bool floatAtomics, bool int64Atomics) {
        caps_.adapterName = "binding recorder";
        caps_.rayTracingPipeline = caps_.accelerationStructure = true;
        caps_.shaderFloatAtomicAdd = floatAtomics;
        caps_.shaderBufferInt64Atomics = int64Atomics;
        caps_.maxRayRecursionDepth = 31;
        caps_.maxInstanceCount = 1u << 24;
    }
    std::vector<RecordedPipeline> pipelines;

    rhi::Backend backend() const override { return rhi::Backend::D3D12; }
    const rhi::Capabilities& capabilities() const override { return caps_; }
    Result<rhi::BufferHandle> createBuffer(const rhi::BufferDesc& d) override {
        return rhi::BufferHandle(std::make_shared<HostBuffer>(d));
    }
    Result<rhi::TextureHandle> createTexture(const rhi::TextureDesc& d) override {
        return rhi::TextureHandle(std::make_shared<DescOnly<rhi::ITexture, rhi::TextureDesc>>(d));
    }
    Result<rhi::SamplerHandle> createSampler(const rhi::SamplerDesc& d) override {
        return rhi::SamplerHandle(std::make_shared<DescOnly<rhi::ISampler, rhi::SamplerDesc>>(d));
    }
    Result<rhi::HeapHandle> createHeap(const rhi::HeapDesc& d) override {
        return rhi::HeapHandle(std::make_shared<DescOnly<rhi::IHeap, rhi::HeapDesc>>(d));
    }
    rhi::MemoryRequirements memoryRequirements(const rhi::TextureDesc&) override { return {65536, 65536}; }
    rhi::MemoryRequirements memoryRequirements(const rhi::BufferDesc& d) override { return {d.byteSize, 256}; }
    Status bindMemory(const rhi::TextureHandle&, const rhi::HeapHandle&, uint64_t) override { return okStatus(); }
    Status bindMemory(const rhi::BufferHandle&, const rhi::HeapHandle&, uint64_t) override { return okStatus(); }
    Result<rhi::BindingLayoutHandle> createBindingLayout(const rhi::BindingLayoutDesc& d) override {
        return rhi::BindingLayoutHandle(std::make_shared<DescOnly<rhi::IBindingLayout, rhi::BindingLayoutDesc>>(d));
    }
    Result<rhi::BindingSetHandle> createBindingSet(const rhi::BindingSetDesc& d, const rhi::BindingLayoutHandle& l) override {
        return rhi::BindingSetHandle(std::make_shared<FakeBindingSet>(d, l));
    }
    Result<rhi::ComputePipelineHandle> createComputePipeline(const rhi::ComputePipelineDesc& d) override {
        RecordedPipeline p = common(PipelineKind::Compute, d.debugName, d.bindings);
        p.shaders = {recordShader(d.shader.code, rhi::ShaderStage::Compute)};
        p.compute = d;
        pipelines.push_back(std::move(p));
        return rhi::ComputePipelineHandle(std::make_shared<DescOnly<rhi::IComputePipeline, rhi::ComputePipelineDesc>>(d));
    }
    Result<rhi::GraphicsPipelineHandle> createGraphicsPipeline(const rhi::GraphicsPipelineDesc& d) override {
        RecordedPipeline p = common(PipelineKind::Graphics, d.debugName, d.bindings);
        p.shaders = {recordShader(d.vertexShader.code, rhi::ShaderStage::Vertex)};
        if (d.fragmentShader.stage != rhi::ShaderStage::None)
            p.shaders.push_back(recordShader(d.fragmentShader.code, rhi::ShaderStage::Fragment));
        p.graphics = d;
        pipelines.push_back(std::move(p));
        return rhi::GraphicsPipelineHandle(std::make_shared<DescOnly<rhi::IGraphicsPipeline, rhi::GraphicsPipelineDesc>>(d));
    }
    Result<rhi::AccelStructHandle> createAccelStruct(const rhi::AccelStructDesc& d) override {
        return rhi::AccelStructHandle(std::make_shared<FakeAccelStruct>(d));
    }
    Result<rhi::AccelStructHandle> compactAccelStruct(const rhi::AccelStructHandle& built) override { return built; }
    Result<rhi::StateObjectHandle> createStateObject(const rhi::StateObjectDesc& d) override {
        RecordedPipeline p = common(PipelineKind::RayTracing, d.debugName, d.globalBindings);
        p.maxPayloadBytes = d.maxPayloadBytes;
        p.maxAttributeBytes = d.maxAttributeBytes;
        for (const auto& lib : d.libraries)
            for (const auto& e : lib.exports) p.shaders.push_back(recordShader(lib.code, e.stage));
        p.stateObject = d;
        auto handle = std::make_shared<FakeStateObject>(d);
        stateObjectIndex_[handle.get()] = pipelines.size();
        pipelines.push_back(std::move(p));
        return rhi::StateObjectHandle(handle);
    }
    Result<rhi::ShaderTableHandle> createShaderTable(const rhi::ShaderTableDesc& d) override {
        auto it = stateObjectIndex_.find(d.stateObject.get());
        if (it == stateObjectIndex_.end()) return makeError("recorder: shader table over an unknown state object");
        pipelines[it->second].shaderTables.push_back(d);
        return rhi::ShaderTableHandle(std::make_shared<DescOnly<rhi::IShaderTable, rhi::ShaderTableDesc>>(d));
    }
    Result<rhi::TimestampPoolHandle> createTimestampPool(uint32_t count) override {
        return rhi::TimestampPoolHandle(std::make_shared<rg::test::FakeTimestampPool>(count));
    }
    std::vector<std::optional<double>> readTimestamps(const rhi::TimestampPoolHandle&, uint32_t, uint32_t count) override {
        return std::vector<std::optional<double>>(count);
    }
    Result<rhi::CommandListHandle> createCommandList() override {
        // Creation-time command lists only build the sphere BLAS; the render graph tests' list records it.
        return rhi::CommandListHandle(std::make_shared<rg::test::RecordingCommandList>());
    }
    Result<uint64_t> submit(std::span<const rhi::CommandListHandle>) override { return ++fence_; }
    Status waitForFence(uint64_t) override { return okStatus(); }
    Status waitIdle() override { return okStatus(); }
    Status readBuffer(const rhi::BufferHandle& b, void* dst, uint64_t bytes, uint64_t offset) override {
        std::memcpy(dst, static_cast<const uint8_t*>(b->mappedData()) + offset, size_t(bytes));
        return okStatus();
    }

private:
    static RecordedPipeline common(PipelineKind kind, const std::string& name, const rhi::PipelineBindings& b) {
        RecordedPipeline p;
        p.kind = kind;
        p.debugName = name;
        p.layouts = layoutDescs(b);
        p.pushConstantBytes = b.pushConstantBytes;
        return p;
    }
    rhi::Capabilities caps_;
    std::map<const void*, size_t> stateObjectIndex_;
    uint64_t fence_ = 0;
};

}  // namespace

Result<std::vector<RecordedPipeline>> recordPassPipelines(const PassPipelineOptions& options) {
    auto device = std::make_shared<RecordingDevice>(options.floatAtomics, options.int64Atomics);
    // The smallest scene SceneBindings accepts: one instance, a TLAS and one texture.
    scene::Scene scene;
    scene.name = "binding recorder";
    scene.instances.push_back({});
    scene::GpuScene gpuScene;
    CAUSTICS_TRY(gpuScene.tlas, device->createAccelStruct(rhi::AccelStructDesc{}));
    CAUSTICS_TRY(auto texture, device->createTexture(rhi::TextureDesc().setSize(1, 1).setFormat(rhi::Format::RGBA8_SRGB)));
    for (auto* b : {&gpuScene.positions, &gpuScene.vertices, &gpuScene.indices, &gpuScene.materials, &gpuScene.instances}) {
        CAUSTICS_TRY(*b, device->createBuffer(rhi::BufferDesc().setByteSize(64)));
    }
    gpuScene.textures = {texture};

    // G-buffer, direct lighting and composite (and the scene and camera layouts they share).
    auto module = CausticsModule::create(device, scene, gpuScene, CausticsSettings{});
    if (!module) return makeError("recording CausticsModule::create: " + module.message());
    // The caustic passes: their persistent pipelines, then the ones that depend on the scene layout.
    auto sceneBindings = SceneBindings::create(*device, gpuScene, scene);
    if (!sceneBindings) return makeError("recording SceneBindings::create: " + sceneBindings.message());
    auto caustics = CausticResources::create(*device);
    if (!caustics) return makeError("recording CausticResources::create: " + caustics.message());
    Status scenePipelines = caustics.value().impl()->ensureScenePipelines(sceneBindings.value().layout);
    if (!scenePipelines.ok()) return makeError("recording the caustic scene pipelines: " + scenePipelines.message());
    // The caustics-only output: its pipelines are made per host format on first use (one stands for all).
    auto output = CausticsOutputPass::create(*device);
    if (!output) return makeError("recording CausticsOutputPass::create: " + output.message());
    auto outputPipeline = output.value().pipeline(*device, rhi::Format::RGBA16_FLOAT, OutputWrite::Add);
    if (!outputPipeline) return makeError("recording the caustics output pipeline: " + outputPipeline.message());
    return std::move(device->pipelines);
}

}  // namespace caustics::test
