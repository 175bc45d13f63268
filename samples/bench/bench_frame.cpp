#include "bench_frame.h"

#include "caustics/caustic_passes.h"
#include "caustics/rhi/format.h"

namespace caustics::bench {

Result<std::unique_ptr<BenchFrames>> BenchFrames::create(rhi::DeviceHandle device, CausticsModule& module,
                                                         uint32_t width, uint32_t height) {
    std::unique_ptr<BenchFrames> r(new BenchFrames());
    r->device_ = device;
    r->module_ = &module;
    r->width_ = width;
    r->height_ = height;
    CAUSTICS_TRY(r->cmd_, device->createCommandList());
    auto readback = [&](uint64_t bytes, const char* name) {
        return device->createBuffer(rhi::BufferDesc().setByteSize(bytes).setUsage(rhi::BufferUsage::CopyDest)
                                        .setMemory(rhi::MemoryType::Readback).setDebugName(name));
    };
    CAUSTICS_TRY(r->statsReadback_, readback(kStatCount * 4, "bench stats readback"));
    CAUSTICS_TRY(r->causticsReadback_, readback(uint64_t(width) * height * 16, "bench caustics readback"));
    r->stats_.assign(kStatCount, 0);
    return r;
}

Status BenchFrames::render(const scene::Camera& camera, uint32_t frameIndex, bool readCaustics) {
    graph_.reset();
    FrameInputs in;
    in.camera = cameraViewMatrices(camera, width_, height_);
    in.width = width_;
    in.height = height_;
    in.frameIndex = frameIndex;
    in.resetHistory = frameIndex == 0;   // a new measurement restarts the frame count (docs/embedding.md)
    CAUSTICS_TRY(FrameOutputs out, module_->addPasses(graph_, in));
    graph_.markOutput(out.display);
    const bool caustics = readCaustics && out.caustics.valid();
    if (caustics) graph_.markOutput(out.caustics, rhi::ResourceState::CopySource);
    if (out.causticStats.valid()) graph_.markOutput(out.causticStats, rhi::ResourceState::CopySource);
    cmd_->begin();
    CAUSTICS_CHECK(graph_.execute(*device_, *cmd_));
    if (caustics) cmd_->copyTextureToBuffer(causticsReadback_, 0, graph_.texture(out.caustics));
    if (out.causticStats.valid()) cmd_->copyBuffer(statsReadback_, 0, graph_.buffer(out.causticStats), 0, kStatCount * 4);
    cmd_->end();
    CAUSTICS_TRY(uint64_t fence, device_->submit(cmd_));
    CAUSTICS_CHECK(device_->waitForFence(fence));
    graph_.collectTimings(*device_);
    stats_.assign(kStatCount, 0);
    if (out.causticStats.valid()) CAUSTICS_CHECK(device_->readBuffer(statsReadback_, stats_.data(), kStatCount * 4));
    if (caustics) {
        caustics_.resize(size_t(width_) * height_ * 4);
        CAUSTICS_CHECK(device_->readBuffer(causticsReadback_, caustics_.data(), caustics_.size() * 4));
    } else if (readCaustics) {
        caustics_.assign(size_t(width_) * height_ * 4, 0.0f);   // caustics off: black
    }
    return okStatus();
}

std::vector<TransientMemory> BenchFrames::transients() const {
    std::vector<TransientMemory> list;
    const rg::CompiledPlan* plan = graph_.plan();
    if (!plan) return list;
    const auto& resources = graph_.desc().resources;
    for (uint32_t i = 0; i < resources.size() && i < plan->lifetimes.size(); ++i) {
        const rg::ResourceDecl& r = resources[i];
        if (r.imported || !plan->lifetimes[i].used() || r.name.rfind("caustics.", 0) != 0) continue;
        uint64_t bytes = 0;
        if (r.kind == rg::ResourceKind::Buffer) {
            bytes = plan->bufferDescs[i].byteSize;
        } else if (r.kind == rg::ResourceKind::Texture) {
            const rhi::TextureDesc& t = plan->textureDescs[i];
            bytes = uint64_t(t.width) * t.height * t.arrayLayers * rhi::formatInfo(t.format).bytesPerPixel;
        }
        list.push_back({r.name, bytes});
    }
    return list;
}

uint64_t BenchFrames::transientHeapBytes() const { return graph_.plan() ? graph_.plan()->heapSize : 0; }

}  // namespace caustics::bench
