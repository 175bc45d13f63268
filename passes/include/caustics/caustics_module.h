#pragma once
// The public entry of the caustics module. A host creates one per (device, scene) and, every frame,
// adds its passes to the host's render graph (docs/embedding.md has the whole contract):
//
//   auto module = CausticsModule::create(device, scene, gpuScene, settings);   // Result<unique_ptr<>>
//   graph.reset();
//   FrameInputs in{.camera = cameraViewMatrices(cam, w, h), .width = w, .height = h, .frameIndex = n};
//   auto out = (*module)->addPasses(graph, in);      // scene update, G-buffer, direct, caustics, composite
//   graph.markOutput(out->display);                  // or read it in a pass: else compile() fails naming it
//   graph.execute(*device, *cmd);  ...submit...; graph.texture(out->display) is the image
//   graph.passTimeMs("direct_lighting")           // per-pass GPU medians come from the graph
//
// Pass names: view.begin, scene.update, gbuffer (or gbuffer.object_ids for a host G-buffer with an id
// map), direct_lighting, caustics.* (caustic_passes.h), composite (caustics.output instead in
// caustics-only mode with an outputTarget). The scene is read every frame: instances, lights and
// materials may change between frames (live_scene.h). A host G-buffer (caustics/gbuffer.h contract)
// replaces our G-buffer pass; a host output target receives the display image instead of a transient,
// or, with settings.causticsOnly (compositing left to the host), the caustics replaced into or added
// onto it (FrameInputs::outputWrite).
#include <memory>
#include <optional>

#include "caustics/camera_view.h"
#include "caustics/caustics_settings.h"
#include "caustics/gbuffer.h"
#include "caustics/memory_report.h"
#include "caustics/output_target.h"
#include "caustics/host_scene.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

// The state of one view that lives across frames: its filter history, its previous view-projection
// and its camera buffers. A host rendering several views per frame (split screen, a reflection probe)
// holds one per view (CausticsModule::createView); each keeps its own history. Everything in it is
// committed when a graph EXECUTES, so a graph built and dropped changes nothing.
class CausticsView {
public:
    ~CausticsView();
    struct Impl;
    Impl& impl() { return *impl_; }
    const Impl& impl() const { return *impl_; }

private:
    friend class CausticsModule;
    explicit CausticsView(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

struct FrameInputs {
    CameraView camera;                         // host matrices (camera_view.h): jitter, reversed Z, infinite far
    uint32_t width = 0;
    uint32_t height = 0;
    // The frame number, counted up by one per frame (never down: addPasses refuses a smaller one than the
    // view's last). It seeds the photons, so it must not be the frame-in-flight slot: a slot index
    // repeats the same photons every framesInFlight frames.
    uint32_t frameIndex = 0;
    // The frame-in-flight slot whose per-frame buffers this frame uses (< settings.framesInFlight): the
    // host's own slot index. Unset: frameIndex % framesInFlight.
    std::optional<uint32_t> frameSlot;
    bool resetHistory = false;                 // camera cut of THIS view: its filter forgets the past
    CausticsView* view = nullptr;              // null: the module's default view
    std::optional<HostGBuffer> hostGBuffer;    // imported instead of running our G-buffer pass
    HostSceneTables hostScene;                 // the host's TLAS / scene tables, each optional (host_scene.h)
    // Optional host image the module writes its result into (docs/embedding.md "Output target"):
    //  - settings.causticsOnly: caustic radiance x outputScale, per outputWrite (Add onto the host's lit
    //    HDR buffer is the usual case). A float or unorm colour format with three or four channels
    //    (causticsOutputFormatSupported, caustics/output_target.h), RenderTarget usage, the image size.
    //  - otherwise: the display image (RGBA8_UNORM with Storage usage) instead of a transient; Replace
    //    and outputScale 1 only.
    // Refused formats, usages and sizes are addPasses errors naming the field.
    rhi::TextureHandle outputTarget;
    rhi::ResourceState outputState = rhi::ResourceState::ShaderResource;   // before and after the graph
    OutputWrite outputWrite = OutputWrite::Replace;
    float outputScale = 1.0f;   // caustics-only: the host's exposure (pre-exposure) of its target, >= 0
};

struct FrameOutputs {
    // display, hdr and direct are invalid in settings.causticsOnly mode.
    rg::RgTexture display;     // RGBA8_UNORM: tone-mapped, sRGB-encoded settings.aov (or outputTarget)
    rg::RgTexture hdr;         // RGBA32_FLOAT: settings.aov in linear units (no exposure, no tone map)
    rg::RgTexture direct;      // RGBA16_FLOAT direct radiance
    rg::RgTexture caustics;    // RGBA32_FLOAT caustic radiance (cd/m^2), filtered when settings.filter;
                               // invalid when caustics are off or the scene has no light
    // The caustic components, exported for the FirstType / SecondType AOVs (one accumulation buffer
    // otherwise, docs/caustics.md "Memory"); invalid for other AOVs or when off. Filtered when
    // settings.filter and settings.filterSecondTypeApart (the default: each type on its own guides,
    // docs/caustics.md "Second-type guides"), unfiltered otherwise.
    rg::RgTexture firstType, secondType;
    GBuffer gbuffer;
    rg::RgBuffer causticStats; // uint32[kStatCount] (caustic_passes.h); causticStatsWarnings() reads it
    // FrameInputs::outputTarget as the module left it (its last version in the graph: read it in a later
    // pass of the host's); invalid without a target.
    rg::RgTexture output;
};

class CausticsModule {
public:
    // Validates settings (errors name the field) and builds pipelines and scene bindings. `scene` and
    // `gpuScene` must outlive the module; `scene` is read again at every addPasses (a live scene; its
    // meshes and textures must stay those gpuScene was made from). A scene without lights is fine: it
    // renders black direct light and no caustics. settings.framesInFlight is fixed from here on: frame
    // n reuses the per-frame buffers of frame n - framesInFlight, so the host must have waited for
    // that frame before executing frame n's graph.
    //
    // Threading (docs/embedding.md "Threading"): create() and prepare() record and submit on the host's
    // queue (the thread that owns it); addPasses() only declares passes and may run on any one thread
    // at a time; the render graph's execute() records into the host's command list and never submits.
    static Result<std::unique_ptr<CausticsModule>> create(rhi::DeviceHandle device, const scene::Scene& scene,
                                                          const scene::GpuScene& gpuScene,
                                                          const CausticsSettings& settings = {});
    ~CausticsModule();

    Result<FrameOutputs> addPasses(rg::RenderGraph& graph, const FrameInputs& inputs);

    // A further view with its own history and camera buffers (the module has one default view).
    Result<std::unique_ptr<CausticsView>> createView();

    const CausticsSettings& settings() const;
    // The persistent GPU memory the module holds or renders from, one entry per resource (memory_report.h;
    // docs/embedding.md "Memory"): the GpuScene's geometry, textures and BLASes (summed, "scene.*"), each
    // frame slot's tables and TLAS, the second type's sphere BLAS/TLAS, readbacks, the default view's
    // camera buffers and filter history. Sizes follow the last executed frame (the sphere TLAS and the
    // history grow with the output size). Views made by createView() add memoryReport(view) each.
    std::vector<MemoryEntry> memoryReport() const;
    std::vector<MemoryEntry> memoryReport(const CausticsView& view) const;
    // Validated like create(); takes effect at the next addPasses. framesInFlight cannot change. Calls
    // prepare(): settings that switch something on (caustics, causticsOnly off) record and submit on
    // the host's queue here, with prepare()'s thread rule.
    Status setSettings(const CausticsSettings& settings);
    // Makes what the current settings need: ray-tracing pipelines and their shader tables (uploaded),
    // the second type's sphere BLAS (built). Records and submits on the host's queue and waits for it:
    // call it from the thread that owns that queue, when no other thread uses it. create() and
    // setSettings() call it; it does nothing when all is made.
    Status prepare();

    struct Impl;

private:
    explicit CausticsModule(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace caustics
