#include "caustics/caustics_module.h"
#include "caustics/photon_budget.h"

#include <cmath>
#include <string>

#include "../caustics_output/caustics_output_pass.h"
#include "../composite/composite_pass.h"
#include "../direct_lighting/direct_lighting_pass.h"
#include "../gbuffer/gbuffer_pass.h"
#include "caustics/caustic_passes.h"
#include "caustics/frame_context.h"
#include "caustics_view.h"
#include "host_gbuffer.h"
#include "live_scene.h"
#include "output_target_check.h"

namespace caustics {

struct CausticsModule::Impl {
    rhi::DeviceHandle device;
    const scene::Scene* scene = nullptr;
    const scene::GpuScene* gpuScene = nullptr;
    CausticsSettings settings;
    std::optional<LiveScene> liveScene;
    rhi::BindingLayoutHandle cameraLayout;
    std::shared_ptr<ViewRegistry> views = std::make_shared<ViewRegistry>();
    std::unique_ptr<CausticsView> defaultView;
    std::optional<GBufferPass> gbuffer;
    std::optional<ObjectIdRemapPass> objectIdRemap;
    std::optional<DirectLightingPass> direct;
    std::optional<CompositePass> composite;
    std::optional<CausticsOutputPass> output;   // caustics-only into FrameInputs::outputTarget
    CausticResources caustics;
    bool causticsReady = false;
    // CausticsSettings::causticTimeTargetMs: the steered budget (photon_budget.h).
    std::optional<PhotonBudgetController> photonBudget;
};

CausticsModule::CausticsModule(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CausticsModule::~CausticsModule() = default;

Result<std::unique_ptr<CausticsModule>> CausticsModule::create(rhi::DeviceHandle device, const scene::Scene& scene,
                                                               const scene::GpuScene& gpuScene,
                                                               const CausticsSettings& settings) {
    if (!device) return makeError("CausticsModule::create: no device");
    CAUSTICS_CHECK(settings.validate());
    if (scene.instances.empty())
        return makeError("scene '" + scene.name + "' has no mesh instances: nothing to render or trace");
    auto impl = std::make_unique<Impl>();
    impl->device = device;
    impl->scene = &scene;
    impl->gpuScene = &gpuScene;
    impl->settings = settings;
    rhi::IDevice& dev = *device;
    CAUSTICS_TRY(impl->liveScene, LiveScene::create(dev, gpuScene, settings.framesInFlight));

    rhi::BindingLayoutDesc cameraLayout;
    cameraLayout.setVisibility(rhi::ShaderStage::All).add(0, rhi::BindingType::ConstantBuffer);
    CAUSTICS_TRY(impl->cameraLayout, dev.createBindingLayout(cameraLayout));
    const rhi::BindingLayoutHandle& sceneLayout = impl->liveScene->layout();
    CAUSTICS_TRY(impl->gbuffer, GBufferPass::create(dev, sceneLayout, impl->cameraLayout));
    CAUSTICS_TRY(impl->objectIdRemap, ObjectIdRemapPass::create(dev));
    CAUSTICS_TRY(impl->output, CausticsOutputPass::create(dev));   // its pipelines: per format, on first use
    auto module = std::unique_ptr<CausticsModule>(new CausticsModule(std::move(impl)));
    CAUSTICS_TRY(module->impl_->defaultView, module->createView());
    CAUSTICS_CHECK(module->prepare());
    return module;
}

Status CausticsModule::prepare() {
    Impl& m = *impl_;
    // Shader tables upload, and the sphere BLAS is built, on the host's queue (docs/embedding.md
    // "Threading"): here, never in addPasses.
    if (!m.settings.causticsOnly && !m.direct) {
        CAUSTICS_TRY(m.direct, DirectLightingPass::create(*m.device, m.liveScene->layout(), m.cameraLayout));
        CAUSTICS_TRY(m.composite, CompositePass::create(*m.device));
    }
    if (m.settings.causticsEnabled && !m.causticsReady) {
        CAUSTICS_TRY(m.caustics, CausticResources::create(*m.device, m.settings.framesInFlight));
        CAUSTICS_CHECK(prepareCausticPipelines(m.caustics, m.liveScene->layout()));
        m.causticsReady = true;
    }
    return okStatus();
}

Result<std::unique_ptr<CausticsView>> CausticsModule::createView() {
    CAUSTICS_TRY(auto view, CausticsView::Impl::create(*impl_->device, impl_->cameraLayout,
                                                        impl_->settings.framesInFlight, impl_->views));
    return std::unique_ptr<CausticsView>(new CausticsView(std::move(view)));
}

const CausticsSettings& CausticsModule::settings() const { return impl_->settings; }

std::vector<MemoryEntry> CausticsModule::memoryReport() const {
    std::vector<MemoryEntry> out;
    const scene::GpuScene& gpu = *impl_->gpuScene;
    addMemoryEntry(out, "scene.positions", gpu.positions);
    addMemoryEntry(out, "scene.vertices", gpu.vertices);
    addMemoryEntry(out, "scene.indices", gpu.indices);
    addMemoryEntry(out, "scene.materials", gpu.materials);
    addMemoryEntry(out, "scene.instances", gpu.instances);
    addMemoryEntry(out, "scene.tlas", gpu.tlas);
    // Per-mesh BLASes and per-material textures: one summed entry each (a scene has thousands).
    MemoryEntry blases{"scene.blases (" + std::to_string(gpu.blases.size()) + ")", 0, MemoryKind::Persistent};
    for (const rhi::AccelStructHandle& b : gpu.blases)
        if (b) blases.bytes += b->storageBytes();
    MemoryEntry textures{"scene.textures (" + std::to_string(gpu.textures.size()) + ")", 0, MemoryKind::Persistent};
    for (const rhi::TextureHandle& t : gpu.textures)
        if (t) textures.bytes += textureBytes(t->desc());
    for (const MemoryEntry& e : {blases, textures})
        if (e.bytes > 0) out.push_back(e);
    impl_->liveScene->appendMemory(out);
    appendCausticMemory(impl_->caustics, out);
    for (MemoryEntry& e : memoryReport(*impl_->defaultView)) out.push_back(std::move(e));
    return out;
}

std::vector<MemoryEntry> CausticsModule::memoryReport(const CausticsView& view) const {
    std::vector<MemoryEntry> out;
    const CausticsView::Impl& v = view.impl();
    MemoryEntry cameras{"view.camera_buffers (" + std::to_string(v.cameraBuffers.size()) + ")", 0, MemoryKind::Persistent};
    for (const rhi::BufferHandle& b : v.cameraBuffers)
        if (b) cameras.bytes += b->desc().byteSize;
    if (cameras.bytes > 0) out.push_back(cameras);
    appendHistoryMemory(v.history, "view.history", out);
    return out;
}

Status CausticsModule::setSettings(const CausticsSettings& settings) {
    CAUSTICS_CHECK(settings.validate());
    if (settings.framesInFlight != impl_->settings.framesInFlight)
        return makeError("CausticsModule::setSettings: framesInFlight is fixed at create() (" +
                         std::to_string(impl_->settings.framesInFlight) + "); create a new module to change it");
    impl_->settings = settings;
    return prepare();
}

namespace {
void releaseDestroyedViews(CausticsModule::Impl& m) {
    std::vector<uint64_t> destroyed;
    {
        std::lock_guard lock(m.views->mutex);
        destroyed.swap(m.views->destroyed);
    }
    for (uint64_t id : destroyed)
        if (m.causticsReady) releaseCausticView(m.caustics, id);
}

// The host must read (or mark) one of the frame's images, else the graph culls every pass of the
// module without a word (docs/embedding.md "No silent failure").
void expectSomeOutputRead(rg::RenderGraph& graph, const FrameOutputs& out) {
    const GBuffer& g = out.gbuffer;
    graph.expectConsumer({out.display, out.hdr, out.direct, out.caustics, out.firstType, out.secondType, g.linearDepth,
                          g.objectId, g.normalRoughness, g.albedoMetallic, g.optics, g.depth},
                         "CausticsModule::addPasses (FrameOutputs)");
}

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
    if (m.settings.causticsOnly && !in.hostGBuffer)
        return makeError("CausticsModule::addPasses: settings.causticsOnly needs FrameInputs::hostGBuffer");
    CAUSTICS_CHECK(checkOutputTarget(in, m.settings.causticsOnly));
    if ((m.settings.causticsEnabled && !m.causticsReady) || (!m.settings.causticsOnly && !m.direct))
        return makeError("CausticsModule::addPasses: the settings need pipelines the module has not made (a "
                         "failed prepare()): call prepare() (it records and submits on the host's queue)");
    CausticsView::Impl& view = in.view ? in.view->impl() : m.defaultView->impl();
    const uint32_t slot = in.frameSlot.value_or(in.frameIndex % m.settings.framesInFlight);
    if (slot >= m.settings.framesInFlight)
        return makeError("CausticsModule::addPasses: FrameInputs::frameSlot " + std::to_string(slot) +
                         " is not below settings.framesInFlight " + std::to_string(m.settings.framesInFlight));
    releaseDestroyedViews(m);
    // The previous view-projection is completed when the graph executes (view.begin).
    glm::mat4 proj = in.camera.proj;
    if (in.camera.jitterPixels) {
        if (proj[2][0] != 0.0f || proj[2][1] != 0.0f)
            return makeError("CausticsModule::addPasses: CameraView::jitterPixels is set and proj[2][0], proj[2][1] "
                             "carry a jitter too: give an unjittered proj with jitterPixels, or neither");
        proj = jitterClipMatrix(proj, *in.camera.jitterPixels, in.width, in.height);
    }
    auto camera = makeCameraConstants(in.camera.view, proj, in.width, in.height, in.frameIndex, nullptr);
    if (!camera) return makeError("CausticsModule::addPasses: " + camera.message());
    BeginPassInputs begin{in.camera.prevViewProj, in.camera.jitterPixels.has_value(), in.resetHistory, in.frameIndex};
    std::shared_ptr<const CameraConstants> executedCamera = view.addBeginPass(graph, camera.value(), slot, begin);
    CAUSTICS_TRY(LiveSceneFrame liveScene, m.liveScene->addUpdatePass(graph, *m.scene, slot, in.hostScene));

    FrameContext frame;
    frame.device = m.device.get();
    frame.scene = m.scene;
    frame.gpuScene = m.gpuScene;
    frame.sceneBindings = liveScene.bindings;
    frame.sceneTlas = liveScene.tlas;
    frame.settings = &m.settings;
    frame.width = in.width;
    frame.height = in.height;
    frame.frameIndex = in.frameIndex;
    frame.camera = camera.value();
    frame.cameraBuffer = view.cameraBuffers[slot];
    frame.cameraSet = view.cameraSets[slot];
    frame.cameraLayout = m.cameraLayout;

    FrameOutputs out;
    if (in.hostGBuffer) {
        CAUSTICS_TRY(out.gbuffer, importHostGBuffer(graph, *in.hostGBuffer, in.width, in.height, m.settings,
                                                        *m.objectIdRemap));
    } else {
        out.gbuffer = m.gbuffer->addToGraph(graph, frame);
    }
    if (!m.settings.causticsOnly) out.direct = m.direct->addToGraph(graph, frame, out.gbuffer);

    // Caustics: skipped when switched off or when there is no light (nothing can form them).
    if (m.settings.causticsEnabled && !m.scene->lights.empty()) {
        CausticFrameInputs ci;
        ci.device = m.device.get();
        ci.scene = m.scene;
        ci.gpuScene = m.gpuScene;
        ci.sceneBindings = liveScene.bindings;
        ci.sceneTlas = liveScene.tlas;
        ci.gbuffer = out.gbuffer;
        ci.camera = frame.camera;
        ci.settings = m.settings;
        ci.frameIndex = in.frameIndex;
        ci.frameSlot = slot;
        ci.executedCamera = executedCamera;
        ci.resetHistory = in.resetHistory;
        ci.history = &view.history;
        if (m.settings.causticTimeTargetMs > 0.0f) {
            if (!m.photonBudget) m.photonBudget.emplace(m.settings.photonsPerFrame);
            const rg::PassTimings& t = graph.timings();
            std::optional<CausticTimeSample> sample;
            if (const uint64_t timed = t.samplesAdded("caustics.forward"); timed > 0) {
                sample = CausticTimeSample{timed - 1, t.latestTotalMs("caustics.").value_or(0.0),
                                           t.latestMs("caustics.forward").value_or(0.0) +
                                               t.latestMs("caustics.gather").value_or(0.0)};
            }
            ci.photonsPerFrame = m.photonBudget->update(sample, m.settings.causticTimeTargetMs);
        } else {
            m.photonBudget.reset();
        }
        // Separate first/second-type buffers only for the AOVs that show one (docs/caustics.md "Memory").
        ci.separateTypes = m.settings.aov == CausticsAov::FirstType || m.settings.aov == CausticsAov::SecondType;
        CAUSTICS_TRY(CausticOutputs co, addCausticPasses(graph, m.caustics, ci));
        if (m.photonBudget && !co.plan.maps.empty()) m.photonBudget->planFrame();   // this frame has a forward pass
        out.caustics = co.radiance;
        out.firstType = co.firstType;
        // In list order (the second type filtered apart without an AOV) the module's second-type image is
        // not a screen image: not handed out (docs/caustics.md "Second-type memory").
        out.secondType = co.secondTypeListOrder ? rg::RgTexture{} : co.secondType;
        out.causticStats = co.stats;
    }
    rg::RgTexture shownCaustics = out.caustics;
    if (m.settings.aov == CausticsAov::FirstType && out.firstType.valid()) shownCaustics = out.firstType;
    if (m.settings.aov == CausticsAov::SecondType && out.secondType.valid()) shownCaustics = out.secondType;
    if (m.settings.causticsOnly) {
        if (in.outputTarget) {
            const rhi::TextureDesc& d = in.outputTarget->desc();
            rg::RgTexture target = graph.importTexture("output", in.outputTarget, in.outputState, in.outputState);
            CausticsOutputParams params{shownCaustics, target, d.format, in.width, in.height, in.outputWrite,
                                        in.outputScale};
            CAUSTICS_TRY(rg::RgTexture written, m.output->addToGraph(graph, *m.device, params));
            out.output = written.valid() ? written : target;
            // The host handed the target in to have it written: keep the passes that feed it (an import
            // is no graph output by itself, and culling would drop them without a word).
            graph.markOutput(out.output);
            return out;
        }
        // The host composites: it must read (or mark) the caustics, else the graph culls every pass.
        expectSomeOutputRead(graph, out);
        return out;
    }

    CompositeParams params;
    params.aov = compositeAov(m.settings.aov);
    params.exposure = m.settings.exposure * m.scene->exposure;
    // Depth AOV: metres shown white; an infinite far plane (clip.y = 0) uses the 50 m cap.
    const float far = frame.camera.clip.y > 0.0f ? frame.camera.clip.y : 50.0f;
    params.depthRange = std::max(1.0f, std::min(far, 50.0f));
    if (in.outputTarget) {   // checked by checkOutputTarget
        params.display = graph.importTexture("output", in.outputTarget, in.outputState, in.outputState);
    }
    CompositeOutputs co = m.composite->addToGraph(graph, out.gbuffer, out.direct, shownCaustics, params);
    out.display = co.display;
    out.hdr = co.hdr;
    if (in.outputTarget) {
        out.output = co.display;
        graph.markOutput(out.output);   // as above: the host's target is what the frame is for
    } else {
        // Reading none of its images culls the whole module without a word.
        expectSomeOutputRead(graph, out);
    }
    return out;
}

}  // namespace caustics
