// caustics.secondTypeGuides.clear, caustics.secondTypeGuides and caustics.secondTypeGuides.fill: the
// second type's own filter guides (passes/backward_trace/shaders/second_type_guides.h and
// second_type_guide_fill.h; docs/caustics.md "Second-type guides"), written from this frame's spheres
// (caustics.backward), then filled where a pixel's sample made none, so that the filter can run the
// second type on the receiver seen through the glass instead of on the glass the camera G-buffer holds.
#include <string>

#include "backward_trace/second_type_guide_fill_bindings.h"
#include "backward_trace/second_type_guides_bindings.h"
#include "backward_trace/shaders/second_type_guide_fill.h"
#include "backward_trace/shaders/second_type_guides.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {
namespace {

// The three guide textures, created and written by the pass being built: <prefix>DepthMotion, Normal, ObjectId.
SecondTypeGuides createGuides(rg::PassBuilder& b, uint32_t w, uint32_t h, const std::string& prefix) {
    auto make = [&](const char* suffix, rhi::Format format) {
        const std::string name = prefix + suffix;
        return b.write(b.createTexture(name, rhi::TextureDesc().setSize(w, h).setFormat(format)
                                                 .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage |
                                                           rhi::TextureUsage::CopySource)
                                                 .setDebugName(name)));
    };
    return {make("DepthMotion", rhi::Format::RGBA32_FLOAT), make("Normal", rhi::Format::RGBA16_FLOAT),
            make("ObjectId", rhi::Format::R32_UINT)};
}

// One dispatch of the guide pipeline over the image grid (clear: per pixel; else per sphere slot).
// cameraDepth, cameraIds: the camera G-buffer's linear depth and object ids (the glass at the pixel).
void recordGuides(rg::PassContext& ctx, const CausticFrame& h, const SecondTypeGuides& g, rg::RgTexture cameraDepth,
                  rg::RgTexture cameraIds, bool clear) {
    CausticResources::Impl& r = *h.res;
    PassBindingSet set(shader_bindings::kSecondTypeGuidesBindings, 0);
    set.buffer("camera", ctx.buffer(h.camera))
        .buffer("spheres", ctx.buffer(h.spheres))
        .buffer("counters", ctx.buffer(h.stats))
        .texture("depthMotion", ctx.texture(g.depthMotion))
        .texture("normal", ctx.texture(g.normal))
        .texture("objectId", ctx.texture(g.objectId))
        .texture("gLinearDepth", ctx.texture(cameraDepth))
        .texture("gObjectId", ctx.texture(cameraIds))
        .buffer("instanceMotion", ctx.buffer(h.instanceMotionRows));
    rhi::BindingSetHandle bound = r.makeSet(*ctx.device(), r.secondTypeGuideLayout, "caustics.secondTypeGuides", set);
    if (!bound) return;
    const shader::SecondTypeGuideParams push{{h.width, h.height}, *h.sphereCapacity, clear ? 1u : 0u,
                                             h.objectMotion ? 1u : 0u, h.plan.instanceCount};
    rhi::ICommandList& cmd = ctx.cmd();
    cmd.setComputePipeline(r.secondTypeGuidePipeline);
    cmd.setBindingSet(0, bound);
    cmd.setPushConstants(&push, sizeof(push));
    cmd.dispatch((h.width + 7) / 8, (h.height + 7) / 8, 1);
}

// caustics.secondTypeGuides.fill: the sphere-written guides, with holes filled from a neighbour.
void addFillPass(rg::RenderGraph& graph, CausticFrame& f, const SecondTypeGuides& fromSpheres) {
    SecondTypeGuides& g = f.secondTypeGuides;
    const uint32_t w = f.width, h = f.height;
    graph.addPass("caustics.secondTypeGuides.fill", [&](rg::PassBuilder& b) {
        const rg::RgTexture in[] = {b.read(fromSpheres.depthMotion), b.read(fromSpheres.normal), b.read(fromSpheres.objectId),
                                    b.read(f.in->gbuffer.objectId)};
        g = createGuides(b, w, h, "caustics.secondType");
        CausticFrame fr = f;
        SecondTypeGuides out = g;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *fr.res;
            rhi::BindingSetHandle bound = r.makeSet(*ctx.device(), r.secondTypeGuideFillLayout, "caustics.secondTypeGuides.fill",
                PassBindingSet(shader_bindings::kSecondTypeGuideFillBindings, 0)
                    .texture("sphereDepthMotion", ctx.texture(in[0]))
                    .texture("sphereNormal", ctx.texture(in[1]))
                    .texture("sphereObjectId", ctx.texture(in[2]))
                    .texture("cameraObjectId", ctx.texture(in[3]))
                    .texture("depthMotion", ctx.texture(out.depthMotion))
                    .texture("normal", ctx.texture(out.normal))
                    .texture("objectId", ctx.texture(out.objectId)));
            if (!bound) return;
            const shader::SecondTypeGuideFillParams push{{fr.width, fr.height}};
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.secondTypeGuideFillPipeline);
            cmd.setBindingSet(0, bound);
            cmd.setPushConstants(&push, sizeof(push));
            cmd.dispatch((fr.width + 7) / 8, (fr.height + 7) / 8, 1);
        };
    });
}

}  // namespace

void addSecondTypeGuidePasses(rg::RenderGraph& graph, CausticFrame& f) {
    SecondTypeGuides g;   // written from the spheres
    const uint32_t w = f.width, h = f.height;
    // Both passes bind the same set (one declaration); the clear reads the buffers without using them.
    for (bool clear : {true, false}) {
        graph.addPass(clear ? "caustics.secondTypeGuides.clear" : "caustics.secondTypeGuides", [&, clear](rg::PassBuilder& b) {
            f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
            f.spheres = b.read(f.spheres, rg::Access::SampledRead);
            f.stats = b.read(f.stats, rg::Access::SampledRead);
            // The glass the camera sees and its motion (docs/caustics.md "Moving objects").
            const rg::RgTexture cameraDepth = b.read(f.in->gbuffer.linearDepth, rg::Access::SampledRead);
            const rg::RgTexture cameraIds = b.read(f.in->gbuffer.objectId, rg::Access::SampledRead);
            f.instanceMotionRows = b.read(f.instanceMotionRows, rg::Access::SampledRead);
            if (clear) {
                g = createGuides(b, w, h, "caustics.sphere");
            } else {
                g.depthMotion = b.write(g.depthMotion, rg::Access::StorageReadWrite);
                g.normal = b.write(g.normal, rg::Access::StorageReadWrite);
                g.objectId = b.write(g.objectId, rg::Access::StorageReadWrite);
            }
            CausticFrame fr = f;
            SecondTypeGuides out = g;
            return [=](rg::PassContext& ctx) { recordGuides(ctx, fr, out, cameraDepth, cameraIds, clear); };
        });
    }
    addFillPass(graph, f, g);
}

}  // namespace caustics
