// caustics.specularPixels: compacts the camera pixels whose surface is specular into a list and counts
// the backward grid up (shaders/specular_pixels.h; the list is cut at the frame's
// sphere capacity, the count is not), so that caustics.backward launches once per listed specular pixel, as caustics.forward launches once per emitting texel (docs/caustics.md,
// "Second-type cost"). It also chooses the frame's sphere capacity (caustics/sphere_capacity.h) and zeroes
// the sphere AABB list: the slots the backward pass leaves unwritten are point boxes at the origin, which
// the intersection shader refuses by their index. (NaN boxes, inactive by the Vulkan and DXR specs, left
// lavapipe's BVH without a single hit.)
#include <algorithm>

#include "backward_trace/shaders/specular_pixels.h"
#include "common/specular_list.h"
#include "backward_trace/specular_pixels_bindings.h"
#include "caustic_maps/caustic_internal.h"
#include "module/pass_bindings.h"

namespace caustics {

void addSpecularPixelPass(rg::RenderGraph& graph, CausticFrame& f) {
    f.sphereAabbs = graph.importBuffer("caustics.sphereAabbs", f.res->sphereAabbs, rhi::ResourceState::Common,
                                       rhi::ResourceState::Common);
    graph.addPass("caustics.specularPixels", [&](rg::PassBuilder& b) {
        b.setStages(rhi::PipelineStages::Compute | rhi::PipelineStages::Copy);
        rg::RgTexture objectId = b.read(f.in->gbuffer.objectId, rg::Access::SampledRead);
        rg::RgTexture optics = b.read(f.in->gbuffer.optics, rg::Access::SampledRead);
        // As many entries as sphere slots: a pixel past the capacity gets no sphere, listed or not.
        f.specularPixels = b.write(b.createBuffer("caustics.specularPixels", rhi::BufferDesc().setByteSize(uint64_t(std::max(f.sphereAllocation, 1u)) * 4)
                                                                                  .setUsage(rhi::BufferUsage::Storage)
                                                                                  .setDebugName("caustics.specularPixels")),
                                   rg::Access::StorageWrite);
        f.backwardArgs = b.write(f.backwardArgs, rg::Access::StorageReadWrite);
        // List order: each pixel's entry, and the second type's words one per entry, zeroed here (the
        // allocation is known from here on; common/specular_list.h).
        const bool listOrder = f.secondTypeListOrder;
        // A pixel is listed once: the list holds at most min(allocation, W x H) entries.
        f.listRows = shader::specularListRows(std::min(f.sphereAllocation, f.width * f.height));
        const uint32_t indexWidth = listOrder ? (f.width + 7) / 8 : 1, indexHeight = listOrder ? (f.height + 7) / 8 : 1;
        f.specularIndex = b.write(b.createTexture("caustics.specularIndex",
                                                  rhi::TextureDesc().setSize(indexWidth, indexHeight).setFormat(rhi::Format::RGBA32_UINT)
                                                      .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage)
                                                      .setDebugName("caustics.specularIndex")));
        if (listOrder) {
            const uint64_t entryBytes = f.wideFixedPoint ? 24 : 12;
            f.radiance2 = b.write(b.createBuffer("caustics.secondTypeBuffer",
                                                 rhi::BufferDesc().setByteSize(uint64_t(f.listRows) * shader::kSpecularListRow * entryBytes)
                                                     .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::CopyDest |
                                                               rhi::BufferUsage::CopySource)
                                                     .setDebugName("caustics.secondTypeBuffer")),
                                  rg::Access::CopyDest);
        }
        f.stats = b.write(f.stats, rg::Access::StorageReadWrite);
        f.sphereAabbs = b.write(f.sphereAabbs, rg::Access::CopyDest);
        CausticFrame h = f;
        return [=](rg::PassContext& ctx) {
            CausticResources::Impl& r = *h.res;
            *h.sphereCapacity = chooseSphereCapacity(r, *h.sphereReadback, h.width, h.height, h.sphereAllocation);
            rhi::ICommandList& cmd = ctx.cmd();
            cmd.fillBuffer(ctx.buffer(h.sphereAabbs), 0);   // every slot the BLAS build reads
            if (h.secondTypeListOrder) cmd.fillBuffer(ctx.buffer(h.radiance2), 0);
            rhi::BindingSetHandle set = r.makeSet(*ctx.device(), r.specularPixelLayout, "caustics.specularPixels",
                PassBindingSet(shader_bindings::kSpecularPixelsBindings, 0)
                    .texture("gObjectId", ctx.texture(objectId))
                    .texture("gOptics", ctx.texture(optics))
                    .buffer("specularPixels", ctx.buffer(h.specularPixels))
                    .buffer("args", ctx.buffer(h.backwardArgs))
                    .buffer("stats", ctx.buffer(h.stats))
                    .texture("specularIndex", ctx.texture(h.specularIndex)));
            if (!set) return;
            const shader::SpecularPixelParams push{h.width, h.height, *h.sphereCapacity, h.secondTypeListOrder ? 1u : 0u};
            cmd.setComputePipeline(r.specularPixelPipeline);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(&push, sizeof(push));
            cmd.dispatch((h.width + 7) / 8, (h.height + 7) / 8, 1);
        };
    });
}

}  // namespace caustics
