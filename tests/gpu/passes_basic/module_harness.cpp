#include "module_harness.h"

#include <cmath>
#include <cstring>

#include "caustics/render_graph/render_graph.h"

namespace caustics::test {

float halfToFloat(uint16_t h) {
    uint32_t sign = (h >> 15) & 1u, exponent = (h >> 10) & 0x1Fu, mantissa = h & 0x3FFu;
    float value;
    if (exponent == 0) value = std::ldexp(float(mantissa), -24);
    else if (exponent == 31) value = mantissa ? NAN : INFINITY;
    else value = std::ldexp(float(mantissa | 0x400u), int(exponent) - 25);
    return sign ? -value : value;
}

Result<RenderedFrame> renderFrame(const rhi::DeviceHandle& device, const scene::Scene& scene,
                                  const CausticsSettings& settings, const scene::Camera& camera, uint32_t width,
                                  uint32_t height) {
    CAUSTICS_TRY(scene::GpuScene gpuScene, scene::GpuScene::create(*device, scene));
    CAUSTICS_TRY(std::unique_ptr<CausticsModule> module, CausticsModule::create(device, scene, gpuScene, settings));
    rg::RenderGraph graph;
    FrameInputs in;
    in.camera = cameraViewMatrices(camera, width, height);
    in.width = width;
    in.height = height;
    CAUSTICS_TRY(FrameOutputs out, module->addPasses(graph, in));
    graph.markOutput(out.hdr, rhi::ResourceState::CopySource);
    graph.markOutput(out.gbuffer.objectId, rhi::ResourceState::CopySource);
    graph.markOutput(out.gbuffer.linearDepth, rhi::ResourceState::CopySource);
    graph.markOutput(out.gbuffer.normalRoughness, rhi::ResourceState::CopySource);

    uint64_t pixels = uint64_t(width) * height;
    auto readback = [&](uint64_t bytes) {
        return device->createBuffer(rhi::BufferDesc().setByteSize(bytes).setUsage(rhi::BufferUsage::CopyDest)
                                        .setMemory(rhi::MemoryType::Readback));
    };
    CAUSTICS_TRY(rhi::BufferHandle hdrBuf, readback(pixels * 16));
    CAUSTICS_TRY(rhi::BufferHandle idBuf, readback(pixels * 4));
    CAUSTICS_TRY(rhi::BufferHandle depthBuf, readback(pixels * 4));
    CAUSTICS_TRY(rhi::BufferHandle normalBuf, readback(pixels * 8));
    CAUSTICS_TRY(rhi::CommandListHandle cmd, device->createCommandList());
    cmd->begin();
    CAUSTICS_CHECK(graph.execute(*device, *cmd));
    cmd->copyTextureToBuffer(hdrBuf, 0, graph.texture(out.hdr));
    cmd->copyTextureToBuffer(idBuf, 0, graph.texture(out.gbuffer.objectId));
    cmd->copyTextureToBuffer(depthBuf, 0, graph.texture(out.gbuffer.linearDepth));
    cmd->copyTextureToBuffer(normalBuf, 0, graph.texture(out.gbuffer.normalRoughness));
    cmd->end();
    CAUSTICS_TRY(uint64_t fence, device->submit(cmd));
    CAUSTICS_CHECK(device->waitForFence(fence));

    RenderedFrame f;
    f.width = width;
    f.height = height;
    f.hdr.resize(pixels * 4);
    f.objectId.resize(pixels);
    f.linearDepth.resize(pixels);
    std::vector<uint16_t> halves(pixels * 4);
    CAUSTICS_CHECK(device->readBuffer(hdrBuf, f.hdr.data(), pixels * 16));
    CAUSTICS_CHECK(device->readBuffer(idBuf, f.objectId.data(), pixels * 4));
    CAUSTICS_CHECK(device->readBuffer(depthBuf, f.linearDepth.data(), pixels * 4));
    CAUSTICS_CHECK(device->readBuffer(normalBuf, halves.data(), pixels * 8));
    f.normalRoughness.resize(pixels * 4);
    for (size_t i = 0; i < halves.size(); ++i) f.normalRoughness[i] = halfToFloat(halves[i]);
    return f;
}

}  // namespace caustics::test
