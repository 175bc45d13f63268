// The G-buffer raster: one draw per instance, vertex pulling; the body is
// passes/gbuffer/shaders/gbuffer.h, its resources gbuffer_bindings.h (the camera set is the module's).
#include "gbuffer_pass.h"

#include <vector>

#include "caustics/pass_shaders.h"
#include "gbuffer/shaders/gbuffer.h"

namespace caustics {

Result<GBufferPass> GBufferPass::create(rhi::IDevice& device, const rhi::BindingLayoutHandle& sceneLayout,
                                        const rhi::BindingLayoutHandle& cameraLayout) {
    rhi::GraphicsPipelineDesc desc;
    CAUSTICS_TRY(desc.vertexShader.code, pass_shaders::shaderCode(device.backend(), "gbuffer/gbuffer.vert"));
    desc.vertexShader.stage = rhi::ShaderStage::Vertex;
    CAUSTICS_TRY(desc.fragmentShader.code, pass_shaders::shaderCode(device.backend(), "gbuffer/gbuffer.frag"));
    desc.fragmentShader.stage = rhi::ShaderStage::Fragment;
    desc.bindings.layouts = {sceneLayout, cameraLayout};
    desc.bindings.pushConstantBytes = sizeof(shader::GBufferParams);
    // No culling: glass and thin surfaces are seen from both sides; the shader turns the normal.
    desc.cullMode = rhi::CullMode::None;
    desc.colorFormats = {GBufferFormats::kNormalRoughness, GBufferFormats::kAlbedoMetallic, GBufferFormats::kOptics,
                         GBufferFormats::kLinearDepth, GBufferFormats::kObjectId};
    desc.depthFormat = GBufferFormats::kDepth;
    desc.depthCompare = rhi::CompareOp::Less;
    desc.debugName = "gbuffer";
    GBufferPass pass;
    CAUSTICS_TRY(pass.pipeline_, device.createGraphicsPipeline(desc));
    desc.depthCompare = rhi::CompareOp::Greater;
    desc.debugName = "gbuffer (reversed Z)";
    CAUSTICS_TRY(pass.reversedZPipeline_, device.createGraphicsPipeline(desc));
    return pass;
}

GBuffer GBufferPass::addToGraph(rg::RenderGraph& graph, const FrameContext& frame) const {
    GBuffer g;
    g.width = frame.width;
    g.height = frame.height;
    graph.addPass("gbuffer", [&](rg::PassBuilder& b) {
        auto make = [&](rhi::Format f, const char* name) {
            return b.createTexture(name, gbufferTextureDesc(f, frame.width, frame.height, name));
        };
        g.depth = b.write(make(GBufferFormats::kDepth, "gbuffer.depth"), rg::Access::DepthWrite);
        g.normalRoughness = b.write(make(GBufferFormats::kNormalRoughness, "gbuffer.normalRoughness"), rg::Access::RenderTarget);
        g.albedoMetallic = b.write(make(GBufferFormats::kAlbedoMetallic, "gbuffer.albedoMetallic"), rg::Access::RenderTarget);
        g.optics = b.write(make(GBufferFormats::kOptics, "gbuffer.optics"), rg::Access::RenderTarget);
        g.linearDepth = b.write(make(GBufferFormats::kLinearDepth, "gbuffer.linearDepth"), rg::Access::RenderTarget);
        g.objectId = b.write(make(GBufferFormats::kObjectId, "gbuffer.objectId"), rg::Access::RenderTarget);

        // Draw list: instance index and its index count (one mesh per instance).
        std::vector<std::pair<uint32_t, uint32_t>> draws;
        for (uint32_t i = 0; i < frame.scene->instances.size(); ++i) {
            uint32_t mesh = frame.scene->instances[i].mesh;
            if (mesh < frame.gpuScene->meshRanges.size() && frame.gpuScene->meshRanges[mesh].indexCount > 0)
                draws.push_back({i, frame.gpuScene->meshRanges[mesh].indexCount});
        }
        GBuffer out = g;
        rhi::BindingSetHandle sceneSet = frame.sceneBindings->set;
        rhi::BindingSetHandle cameraSet = frame.cameraSet;
        const bool reversedZ = frame.camera.frame.w != 0u;
        rhi::GraphicsPipelineHandle pipeline = reversedZ ? reversedZPipeline_ : pipeline_;
        return [=](rg::PassContext& ctx) {
            rhi::RenderingDesc rd;
            rd.width = out.width;
            rd.height = out.height;
            for (rg::RgTexture t : {out.normalRoughness, out.albedoMetallic, out.optics, out.linearDepth, out.objectId}) {
                rhi::ColorAttachment a;
                a.texture = ctx.texture(t);
                a.clear = true;   // background: all zero (objectId 0, linearDepth 0)
                rd.colors.push_back(a);
            }
            rd.depth.texture = ctx.texture(out.depth);
            rd.depth.clear = true;
            rd.depth.clearDepth = reversedZ ? 0.0f : 1.0f;   // the far plane
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.beginRendering(rd);
            cmd.setGraphicsPipeline(pipeline);
            cmd.setViewport(0.0f, 0.0f, float(out.width), float(out.height));
            cmd.setBindingSet(kSceneSet, sceneSet);
            cmd.setBindingSet(kCameraSet, cameraSet);
            for (auto [instance, indexCount] : draws) {
                const shader::GBufferParams push{instance};
                cmd.setPushConstants(&push, sizeof(push));
                cmd.draw(indexCount);
            }
            cmd.endRendering();
        };
    });
    return g;
}

}  // namespace caustics
