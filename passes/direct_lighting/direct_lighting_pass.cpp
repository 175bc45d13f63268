// Deferred direct lighting (paper 3.1) with ray-traced shadows and specular chains; the body is
// passes/direct_lighting/shaders/direct.h, its resources direct_lighting_bindings.h.
#include "direct_lighting_pass.h"

#include "caustics/pass_shaders.h"
#include "caustics/rhi/log.h"
#include "direct_lighting/direct_lighting_bindings.h"
#include "direct_lighting/shaders/direct_light.h"
#include "module/pass_bindings.h"

namespace caustics {

Result<DirectLightingPass> DirectLightingPass::create(rhi::IDevice& device, const rhi::BindingLayoutHandle& sceneLayout,
                                                      const rhi::BindingLayoutHandle& cameraLayout) {
    DirectLightingPass pass;
    CAUSTICS_TRY(pass.layout_, createPassBindingLayout(device, shader_bindings::kDirectLightingBindings, 2,
                                                       rhi::ShaderStage::AllRayTracing));

    auto library = [&](const char* file, const char* name, rhi::ShaderStage stage) {
        return pass_shaders::shaderLibrary(device.backend(), file, name, stage);
    };
    rhi::StateObjectDesc desc;
    CAUSTICS_TRY(auto rgen, library("direct_lighting/direct.rgen", "directRayGen", rhi::ShaderStage::RayGen));
    CAUSTICS_TRY(auto surfaceMiss, library("direct_lighting/surface.rmiss", "surfaceMiss", rhi::ShaderStage::Miss));
    CAUSTICS_TRY(auto shadowMiss, library("direct_lighting/shadow.rmiss", "shadowMiss", rhi::ShaderStage::Miss));
    CAUSTICS_TRY(auto surfaceHit, library("direct_lighting/surface.rchit", "surfaceClosestHit", rhi::ShaderStage::ClosestHit));
    desc.libraries = {rgen, surfaceMiss, shadowMiss, surfaceHit};
    desc.hitGroups.push_back({"surfaceHit", rhi::HitGroupType::Triangles, "surfaceClosestHit", "", ""});
    desc.maxPayloadBytes = sizeof(shader::SurfacePayload);
    desc.maxAttributeBytes = 8;
    desc.maxRecursionDepth = 1;  // only the raygen traces
    desc.globalBindings.layouts = {sceneLayout, cameraLayout, pass.layout_};
    desc.debugName = "direct lighting";
    CAUSTICS_TRY(pass.stateObject_, device.createStateObject(desc));

    rhi::ShaderTableDesc table;
    table.stateObject = pass.stateObject_;
    table.setRayGen("directRayGen").addMiss("surfaceMiss").addMiss("shadowMiss").addHitGroup("surfaceHit");
    table.debugName = "direct lighting";
    CAUSTICS_TRY(pass.shaderTable_, device.createShaderTable(table));
    return pass;
}

rg::RgTexture DirectLightingPass::addToGraph(rg::RenderGraph& graph, const FrameContext& frame,
                                             const GBuffer& gbuffer) const {
    rg::RgTexture out;
    graph.addPass("direct_lighting", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::RayTracing);
        rg::RgTexture normal = b.read(gbuffer.normalRoughness, rg::Access::SampledRead);
        rg::RgTexture albedo = b.read(gbuffer.albedoMetallic, rg::Access::SampledRead);
        rg::RgTexture depth = b.read(gbuffer.linearDepth, rg::Access::SampledRead);
        rg::RgTexture ids = b.read(gbuffer.objectId, rg::Access::SampledRead);
        if (frame.sceneTlas.valid()) b.read(frame.sceneTlas);   // shadow and surface rays
        out = b.write(b.createTexture("direct", gbufferTextureDesc(kOutputFormat, gbuffer.width, gbuffer.height, "direct")),
                      rg::Access::StorageWrite);
        rg::RgTexture target = out;
        uint32_t w = gbuffer.width, h = gbuffer.height;
        rhi::BindingLayoutHandle layout = layout_;
        rhi::StateObjectHandle so = stateObject_;
        rhi::ShaderTableHandle table = shaderTable_;
        rhi::BindingSetHandle sceneSet = frame.sceneBindings->set, cameraSet = frame.cameraSet;
        return [=](rg::PassContext& ctx) {
            auto sd = PassBindingSet(shader_bindings::kDirectLightingBindings, 2)
                          .texture("gNormalRoughness", ctx.texture(normal))
                          .texture("gAlbedoMetallic", ctx.texture(albedo))
                          .texture("gLinearDepth", ctx.texture(depth))
                          .texture("gObjectId", ctx.texture(ids))
                          .texture("outRadiance", ctx.texture(target))
                          .desc();
            if (!sd) {
                log(LogLevel::Error, "direct_lighting: " + sd.message());
                return;
            }
            auto set = ctx.device()->createBindingSet(*sd, layout);
            if (!set) {
                log(LogLevel::Error, "direct_lighting: " + set.message());
                return;
            }
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setRayTracingState(so, table);
            cmd.setBindingSet(kSceneSet, sceneSet);
            cmd.setBindingSet(kCameraSet, cameraSet);
            cmd.setBindingSet(kPassSet, *set);
            cmd.dispatchRays(w, h, 1);
        };
    });
    return out;
}

}  // namespace caustics
