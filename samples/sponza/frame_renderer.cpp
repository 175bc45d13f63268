#include "frame_renderer.h"

#include "caustics/caustic_passes.h"

#include <cstring>

namespace caustics::sample {

Result<std::unique_ptr<FrameRenderer>> FrameRenderer::create(rhi::DeviceHandle device, CausticsModule& module,
                                                             uint32_t width, uint32_t height) {
    std::unique_ptr<FrameRenderer> r(new FrameRenderer());
    r->device_ = device;
    r->module_ = &module;
    r->images_.width = width;
    r->images_.height = height;
    CAUSTICS_TRY(r->cmd_, device->createCommandList());
    uint64_t pixels = uint64_t(width) * height;
    auto readback = [&](uint64_t bytes, const char* name) {
        return device->createBuffer(rhi::BufferDesc()
                                        .setByteSize(bytes)
                                        .setUsage(rhi::BufferUsage::CopyDest)
                                        .setMemory(rhi::MemoryType::Readback)
                                        .setDebugName(name));
    };
    CAUSTICS_TRY(r->displayReadback_, readback(pixels * 4, "display readback"));
    CAUSTICS_TRY(r->hdrReadback_, readback(pixels * 16, "hdr readback"));
    CAUSTICS_TRY(r->statsReadback_, readback(kStatCount * 4, "caustic stats readback"));
    return r;
}

Status FrameRenderer::render(const scene::Camera& camera, uint32_t frameIndex, bool readBack) {
    graph_.reset();
    FrameInputs in;
    in.camera = cameraViewMatrices(camera, images_.width, images_.height);
    in.width = images_.width;
    in.height = images_.height;
    in.frameIndex = frameIndex;
    CAUSTICS_TRY(FrameOutputs out, module_->addPasses(graph_, in));
    graph_.markOutput(out.display, rhi::ResourceState::CopySource);
    graph_.markOutput(out.hdr, rhi::ResourceState::CopySource);
    if (out.causticStats.valid()) graph_.markOutput(out.causticStats, rhi::ResourceState::CopySource);

    cmd_->begin();
    CAUSTICS_CHECK(graph_.execute(*device_, *cmd_));
    if (readBack) {
        cmd_->copyTextureToBuffer(displayReadback_, 0, graph_.texture(out.display));
        cmd_->copyTextureToBuffer(hdrReadback_, 0, graph_.texture(out.hdr));
    }
    if (out.causticStats.valid()) cmd_->copyBuffer(statsReadback_, 0, graph_.buffer(out.causticStats), 0, kStatCount * 4);
    cmd_->end();
    CAUSTICS_TRY(uint64_t fence, device_->submit(cmd_));
    CAUSTICS_CHECK(device_->waitForFence(fence));
    graph_.collectTimings(*device_);
    stats_.assign(kStatCount, 0u);
    if (out.causticStats.valid()) {
        CAUSTICS_CHECK(device_->readBuffer(statsReadback_, stats_.data(), kStatCount * 4));
        if (!warnedAboutStats_)
            for (const std::string& w : causticStatsWarnings(stats_, module_->settings())) {
                caustics::log(LogLevel::Warning, w);
                warnedAboutStats_ = true;   // once per run, not every frame
            }
    }
    if (readBack) {
        uint64_t pixels = uint64_t(images_.width) * images_.height;
        images_.display.resize(pixels * 4);
        images_.hdr.resize(pixels * 4);
        CAUSTICS_CHECK(device_->readBuffer(displayReadback_, images_.display.data(), pixels * 4));
        CAUSTICS_CHECK(device_->readBuffer(hdrReadback_, images_.hdr.data(), pixels * 16));
    }
    return okStatus();
}

}  // namespace caustics::sample
