#pragma once
// The public entry of the caustics module. A host creates one per (device, scene) and, every frame,
// adds its passes to the host's render graph:
//
//   auto module = CausticsModule::create(device, scene, gpuScene, settings);   // Result<unique_ptr<>>
//   graph.reset();
//   FrameInputs in{.camera = cam, .width = w, .height = h, .frameIndex = n};
//   auto out = (*module)->addPasses(graph, in);      // G-buffer, direct, caustics, composite
//   graph.markOutput(out->display);
//   graph.execute(*device, *cmd);  ...submit...; graph.texture(out->display) is the image
//   graph.passTimeMs("direct_lighting")           // per-pass GPU medians come from the graph
//
// Pass names: gbuffer, direct_lighting, caustics.* (caustic_passes.h), composite.
// A host G-buffer (caustics/gbuffer.h contract) replaces our G-buffer pass; a host output target
// (RGBA8_UNORM with Storage usage) receives the display image instead of a transient.
#include <memory>
#include <optional>

#include "caustics/caustics_settings.h"
#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/scene.h"

namespace caustics {

struct FrameInputs {
    scene::Camera camera;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t frameIndex = 0;
    bool resetHistory = false;                 // camera cut: temporal filtering forgets the past
    std::optional<HostGBuffer> hostGBuffer;    // imported instead of running our G-buffer pass
    rhi::TextureHandle outputTarget;           // optional RGBA8_UNORM, Storage usage
    rhi::ResourceState outputState = rhi::ResourceState::ShaderResource;   // before and after the graph
};

struct FrameOutputs {
    rg::RgTexture display;     // RGBA8_UNORM: tone-mapped, sRGB-encoded settings.aov (or outputTarget)
    rg::RgTexture hdr;         // RGBA32_FLOAT: settings.aov in linear units (no exposure, no tone map)
    rg::RgTexture direct;      // RGBA16_FLOAT direct radiance
    rg::RgTexture caustics;    // RGBA32_FLOAT caustic radiance; invalid when caustics are off
    rg::RgTexture firstType, secondType;   // unfiltered caustic components; invalid when off
    GBuffer gbuffer;
    rg::RgBuffer causticStats; // uint32[kStatCount] (caustic_passes.h); causticStatsWarnings() reads it
};

class CausticsModule {
public:
    // The frames whose camera constants may be in flight at once: frame n reuses the camera buffer
    // of frame n - kFramesInFlight, so the host must have waited for that frame by then.
    static constexpr uint32_t kFramesInFlight = 3;

    // Validates settings (errors name the field) and builds pipelines and scene bindings. `scene` and
    // `gpuScene` must outlive the module. A scene without lights is fine: it renders black direct light
    // and no caustics.
    static Result<std::unique_ptr<CausticsModule>> create(rhi::DeviceHandle device, const scene::Scene& scene,
                                                          const scene::GpuScene& gpuScene,
                                                          const CausticsSettings& settings = {});
    ~CausticsModule();

    Result<FrameOutputs> addPasses(rg::RenderGraph& graph, const FrameInputs& inputs);

    const CausticsSettings& settings() const;
    // Validated like create(); takes effect at the next addPasses.
    Status setSettings(const CausticsSettings& settings);

    struct Impl;

private:
    explicit CausticsModule(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace caustics
