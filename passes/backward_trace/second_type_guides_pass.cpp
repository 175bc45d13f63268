// caustics.secondTypeGuides.clear and caustics.secondTypeGuides: the second type's own filter guides
// (passes/backward_trace/shaders/second_type_guides.h; docs/caustics.md "Second-type guides"), written
// from this frame's spheres (caustics.backward) so that the filter can run the second type on the
// receiver seen through the glass instead of on the glass the camera G-buffer holds.
#include <cstddef>

#include "backward_trace/second_type_guides_bindings.h"
#include "backward_trace/shaders/second_type_guides.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"
#include "module/pass_bindings.h"

namespace caustics {
namespace {

static_assert(sizeof(shader::GuideSphere) == sizeof(CausticSphere));
static_assert(offsetof(shader::GuideSphere, pixel) == offsetof(CausticSphere, pixel));
static_assert(sizeof(shader::GuideCamera) == sizeof(CameraConstants));
static_assert(offsetof(shader::GuideCamera, prevViewProj) == offsetof(CameraConstants, prevViewProj));
static_assert(shader::kGuideSphereCountSlot == kStatSpheres);

rhi::TextureDesc guideDesc(uint32_t w, uint32_t h, rhi::Format format, const char* name) {
    return rhi::TextureDesc().setSize(w, h).setFormat(format)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage | rhi::TextureUsage::CopySource)
        .setDebugName(name);
}

// One dispatch of the guide pipeline over the image grid (clear: per pixel; else per sphere slot).
void recordGuides(rg::PassContext& ctx, const CausticFrame& h, const SecondTypeGuides& g, bool clear) {
    CausticResources::Impl& r = *h.res;
    PassBindingSet set(shader_bindings::kSecondTypeGuidesBindings, 0);
    set.buffer("camera", ctx.buffer(h.camera))
        .buffer("spheres", ctx.buffer(h.spheres))
        .buffer("counters", ctx.buffer(h.stats))
        .texture("depthMotion", ctx.texture(g.depthMotion))
        .texture("normal", ctx.texture(g.normal))
        .texture("objectId", ctx.texture(g.objectId));
    auto desc = set.desc();
    if (!desc) {
        log(LogLevel::Error, "caustics.secondTypeGuides: " + desc.message());
        return;
    }
    rhi::BindingSetHandle bound = r.makeSet(*ctx.device(), r.secondTypeGuideLayout, *desc);
    if (!bound) return;
    const shader::SecondTypeGuideParams push{{h.width, h.height}, *h.sphereCapacity, clear ? 1u : 0u};
    rhi::ICommandList& cmd = ctx.cmd();
    cmd.setComputePipeline(r.secondTypeGuidePipeline);
    cmd.setBindingSet(0, bound);
    cmd.setPushConstants(&push, sizeof(push));
    cmd.dispatch((h.width + 7) / 8, (h.height + 7) / 8, 1);
}

}  // namespace

void addSecondTypeGuidePasses(rg::RenderGraph& graph, CausticFrame& f) {
    SecondTypeGuides& g = f.secondTypeGuides;
    const uint32_t w = f.width, h = f.height;
    // Both passes bind the same set (one declaration); the clear reads the buffers without using them.
    for (bool clear : {true, false}) {
        graph.addPass(clear ? "caustics.secondTypeGuides.clear" : "caustics.secondTypeGuides", [&, clear](rg::PassBuilder& b) {
            f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
            f.spheres = b.read(f.spheres, rg::Access::SampledRead);
            f.stats = b.read(f.stats, rg::Access::SampledRead);
            if (clear) {
                g.depthMotion = b.write(b.createTexture("caustics.secondTypeDepthMotion",
                                                        guideDesc(w, h, rhi::Format::RGBA32_FLOAT, "caustics.secondTypeDepthMotion")));
                g.normal = b.write(b.createTexture("caustics.secondTypeNormal",
                                                   guideDesc(w, h, rhi::Format::RGBA16_FLOAT, "caustics.secondTypeNormal")));
                g.objectId = b.write(b.createTexture("caustics.secondTypeObjectId",
                                                     guideDesc(w, h, rhi::Format::R32_UINT, "caustics.secondTypeObjectId")));
            } else {
                g.depthMotion = b.write(g.depthMotion, rg::Access::StorageReadWrite);
                g.normal = b.write(g.normal, rg::Access::StorageReadWrite);
                g.objectId = b.write(g.objectId, rg::Access::StorageReadWrite);
            }
            CausticFrame fr = f;
            SecondTypeGuides out = g;
            return [=](rg::PassContext& ctx) { recordGuides(ctx, fr, out, clear); };
        });
    }
}

}  // namespace caustics
