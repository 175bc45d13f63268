// caustics.maps: the light-space visibility maps (paper 3.2, Figure 3), one texture-array layer per
// planned map, all of the planned resolution (so one forward dispatch covers every light). Only what
// the forward pass reads is rendered: the objectId target (plus the depth it needs), and only the
// instances inside each map's frustum (CausticMapPlan::drawnInstances).
#include "caustic_maps/caustic_internal.h"
#include "caustic_maps/caustic_map_bindings.h"
#include "caustic_maps/shaders/caustic_map.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {

void addMapPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.maps", [&](rg::PassBuilder& b) {
        const uint32_t n = f.in->settings.mapResolution;
        const uint32_t layers = uint32_t(f.plan.maps.size());
        auto tex = [&](const char* name, rhi::Format format, rg::Access access) {
            rhi::TextureDesc d = rhi::TextureDesc().setDimension(rhi::TextureDimension::Texture2DArray).setSize(n, n)
                                     .setArrayLayers(layers).setFormat(format).setUsage(rhi::TextureUsage::Sampled)
                                     .setDebugName(name);
            return b.write(b.createTexture(name, d), access);
        };
        f.mapIds = tex("caustics.mapObjectIds", rhi::Format::R32_UINT, rg::Access::RenderTarget);
        f.mapDepth = tex("caustics.mapDepth", rhi::Format::D32_FLOAT, rg::Access::DepthWrite);
        f.maps = b.read(f.maps, rg::Access::SampledRead);
        // Per layer: (instance, index count) of the instances inside that map's frustum.
        std::vector<std::vector<std::pair<uint32_t, uint32_t>>> draws(layers);
        const scene::GpuScene& gs = *f.in->gpuScene;
        for (uint32_t layer = 0; layer < layers; ++layer) {
            for (uint32_t i : f.plan.drawnInstances[layer]) {
                uint32_t mesh = f.in->scene->instances[i].mesh;
                if (mesh < gs.meshRanges.size() && gs.meshRanges[mesh].indexCount > 0)
                    draws[layer].push_back({i, gs.meshRanges[mesh].indexCount});
            }
        }
        CausticFrame h = f;
        rhi::BindingSetHandle sceneSet = f.in->sceneBindings->set;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.mapLayout, "caustics.maps",
                PassBindingSet(shader_bindings::kCausticMapBindings, 1).buffer("maps", ctx.buffer(h.maps)));
            if (!set) return;
            rhi::ICommandList& cmd = ctx.cmd();
            for (uint32_t layer = 0; layer < layers; ++layer) {
                rhi::RenderingDesc rd;
                rd.width = rd.height = n;
                rhi::ColorAttachment ids;
                ids.texture = ctx.texture(h.mapIds);
                ids.layer = layer;
                ids.clear = true;   // id 0 = nothing seen
                rd.colors.push_back(ids);
                rd.depth.texture = ctx.texture(h.mapDepth);
                rd.depth.layer = layer;
                rd.depth.clear = true;
                cmd.beginRendering(rd);
                cmd.setGraphicsPipeline(r.mapPipeline);
                cmd.setViewport(0.0f, 0.0f, float(n), float(n));
                cmd.setBindingSet(0, sceneSet);
                cmd.setBindingSet(1, set);
                const shader::CausticMapParams push{layer};
                cmd.setPushConstants(&push, sizeof(push));
                for (auto [instance, indexCount] : draws[layer]) cmd.draw(indexCount, 1, 0, instance);
                cmd.endRendering();
            }
        };
    });
}

}  // namespace caustics
