#include "caustics/caustics_module.h"

#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "../composite/composite_pass.h"
#include "../direct_lighting/direct_lighting_pass.h"
#include "../gbuffer/gbuffer_pass.h"
#include "caustics/caustic_passes.h"
#include "caustics/frame_context.h"

namespace caustics {

struct CausticsModule::Impl {
    rhi::DeviceHandle device;
    const scene::Scene* scene = nullptr;
    const scene::GpuScene* gpuScene = nullptr;
    CausticsSettings settings;
    SceneBindings sceneBindings;
    rhi::BindingLayoutHandle cameraLayout;
    std::array<rhi::BufferHandle, kFramesInFlight> cameraBuffers;
    std::array<rhi::BindingSetHandle, kFramesInFlight> cameraSets;
    std::optional<GBufferPass> gbuffer;
    std::optional<DirectLightingPass> direct;
    std::optional<CompositePass> composite;
    CausticResources caustics;
    bool causticsReady = false;
    std::optional<glm::mat4> lastViewProj;
};

CausticsModule::CausticsModule(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CausticsModule::~CausticsModule() = default;

Result<std::unique_ptr<CausticsModule>> CausticsModule::create(rhi::DeviceHandle device, const scene::Scene& scene,
                                                               const scene::GpuScene& gpuScene,
                                                               const CausticsSettings& settings) {
    if (!device) return makeError("CausticsModule::create: no device");
    CAUSTICS_CHECK(settings.validate());
    auto impl = std::make_unique<Impl>();
    impl->device = device;
    impl->scene = &scene;
    impl->gpuScene = &gpuScene;
    impl->settings = settings;
    rhi::IDevice& dev = *device;
    CAUSTICS_TRY(impl->sceneBindings, SceneBindings::create(dev, gpuScene, scene));

    rhi::BindingLayoutDesc cameraLayout;
    cameraLayout.setVisibility(rhi::ShaderStage::All).add(0, rhi::BindingType::ConstantBuffer);
    CAUSTICS_TRY(impl->cameraLayout, dev.createBindingLayout(cameraLayout));
    for (uint32_t i = 0; i < kFramesInFlight; ++i) {
        CAUSTICS_TRY(impl->cameraBuffers[i], dev.createBuffer(rhi::BufferDesc()
                                                                  .setByteSize(sizeof(CameraConstants))
                                                                  .setUsage(rhi::BufferUsage::Constant)
                                                                  .setMemory(rhi::MemoryType::Upload)
                                                                  .setDebugName("camera constants")));
        CAUSTICS_TRY(impl->cameraSets[i],
                     dev.createBindingSet(rhi::BindingSetDesc().add(rhi::BindingSetItem::constantBuffer(0, impl->cameraBuffers[i])),
                                          impl->cameraLayout));
    }
    CAUSTICS_TRY(impl->gbuffer, GBufferPass::create(dev, impl->sceneBindings.layout, impl->cameraLayout));
    CAUSTICS_TRY(impl->direct, DirectLightingPass::create(dev, impl->sceneBindings.layout, impl->cameraLayout));
    CAUSTICS_TRY(impl->composite, CompositePass::create(dev));
    return std::unique_ptr<CausticsModule>(new CausticsModule(std::move(impl)));
}

const CausticsSettings& CausticsModule::settings() const { return impl_->settings; }

Status CausticsModule::setSettings(const CausticsSettings& settings) {
    CAUSTICS_CHECK(settings.validate());
    impl_->settings = settings;
    return okStatus();
}

namespace {
CompositeAov compositeAov(CausticsAov aov) {
    switch (aov) {
        case CausticsAov::Final: return CompositeAov::Final;
        case CausticsAov::Direct: return CompositeAov::Direct;
        case CausticsAov::Caustics:
        case CausticsAov::FirstType:
        case CausticsAov::SecondType: return CompositeAov::Caustics;
        case CausticsAov::Albedo: return CompositeAov::Albedo;
        case CausticsAov::Normal: return CompositeAov::Normal;
        case CausticsAov::Depth: return CompositeAov::Depth;
    }
    return CompositeAov::Final;
}
}  // namespace

Result<FrameOutputs> CausticsModule::addPasses(rg::RenderGraph& graph, const FrameInputs& in) {
    Impl& m = *impl_;
    constexpr uint32_t kMaxSide = 16384;
    if (in.width < 1 || in.height < 1 || in.width > kMaxSide || in.height > kMaxSide)
        return makeError("CausticsModule::addPasses: image size " + std::to_string(in.width) + "x" +
                         std::to_string(in.height) + " is outside [1, 16384]");
    if (!(in.camera.verticalFovRadians > 0.0f && in.camera.verticalFovRadians < 3.1f) ||
        !(in.camera.nearPlane > 0.0f && in.camera.farPlane > in.camera.nearPlane) ||
        glm::length(in.camera.target - in.camera.eye) <= 0.0f)
        return makeError("CausticsModule::addPasses: FrameInputs::camera is degenerate (fov, near/far or eye == target)");

    FrameContext frame;
    frame.device = m.device.get();
    frame.scene = m.scene;
    frame.gpuScene = m.gpuScene;
    frame.sceneBindings = &m.sceneBindings;
    frame.settings = &m.settings;
    frame.width = in.width;
    frame.height = in.height;
    frame.frameIndex = in.frameIndex;
    glm::mat4 prev = m.lastViewProj && !in.resetHistory ? *m.lastViewProj : glm::mat4(1.0f);
    frame.camera = makeCameraConstants(in.camera, in.width, in.height, in.frameIndex,
                                       m.lastViewProj && !in.resetHistory ? &prev : nullptr);
    m.lastViewProj = frame.camera.viewProj;
    uint32_t slot = in.frameIndex % kFramesInFlight;
    frame.cameraBuffer = m.cameraBuffers[slot];
    frame.cameraSet = m.cameraSets[slot];
    frame.cameraLayout = m.cameraLayout;
    // Host-visible memory: the write is visible to the GPU from the next submit on (Vulkan spec 7.9).
    std::memcpy(frame.cameraBuffer->mappedData(), &frame.camera, sizeof(CameraConstants));

    FrameOutputs out;
    if (in.hostGBuffer) {
        const HostGBuffer& h = *in.hostGBuffer;
        if (!h.depth || !h.normalRoughness || !h.albedoMetallic || !h.optics || !h.linearDepth || !h.objectId)
            return makeError("CausticsModule::addPasses: hostGBuffer lacks a texture (all six are required)");
        auto import = [&](const rhi::TextureHandle& t, const char* name, rhi::Format f) -> Result<rg::RgTexture> {
            const rhi::TextureDesc& d = t->desc();
            if (d.format != f || d.width != in.width || d.height != in.height)
                return makeError(std::string("CausticsModule::addPasses: hostGBuffer.") + name + " is " +
                                 rhi::formatInfo(d.format).name + " " + std::to_string(d.width) + "x" +
                                 std::to_string(d.height) + ", expected " + rhi::formatInfo(f).name + " " +
                                 std::to_string(in.width) + "x" + std::to_string(in.height));
            return graph.importTexture(std::string("host.") + name, t, h.state, h.state);
        };
        CAUSTICS_TRY(out.gbuffer.depth, import(h.depth, "depth", GBufferFormats::kDepth));
        CAUSTICS_TRY(out.gbuffer.normalRoughness, import(h.normalRoughness, "normalRoughness", GBufferFormats::kNormalRoughness));
        CAUSTICS_TRY(out.gbuffer.albedoMetallic, import(h.albedoMetallic, "albedoMetallic", GBufferFormats::kAlbedoMetallic));
        CAUSTICS_TRY(out.gbuffer.optics, import(h.optics, "optics", GBufferFormats::kOptics));
        CAUSTICS_TRY(out.gbuffer.linearDepth, import(h.linearDepth, "linearDepth", GBufferFormats::kLinearDepth));
        CAUSTICS_TRY(out.gbuffer.objectId, import(h.objectId, "objectId", GBufferFormats::kObjectId));
        out.gbuffer.width = in.width;
        out.gbuffer.height = in.height;
    } else {
        out.gbuffer = m.gbuffer->addToGraph(graph, frame);
    }

    out.direct = m.direct->addToGraph(graph, frame, out.gbuffer);

    // Caustics: skipped when switched off or when there is no light (nothing can form them).
    if (m.settings.causticsEnabled && !m.scene->lights.empty()) {
        if (!m.causticsReady) {
            CAUSTICS_TRY(m.caustics, CausticResources::create(*m.device));
            m.causticsReady = true;
        }
        CausticFrameInputs ci;
        ci.device = m.device.get();
        ci.scene = m.scene;
        ci.gpuScene = m.gpuScene;
        ci.sceneBindings = &m.sceneBindings;
        ci.gbuffer = out.gbuffer;
        ci.camera = frame.camera;
        ci.settings = m.settings;
        ci.frameIndex = in.frameIndex;
        ci.resetHistory = in.resetHistory;
        CAUSTICS_TRY(CausticOutputs co, addCausticPasses(graph, m.caustics, ci));
        out.caustics = co.radiance;
        out.firstType = co.firstType;
        out.secondType = co.secondType;
        out.causticStats = co.stats;
    }

    CompositeParams params;
    params.aov = compositeAov(m.settings.aov);
    params.exposure = m.settings.exposure * m.scene->exposure;
    params.depthRange = std::max(1.0f, std::min(in.camera.farPlane, 50.0f));
    if (in.outputTarget) {
        if (in.outputTarget->desc().format != rhi::Format::RGBA8_UNORM ||
            in.outputTarget->desc().width != in.width || in.outputTarget->desc().height != in.height)
            return makeError("CausticsModule::addPasses: outputTarget must be RGBA8_UNORM of the image size");
        params.display = graph.importTexture("output", in.outputTarget, in.outputState, in.outputState);
    }
    rg::RgTexture shownCaustics = out.caustics;
    if (m.settings.aov == CausticsAov::FirstType && out.firstType.valid()) shownCaustics = out.firstType;
    if (m.settings.aov == CausticsAov::SecondType && out.secondType.valid()) shownCaustics = out.secondType;
    CompositeOutputs co = m.composite->addToGraph(graph, out.gbuffer, out.direct, shownCaustics, params);
    out.display = co.display;
    out.hdr = co.hdr;
    return out;
}

}  // namespace caustics
