// caustics.secondTypeGuides.clear, caustics.secondTypeGuides, .fill and .glass: the
// second type's own filter guides (passes/backward_trace/shaders/second_type_guides.h and
// second_type_guide_fill.h; docs/caustics.md "Second-type guides"), written from this frame's spheres
// (caustics.backward), then filled in place where a pixel's sample made none, so that the filter can run
// the second type on the receiver seen through the glass instead of on the glass the camera G-buffer
// holds, except where the receiver is no surface it can follow (too few neighbours agree: those pixels
// take the glass's guides). Declared after the resolve (caustic_filter_pass.cpp): the guides then do not share the frame's
// peak with the stored hits and the radiance buffers.
#include <string>

#include "backward_trace/second_type_guide_fill_bindings.h"
#include "backward_trace/second_type_guides_bindings.h"
#include "backward_trace/shaders/second_type_guide_fill.h"
#include "backward_trace/shaders/second_type_guides.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"
#include "common/specular_list.h"
#include "module/pass_bindings.h"

namespace caustics {
namespace {

rg::RgTexture createGuide(rg::PassBuilder& b, uint32_t w, uint32_t h, const std::string& name, rhi::Format format) {
    return b.write(b.createTexture(name, rhi::TextureDesc().setSize(w, h).setFormat(format)
                                             .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage |
                                                       rhi::TextureUsage::CopySource)
                                             .setDebugName(name)));
}

// The guide images' size: the screen's, or one texel per list entry (common/specular_list.h).
struct GuideSize {
    uint32_t width, height;
};
GuideSize guideSize(const CausticFrame& f) {
    return f.secondTypeListOrder ? GuideSize{shader::kSpecularListRow, f.listRows} : GuideSize{f.width, f.height};
}

// What the sphere pass writes: depth and motion, normal and photon weight (both half precision), and
// the pixel's receiver id in sphereObjectId (0: no sphere), which the fill reads.
struct SphereGuides {
    rg::RgTexture depthMotion, normal, sphereObjectId;
};

// One dispatch of the guide pipeline over the image grid (clear: per pixel; else per sphere slot).
// cameraDepth, cameraIds: the camera G-buffer's linear depth and object ids (the glass at the pixel).
void recordGuides(rg::PassContext& ctx, const CausticFrame& h, const SphereGuides& g, rg::RgTexture cameraDepth,
                  rg::RgTexture cameraIds, bool clear) {
    CausticResources::Impl& r = *h.res;
    PassBindingSet set(shader_bindings::kSecondTypeGuidesBindings, 0);
    set.buffer("camera", ctx.buffer(h.camera))
        .buffer("spheres", ctx.buffer(h.spheres))
        .buffer("counters", ctx.buffer(h.stats))
        .texture("depthMotion", ctx.texture(g.depthMotion))
        .texture("normal", ctx.texture(g.normal))
        .texture("sphereObjectId", ctx.texture(g.sphereObjectId))
        .texture("gLinearDepth", ctx.texture(cameraDepth))
        .texture("gObjectId", ctx.texture(cameraIds))
        .buffer("instanceMotion", ctx.buffer(h.instanceMotionRows))
        .texture("specularIndex", ctx.texture(h.specularIndex));
    rhi::BindingSetHandle bound = r.makeSet(*ctx.device(), r.secondTypeGuideLayout, "caustics.secondTypeGuides", set);
    if (!bound) return;
    const GuideSize size = guideSize(h);
    const shader::SecondTypeGuideParams push{{h.width, h.height}, *h.sphereCapacity, clear ? 1u : 0u,
                                             h.objectMotion ? 1u : 0u, h.plan.instanceCount, {size.width, size.height},
                                             h.secondTypeListOrder ? 1u : 0u, 0u};
    // The clear covers the guide images, the sphere pass a grid of the list's width with a thread per
    // sphere slot (up to kMaxSpheresPerPixel a pixel: more than the list's entries).
    const uint32_t gridWidth = clear ? size.width : shader::kSpecularListRow;
    const uint32_t gridHeight = clear ? size.height : shader::specularListRows(h.sphereAllocation);
    rhi::ICommandList& cmd = ctx.cmd();
    cmd.setComputePipeline(r.secondTypeGuidePipeline);
    cmd.setBindingSet(0, bound);
    cmd.setPushConstants(&push, sizeof(push));
    cmd.dispatch((gridWidth + 7) / 8, (gridHeight + 7) / 8, 1);
}

// caustics.secondTypeGuides.fill (glass false): the sphere-written guides completed in place where a
// pixel has none, every pixel's object id, and the mark of those whose receiver too few neighbours agree
// with; caustics.secondTypeGuides.glass (glass true): the marked pixels take the glass's guides.
void addFillPass(rg::RenderGraph& graph, CausticFrame& f, const SphereGuides& fromSpheres, bool glass) {
    SecondTypeGuides& g = f.secondTypeGuides;
    const GuideSize size = guideSize(f);
    graph.addPass(glass ? "caustics.secondTypeGuides.glass" : "caustics.secondTypeGuides.fill", [&, glass](rg::PassBuilder& b) {
        // The glass pass reads no sphere id (its slot takes the camera's ids): the sphere ids live no longer
        // than the fill.
        const rg::RgTexture cameraIds = b.read(f.in->gbuffer.objectId);
        const rg::RgTexture sphereIds = glass ? cameraIds : b.read(fromSpheres.sphereObjectId);
        const rg::RgTexture cameraDepth = b.read(f.in->gbuffer.linearDepth, rg::Access::SampledRead);
        const rg::RgTexture cameraNormal = b.read(f.in->gbuffer.normalRoughness, rg::Access::SampledRead);
        // Only the screen layout tests which pixels are specular (in list order every entry is): in list
        // order the slot takes the normal, so the optics live no longer than before (MemoryBudget.*).
        const rg::RgTexture cameraOptics =
            f.secondTypeListOrder ? cameraNormal : b.read(f.in->gbuffer.optics, rg::Access::SampledRead);
        const rg::RgTexture index = f.specularIndex = b.read(f.specularIndex, rg::Access::SampledRead);
        f.specularPixels = b.read(f.specularPixels, rg::Access::SampledRead);
        f.backwardArgs = b.read(f.backwardArgs, rg::Access::SampledRead);
        f.camera = b.read(f.camera, rg::Access::ConstantBuffer);
        f.instanceMotionRows = b.read(f.instanceMotionRows, rg::Access::SampledRead);
        g.depthMotion = b.write(glass ? g.depthMotion : fromSpheres.depthMotion, rg::Access::StorageReadWrite);
        g.normal = b.write(glass ? g.normal : fromSpheres.normal, rg::Access::StorageReadWrite);
        g.objectId = glass ? b.write(g.objectId, rg::Access::StorageReadWrite)
                           : createGuide(b, size.width, size.height, "caustics.secondTypeObjectId", rhi::Format::R32_UINT);
        CausticFrame fr = f;
        SecondTypeGuides out = g;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *fr.res;
            rhi::BindingSetHandle bound = r.makeSet(*ctx.device(), r.secondTypeGuideFillLayout,
                glass ? "caustics.secondTypeGuides.glass" : "caustics.secondTypeGuides.fill",
                PassBindingSet(shader_bindings::kSecondTypeGuideFillBindings, 0)
                    .texture("sphereObjectId", ctx.texture(sphereIds))
                    .texture("cameraObjectId", ctx.texture(cameraIds))
                    .texture("depthMotion", ctx.texture(out.depthMotion))
                    .texture("normal", ctx.texture(out.normal))
                    .texture("objectId", ctx.texture(out.objectId))
                    .texture("specularIndex", ctx.texture(index))
                    .buffer("specularPixels", ctx.buffer(fr.specularPixels))
                    .buffer("listCount", ctx.buffer(fr.backwardArgs))
                    .buffer("camera", ctx.buffer(fr.camera))
                    .texture("cameraLinearDepth", ctx.texture(cameraDepth))
                    .texture("cameraNormal", ctx.texture(cameraNormal))
                    .texture("cameraOptics", ctx.texture(cameraOptics))
                    .buffer("instanceMotion", ctx.buffer(fr.instanceMotionRows)));
            if (!bound) return;
            const shader::SecondTypeGuideFillParams push{{fr.width, fr.height}, fr.secondTypeListOrder ? 1u : 0u, glass ? 1u : 0u,
                                                         fr.objectMotion ? 1u : 0u, fr.plan.instanceCount};
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.setComputePipeline(r.secondTypeGuideFillPipeline);
            cmd.setBindingSet(0, bound);
            cmd.setPushConstants(&push, sizeof(push));
            // One thread per pixel, or per list entry.
            const GuideSize grid = guideSize(fr);
            cmd.dispatch((grid.width + 7) / 8, (grid.height + 7) / 8, 1);
        };
    });
}

}  // namespace

void addSecondTypeGuidePasses(rg::RenderGraph& graph, CausticFrame& f) {
    SphereGuides g;   // written from the spheres
    const GuideSize size = guideSize(f);
    const uint32_t w = size.width, h = size.height;
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
            f.specularIndex = b.read(f.specularIndex, rg::Access::SampledRead);
            if (clear) {
                // Half precision (docs/caustics.md "Second-type guides": within the filter's depth and
                // motion tolerances, and the half of the memory).
                g.depthMotion = createGuide(b, w, h, "caustics.secondTypeDepthMotion", rhi::Format::RGBA16_FLOAT);
                g.normal = createGuide(b, w, h, "caustics.secondTypeNormal", rhi::Format::RGBA16_FLOAT);
                g.sphereObjectId = createGuide(b, w, h, "caustics.sphereObjectId", rhi::Format::R32_UINT);
            } else {
                g.depthMotion = b.write(g.depthMotion, rg::Access::StorageReadWrite);
                g.normal = b.write(g.normal, rg::Access::StorageReadWrite);
                g.sphereObjectId = b.write(g.sphereObjectId, rg::Access::StorageReadWrite);
            }
            CausticFrame fr = f;
            SphereGuides out = g;
            return [=](rg::PassContext& ctx) { recordGuides(ctx, fr, out, cameraDepth, cameraIds, clear); };
        });
    }
    addFillPass(graph, f, g, false);
    addFillPass(graph, f, g, true);
}

}  // namespace caustics
