#include "host_engine.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <iterator>

#include "caustics/rhi/vulkan_interop.h"
#include "host_gbuffer_compute.h"
#include "host_ray_tracing_scene.h"
#include "raw_vulkan_host.h"

namespace caustics::test {

CausticsSettings hostEngineSettings(uint32_t seed, bool causticsOnly) {
    CausticsSettings s;
    s.mapResolution = 64;
    s.raysPerTexel = 4.0f;
    s.filter = false;
    s.secondType = true;   // the backward pass starts at the host's optics.w = 1 pixels
    s.maxStoredHits = 1u << 14;
    s.causticsOnly = causticsOnly;
    s.seed = seed;
    return s;
}

namespace {

constexpr uint32_t kSize = kHostImageSize;

// ---- The host integration (README "Embedding it in an engine" counts these lines) ---------------
struct EmbeddedCaustics {
    rhi::DeviceHandle device;
    std::unique_ptr<scene::GpuScene> gpuScene;
    std::unique_ptr<CausticsModule> module;
    HostGBuffer gbuffer;
    rhi::TextureHandle output;
};

Result<EmbeddedCaustics> embedCaustics(const RawVulkanHost& host, const HostGBufferCompute& gb, VkImage output,
                                       const scene::Scene& scene, const CausticsSettings& settings, bool hostTlas) {
    EmbeddedCaustics e;
    CAUSTICS_TRY(e.device, rhi::wrapVulkanDevice(host.deviceImport()));
    rhi::TextureHandle* targets[] = {&e.gbuffer.normalRoughness, &e.gbuffer.albedoMetallic, &e.gbuffer.optics,
                                     &e.gbuffer.linearDepth, &e.gbuffer.objectId};
    for (int c = 0; c < HostGBufferCompute::kChannelCount; ++c) {
        const rhi::VulkanTextureImport channel{.image = gb.images[c].image, .format = HostGBufferCompute::kFormats[c],
            .usage = HostGBufferCompute::kUsage, .width = kSize, .height = kSize, .debugName = "host gbuffer"};
        CAUSTICS_TRY(*targets[c], rhi::importVulkanTexture(*e.device, channel));
    }
    CAUSTICS_TRY(e.gbuffer.state, rhi::resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    const rhi::VulkanTextureImport target{.image = output, .format = VK_FORMAT_R32G32B32A32_SFLOAT,
        .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, .width = kSize, .height = kSize,
        .uses = rhi::TextureUsage::CopyDest, .debugName = "host output"};
    CAUSTICS_TRY(e.output, rhi::importVulkanTexture(*e.device, target));
    // With the host's TLAS and tables the module needs no BLAS and no geometry of its own (docs/embedding.md).
    CAUSTICS_TRY(scene::GpuScene gpuScene,
                 scene::GpuScene::create(*e.device, scene, {.buildAccelStructs = !hostTlas, .uploadGeometry = !hostTlas}));
    e.gpuScene = std::make_unique<scene::GpuScene>(std::move(gpuScene));
    CAUSTICS_TRY(e.module, CausticsModule::create(e.device, scene, *e.gpuScene, settings));
    return e;
}

// Records the module into the host's begun command buffer: the caustic radiance ends in the host's
// output image (TRANSFER_DST_OPTIMAL before, TRANSFER_SRC_OPTIMAL after). Returns what the host's
// vkQueueSubmit must signal.
Result<rhi::VulkanSubmitSignal> recordCaustics(EmbeddedCaustics& e, rg::RenderGraph& graph, rhi::CommandListHandle& list,
                                               VkCommandBuffer cmd, const CameraView& camera,
                                               const HostSceneTables& hostScene) {
    CAUSTICS_TRY(list, rhi::wrapVulkanCommandBuffer(*e.device, {.commandBuffer = cmd}));
    const FrameInputs inputs{.camera = camera, .width = kSize, .height = kSize, .hostGBuffer = e.gbuffer,
                             .hostScene = hostScene};
    CAUSTICS_TRY(FrameOutputs out, e.module->addPasses(graph, inputs));
    rg::RgTexture output = graph.importTexture("host output", e.output, rhi::ResourceState::CopyDest,
                                               rhi::ResourceState::CopySource);
    graph.addPass("host.copy_caustics", [&](rg::PassBuilder& b) {
        rg::RgTexture src = b.read(out.caustics, rg::Access::CopySource), dst = b.write(output, rg::Access::CopyDest);
        const rhi::TextureRegion all = rhi::TextureRegion().setSize(kSize, kSize);
        return [=](rg::PassContext& ctx) { ctx.cmd().copyTexture(ctx.texture(dst), all, ctx.texture(src), all); };
    });
    graph.markOutput(output, rhi::ResourceState::CopySource);
    CAUSTICS_CHECK(graph.execute(*e.device, *list));
    return rhi::vulkanSubmitSignal(*e.device, *list);
}
// ---- end of the host integration ------------------------------------------------------------------

// The host's own TLAS and tables, imported by their native handles (docs/embedding.md "Host scene tables").
Result<HostSceneTables> importHostScene(rhi::IDevice& device, const HostRayTracingScene& rt) {
    HostSceneTables t;
    CAUSTICS_TRY(t.tlas, rhi::importVulkanAccelStruct(device, {.accelStruct = rt.tlas, .debugName = "host TLAS"}));
    const std::pair<rhi::BufferHandle*, std::pair<const RawBuffer*, VkDeviceSize>> tables[] = {
        {&t.positions, {&rt.positions, rt.positionBytes}}, {&t.vertices, {&rt.vertices, rt.vertexBytes}},
        {&t.indices, {&rt.indices, rt.indexBytes}},       {&t.materials, {&rt.materials, rt.materialBytes}},
        {&t.instances, {&rt.instances, rt.instanceBytes}}};
    t.instanceRows = rt.instanceRows;
    const char* names[] = {"host positions", "host vertices", "host indices", "host materials", "host instances"};
    for (size_t i = 0; i < std::size(tables); ++i) {
        const auto& [handle, raw] = tables[i];
        CAUSTICS_TRY(*handle, rhi::importVulkanBuffer(device, {.buffer = raw.first->buffer, .byteSize = raw.second,
                                                               .usage = HostRayTracingScene::kTableUsage,
                                                               .debugName = names[i]}));
    }
    return t;
}

// Everything the engine owns for one frame; destroyed by the caller whatever the module did.
struct HostResources {
    HostGBufferCompute gbuffer;
    HostRayTracingScene rayTracing;
    RawImage output;
    RawBuffer readback, idBack, depthBack;
    RawBuffer objectIdMap;   // (hostId, moduleId) pairs, sorted by hostId
};

// The host's id of instance row k is kSparseIdBase + kSparseIdStride * k; the module's is k + 1.
RawBuffer writeObjectIdMap(RawVulkanHost& host, size_t instanceCount) {
    std::vector<std::array<uint32_t, 2>> pairs;
    for (uint32_t k = 0; k < instanceCount; ++k) pairs.push_back({kSparseIdBase + kSparseIdStride * k, k + 1});
    RawBuffer b = host.createHostBuffer(pairs.size() * 8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (b.mapped) std::memcpy(b.mapped, pairs.data(), pairs.size() * 8);
    return b;
}

// The module's part of the frame, recorded between the host's G-buffer and its readback copies.
Result<HostEngineFrame> renderFrame(RawVulkanHost& host, HostResources& r, const scene::Scene& scene,
                                    const CameraView& camera, uint32_t seed, const HostEngineOptions& options) {
    CAUSTICS_TRY(EmbeddedCaustics embedded, embedCaustics(host, r.gbuffer, r.output.image, scene,
                                                          hostEngineSettings(seed, true), options.ownSceneTables));
    if (options.objectIdMap) {
        CAUSTICS_TRY(embedded.gbuffer.objectIdMap,
                     rhi::importVulkanBuffer(*embedded.device, {.buffer = r.objectIdMap.buffer,
                                                                .byteSize = scene.instances.size() * 8,
                                                                .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                                .debugName = "host object id map"}));
        embedded.gbuffer.objectIdMapCount = uint32_t(scene.instances.size());
    }
    HostSceneTables hostScene;
    if (options.ownSceneTables) {
        CAUSTICS_TRY(hostScene, importHostScene(*embedded.device, r.rayTracing));
    }
    rg::RenderGraph graph;
    rhi::CommandListHandle list;
    host.begin();
    r.gbuffer.record(camera);
    if (options.ownSceneTables) r.rayTracing.recordBuilds();
    if (options.materialsWrittenInCommandBuffer) {
        r.rayTracing.recordMaterialUpload();
        hostScene.tablesState = rhi::ResourceState::CopyDest;
    }
    host.imageBarrier(r.output.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    auto signal = recordCaustics(embedded, graph, list, host.commandBuffer, camera, hostScene);
    if (!signal) {
        vkEndCommandBuffer(host.commandBuffer);   // recorded, never submitted
        return makeError(signal.message());
    }
    // The engine reads its output image back with raw Vulkan.
    host.imageBarrier(r.output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    const VkBufferImageCopy region{0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {0, 0, 0}, {kSize, kSize, 1}};
    vkCmdCopyImageToBuffer(host.commandBuffer, r.output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.readback.buffer, 1,
                           &region);
    for (auto [channel, buffer] : {std::pair{HostGBufferCompute::ObjectId, r.idBack.buffer},
                                   std::pair{HostGBufferCompute::LinearDepth, r.depthBack.buffer}}) {
        const VkImage gbufferImage = r.gbuffer.images[channel].image;
        host.imageBarrier(gbufferImage, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkCmdCopyImageToBuffer(host.commandBuffer, gbufferImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    }
    host.memoryBarrier(VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                       VK_ACCESS_2_HOST_READ_BIT);
    if (!host.endSubmitAndWait(&signal.value())) return makeError("raw host: submit failed");

    const size_t pixels = size_t(kSize) * kSize;
    HostEngineFrame frame{{kSize, kSize, std::vector<glm::vec3>(pixels)}, {}};
    const auto* rgba = static_cast<const glm::vec4*>(r.readback.mapped);
    for (size_t i = 0; i < pixels; ++i) frame.caustics.pixels[i] = glm::vec3(rgba[i]);
    const auto* ids = static_cast<const uint32_t*>(r.idBack.mapped);
    const auto* depths = static_cast<const float*>(r.depthBack.mapped);
    frame.gbuffer.objectId.assign(ids, ids + pixels);
    frame.gbuffer.linearDepth.assign(depths, depths + pixels);
    return frame;
}   // the module and the wrapped device go before the engine's device

}  // namespace

Result<HostEngineFrame> hostEngineFrame(const scene::Scene& scene, const CameraView& camera, uint32_t seed,
                                        const HostEngineOptions& options, std::vector<std::string>& messages) {
    RawVulkanHost host;
    if (!host.create(true)) return makeError("raw host: " + host.why());
    HostResources r;
    const uint64_t pixels = uint64_t(kSize) * kSize;
    bool created = r.gbuffer.create(host, scene, kSize, kSize);
    if (options.sparseObjectIds) {
        r.gbuffer.idBase = kSparseIdBase;
        r.gbuffer.idStride = kSparseIdStride;
    }
    if (options.objectIdMap) {
        r.objectIdMap = writeObjectIdMap(host, scene.instances.size());
        created = created && r.objectIdMap.mapped;
    }
    if (options.ownSceneTables)
        created = created && r.rayTracing.create(host, scene, std::min(options.instanceRows, scene.instances.size()),
                                                      options.diffuseAlbedoScale, options.materialsWrittenInCommandBuffer);
    r.output = host.createImage(kSize, kSize, VK_FORMAT_R32G32B32A32_SFLOAT,
                                VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    r.readback = host.createHostBuffer(pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    r.idBack = host.createHostBuffer(pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    r.depthBack = host.createHostBuffer(pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    Result<HostEngineFrame> frame = created ? renderFrame(host, r, scene, camera, seed, options)
                                            : Result<HostEngineFrame>(makeError("raw host: its G-buffer pass or "
                                                                                "acceleration structures failed"));
    r.gbuffer.destroy();
    r.rayTracing.destroy();
    for (RawBuffer* b : {&r.readback, &r.idBack, &r.depthBack, &r.objectIdMap}) host.destroy(*b);
    host.destroy(r.output);
    host.destroyAll();   // leaks of the wrapped device would be reported here
    messages = host.messages();
    return frame;
}

}  // namespace caustics::test
