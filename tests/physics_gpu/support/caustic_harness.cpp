#include "caustic_harness.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <glm/gtc/packing.hpp>

#include "caustics/frame_context.h"
#include "caustics/scene_bindings.h"
#include "gbuffer/gbuffer_pass.h"
#include "caustics/scene/gpu_scene.h"

namespace caustics::test {
namespace {

using namespace caustics::rhi;

Result<BufferHandle> readbackBuffer(IDevice& d, uint64_t bytes) {
    return d.createBuffer(BufferDesc().setByteSize(std::max<uint64_t>(bytes, 4)).setUsage(BufferUsage::CopyDest)
                              .setMemory(MemoryType::Readback).setDebugName("harness readback"));
}

template <typename T>
std::vector<T> fetch(IDevice& d, const BufferHandle& b, size_t count) {
    std::vector<T> v(count);
    if (count && !d.readBuffer(b, v.data(), count * sizeof(T))) v.clear();
    return v;
}

std::vector<glm::vec3> rgb(const std::vector<glm::vec4>& v) {
    std::vector<glm::vec3> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) out[i] = glm::vec3(v[i]);
    return out;
}

// List-ordered texels (one per entry of `list`, which names each entry's pixel) as a screen image;
// `none` where no entry names the pixel.
template <typename T>
std::vector<T> toScreen(const std::vector<T>& entries, const std::vector<uint32_t>& list, uint64_t pixels, T none) {
    std::vector<T> screen(pixels, none);
    if (entries.empty()) return {};
    for (size_t i = 0; i < list.size() && i < entries.size(); ++i)
        if (list[i] < pixels) screen[list[i]] = entries[i];
    return screen;
}

}  // namespace

Result<CausticRun> runCaustics(IDevice& device, const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                               uint32_t height, const CausticsSettings& settings, uint32_t frames, bool separateTypes) {
    const std::vector<scene::Camera> cameras(std::max(frames, 1u), camera);
    return runCaustics(device, scene, cameras, width, height, settings, 3, {}, separateTypes);
}

Result<CausticRun> runCaustics(IDevice& device, const scene::Scene& scene, std::span<const scene::Camera> cameras,
                               uint32_t width, uint32_t height, const CausticsSettings& settings,
                               uint32_t framesInFlight, std::span<const std::vector<scene::Light>> lightsPerFrame,
                               bool separateTypes) {
    const uint32_t frames = uint32_t(cameras.size());
    if (!lightsPerFrame.empty() && lightsPerFrame.size() != cameras.size())
        return makeError("runCaustics: " + std::to_string(lightsPerFrame.size()) + " light lists for " +
                         std::to_string(cameras.size()) + " cameras");
    scene::Scene lit = scene;   // the frame's lights; the caustic passes read them from the CPU scene
    CAUSTICS_TRY(scene::GpuScene gpuScene, scene::GpuScene::create(device, scene));
    CAUSTICS_TRY(SceneBindings bindings, SceneBindings::create(device, gpuScene, scene));
    BindingLayoutDesc cl;
    cl.setVisibility(ShaderStage::All).add(0, BindingType::ConstantBuffer);
    CAUSTICS_TRY(BindingLayoutHandle cameraLayout, device.createBindingLayout(cl));
    CAUSTICS_TRY(BufferHandle cameraBuffer, device.createBuffer(BufferDesc().setByteSize(sizeof(CameraConstants))
                                                                    .setUsage(BufferUsage::Constant)
                                                                    .setMemory(MemoryType::Upload)));
    CAUSTICS_TRY(BindingSetHandle cameraSet,
                 device.createBindingSet(BindingSetDesc().add(BindingSetItem::constantBuffer(0, cameraBuffer)), cameraLayout));
    CAUSTICS_TRY(GBufferPass gbufferPass, GBufferPass::create(device, bindings.layout, cameraLayout));
    CAUSTICS_TRY(CausticResources resources, CausticResources::create(device, framesInFlight));

    CausticRun run;
    run.width = width;
    run.height = height;
    const uint64_t pixels = uint64_t(width) * height;
    rg::RenderGraph graph;
    glm::mat4 prevViewProj(1.0f);
    for (uint32_t frame = 0; frame < frames; ++frame) {
        graph.reset();
        if (!lightsPerFrame.empty()) lit.lights = lightsPerFrame[frame];
        FrameContext fc;
        fc.device = &device;
        fc.scene = &lit;
        fc.gpuScene = &gpuScene;
        fc.sceneBindings = &bindings;
        fc.settings = &settings;
        CAUSTICS_TRY(fc.camera, makeCameraConstants(cameras[frame], width, height, frame, frame ? &prevViewProj : nullptr));
        prevViewProj = fc.camera.viewProj;
        std::memcpy(cameraBuffer->mappedData(), &fc.camera, sizeof(CameraConstants));
        fc.cameraBuffer = cameraBuffer;
        fc.cameraLayout = cameraLayout;
        fc.cameraSet = cameraSet;
        fc.width = width;
        fc.height = height;
        fc.frameIndex = frame;
        GBuffer g = gbufferPass.addToGraph(graph, fc);
        CausticFrameInputs in;
        in.device = &device;
        in.scene = &lit;
        in.gpuScene = &gpuScene;
        in.sceneBindings = &bindings;
        in.gbuffer = g;
        in.camera = fc.camera;
        in.settings = settings;
        in.frameIndex = frame;
        in.separateTypes = separateTypes;
        CAUSTICS_TRY(CausticOutputs out, addCausticPasses(graph, resources, in));
        const bool last = frame + 1 == frames;
        if (last) {
            for (rg::RgTexture t : {out.firstType, out.secondType, out.radiance, g.linearDepth, g.objectId})
                if (t.valid()) graph.markOutput(t, ResourceState::CopySource);
            if (out.secondTypeListOrder) graph.markOutput(out.specularPixels, ResourceState::CopySource);
            graph.markOutput(out.stats, ResourceState::CopySource);
            if (out.hits.valid()) graph.markOutput(out.hits, ResourceState::CopySource);
            if (out.spheres.valid()) graph.markOutput(out.spheres, ResourceState::CopySource);
            if (out.layerPlans.valid()) graph.markOutput(out.layerPlans, ResourceState::CopySource);
            if (out.filterTiles.valid()) graph.markOutput(out.filterTiles, ResourceState::CopySource);
            if (out.secondTypeGuides.valid())
                for (rg::RgTexture t : {out.secondTypeGuides.depthMotion, out.secondTypeGuides.normal, out.secondTypeGuides.objectId})
                    graph.markOutput(t, ResourceState::CopySource);
        } else {
            graph.markOutput(out.radiance);
        }
        CAUSTICS_TRY(CommandListHandle cmd, device.createCommandList());
        cmd->begin();
        CAUSTICS_CHECK(graph.execute(device, *cmd));
        cmd->end();
        CAUSTICS_TRY(uint64_t fence, device.submit(cmd));
        CAUSTICS_CHECK(device.waitForFence(fence));
        if (!last) continue;

        // Read back everything the tests look at.
        // The second type's images: one texel per pixel, or per list entry (list order).
        const uint64_t secondTexels = out.secondType.valid() ? uint64_t(graph.texture(out.secondType)->desc().width) *
                                                                   graph.texture(out.secondType)->desc().height
                                                             : pixels;
        const uint64_t listBytes = out.secondTypeListOrder ? graph.buffer(out.specularPixels)->desc().byteSize : 4;
        CAUSTICS_TRY(BufferHandle rbFirst, readbackBuffer(device, pixels * 16));
        CAUSTICS_TRY(BufferHandle rbSecond, readbackBuffer(device, secondTexels * 16));
        CAUSTICS_TRY(BufferHandle rbList, readbackBuffer(device, listBytes));
        CAUSTICS_TRY(BufferHandle rbRadiance, readbackBuffer(device, pixels * 16));
        CAUSTICS_TRY(BufferHandle rbDepth, readbackBuffer(device, pixels * 4));
        CAUSTICS_TRY(BufferHandle rbId, readbackBuffer(device, pixels * 4));
        CAUSTICS_TRY(BufferHandle rbStats, readbackBuffer(device, kStatCount * 4));
        // The hit and sphere buffers are sized by the frame's work (docs/caustics.md, "Memory"): whole.
        const uint64_t hitBytes = out.hits.valid() ? graph.buffer(out.hits)->desc().byteSize : 4;
        const uint64_t sphereBytes = out.spheres.valid() ? graph.buffer(out.spheres)->desc().byteSize : 4;
        CAUSTICS_TRY(BufferHandle rbHits, readbackBuffer(device, hitBytes));
        CAUSTICS_TRY(BufferHandle rbSpheres, readbackBuffer(device, sphereBytes));
        const uint64_t planBytes = std::max<uint64_t>(out.plan.maps.size(), 1) * sizeof(CausticLayerPlanGpu);
        CAUSTICS_TRY(BufferHandle rbPlans, readbackBuffer(device, planBytes));
        CAUSTICS_TRY(BufferHandle rbTiles, readbackBuffer(device, 4));
        const SecondTypeGuides& guides = out.secondTypeGuides;
        CAUSTICS_TRY(BufferHandle rbGuideDepth, readbackBuffer(device, secondTexels * 8));
        CAUSTICS_TRY(BufferHandle rbGuideNormal, readbackBuffer(device, secondTexels * 8));
        CAUSTICS_TRY(BufferHandle rbGuideId, readbackBuffer(device, secondTexels * 4));
        CAUSTICS_TRY(CommandListHandle copy, device.createCommandList());
        copy->begin();
        if (out.firstType.valid()) copy->copyTextureToBuffer(rbFirst, 0, graph.texture(out.firstType));
        if (out.secondType.valid()) copy->copyTextureToBuffer(rbSecond, 0, graph.texture(out.secondType));
        if (out.secondTypeListOrder) copy->copyBuffer(rbList, 0, graph.buffer(out.specularPixels), 0, listBytes);
        copy->copyTextureToBuffer(rbRadiance, 0, graph.texture(out.radiance));
        copy->copyTextureToBuffer(rbDepth, 0, graph.texture(g.linearDepth));
        copy->copyTextureToBuffer(rbId, 0, graph.texture(g.objectId));
        copy->copyBuffer(rbStats, 0, graph.buffer(out.stats), 0, kStatCount * 4);
        if (out.hits.valid()) copy->copyBuffer(rbHits, 0, graph.buffer(out.hits), 0, hitBytes);
        if (out.spheres.valid()) copy->copyBuffer(rbSpheres, 0, graph.buffer(out.spheres), 0, sphereBytes);
        if (out.layerPlans.valid()) copy->copyBuffer(rbPlans, 0, graph.buffer(out.layerPlans), 0, planBytes);
        if (out.filterTiles.valid()) copy->copyBuffer(rbTiles, 0, graph.buffer(out.filterTiles), 0, 4);
        if (guides.valid()) {
            copy->copyTextureToBuffer(rbGuideDepth, 0, graph.texture(guides.depthMotion));
            copy->copyTextureToBuffer(rbGuideNormal, 0, graph.texture(guides.normal));
            copy->copyTextureToBuffer(rbGuideId, 0, graph.texture(guides.objectId));
        }
        copy->end();
        CAUSTICS_TRY(uint64_t copyFence, device.submit(copy));
        CAUSTICS_CHECK(device.waitForFence(copyFence));
        if (out.firstType.valid()) run.firstType = rgb(fetch<glm::vec4>(device, rbFirst, pixels));
        if (out.secondType.valid()) run.secondType = rgb(fetch<glm::vec4>(device, rbSecond, secondTexels));
        run.radiance = rgb(fetch<glm::vec4>(device, rbRadiance, pixels));
        run.linearDepth = fetch<float>(device, rbDepth, pixels);
        run.objectId = fetch<uint32_t>(device, rbId, pixels);
        run.stats = fetch<uint32_t>(device, rbStats, kStatCount);
        if (out.hits.valid())
            run.hits = fetch<CausticHit>(device, rbHits, std::min<uint64_t>(run.stats[kStatStoredHitAttempts], hitBytes / sizeof(CausticHit)));
        // The backward pass appends: the first min(spheres, capacity) entries are this frame's.
        if (out.spheres.valid())
            run.spheres = fetch<CausticSphere>(device, rbSpheres, std::min(run.stats[kStatSpheres], run.stats[kStatSphereCapacity]));
        if (out.filterTiles.valid()) run.filterTiles = fetch<uint32_t>(device, rbTiles, 1).at(0);
        if (guides.valid()) {
            for (const glm::uvec2& h : fetch<glm::uvec2>(device, rbGuideDepth, secondTexels))   // RGBA16F
                run.guideDepthMotion.push_back(glm::vec4(glm::unpackHalf2x16(h.x), glm::unpackHalf2x16(h.y)));
            for (const glm::uvec2& h : fetch<glm::uvec2>(device, rbGuideNormal, secondTexels))
                run.guideNormal.push_back(glm::vec4(glm::unpackHalf2x16(h.x), glm::unpackHalf2x16(h.y)));
            run.guideObjectId = fetch<uint32_t>(device, rbGuideId, secondTexels);
        }
        run.secondTypeListOrder = out.secondTypeListOrder;
        if (out.secondTypeListOrder) {
            // Entry i (texel i of the list-ordered images) belongs to pixel list[i]; the listed entries are
            // the first min(specular pixels, capacity) (common/specular_list.h).
            const uint32_t listed = std::min(run.stats[kStatSpecularPixels], run.stats[kStatSphereCapacity]);
            const std::vector<uint32_t> list = fetch<uint32_t>(device, rbList, listed);
            run.secondType = toScreen(run.secondType, list, pixels, glm::vec3(0.0f));
            run.guideDepthMotion = toScreen(run.guideDepthMotion, list, pixels, glm::vec4(0.0f));
            run.guideNormal = toScreen(run.guideNormal, list, pixels, glm::vec4(0.0f));
            run.guideObjectId = toScreen(run.guideObjectId, list, pixels, 0u);
        }
        run.plan = out.plan;
        if (out.layerPlans.valid()) run.layerPlans = fetch<CausticLayerPlanGpu>(device, rbPlans, out.plan.maps.size());
    }
    CAUSTICS_CHECK(device.waitIdle());
    return run;
}

}  // namespace caustics::test
