// The sphere structure's capacity (caustics/sphere_capacity.h): the policy, the per-slot read-back of the sphere count
// and the pass that copies it (caustics.sphereCount).
#include "caustics/sphere_capacity.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "backward_trace/shaders/backward.h"
#include "caustic_maps/caustic_internal.h"

namespace caustics {

static_assert(kMaxSpheresPerPixel == shader::kBackwardMaxSpheres, "the capacity follows the backward launch's branches");

uint32_t sphereSlotLimit(uint32_t pixels) { return uint32_t(std::min<uint64_t>(uint64_t(pixels) * kMaxSpheresPerPixel, UINT32_MAX)); }

uint32_t sphereTlasCapacity(std::optional<uint32_t> earlierCount, uint32_t slotLimit) {
    if (!earlierCount) return slotLimit;
    if (*earlierCount == 0) return 0;   // nothing to build or gather (caustics/sphere_capacity.h)
    const uint64_t wanted = uint64_t(std::ceil(double(*earlierCount) * kSphereCapacityHeadroom));
    const uint64_t bucket = std::max<uint64_t>(std::bit_ceil(std::max<uint64_t>(wanted, 1)) / 8, 1);
    const uint64_t rounded = (wanted + bucket - 1) / bucket * bucket;
    return uint32_t(std::min<uint64_t>(std::max<uint64_t>(rounded, kMinSphereCapacity), slotLimit));
}

uint32_t initialSphereAllocation(uint32_t pixels, double specularCoverage) {
    const double seen = std::clamp(specularCoverage, 0.0, 1.0) * kSpecularCoverageMargin * double(pixels);
    const uint32_t limit = sphereSlotLimit(pixels);
    const uint32_t estimate = uint32_t(std::min(seen, double(limit)));
    const uint32_t bucketed = estimate == 0 ? 0 : sphereTlasCapacity(uint32_t(estimate / kSphereCapacityHeadroom), limit);
    return std::min(limit, std::max(kMinSphereAllocation, bucketed));
}

uint32_t grownSphereAllocation(uint32_t allocated, uint32_t wanted, uint32_t initial, uint32_t slotLimit) {
    return std::max({allocated, std::min(initial, slotLimit), std::min(wanted, slotLimit)});
}

void prepareSphereBudget(CausticFrame& f) {
    std::vector<SphereCountReadback>& slots = f.res->sphereCounts[f.history->viewId];
    slots.resize(f.res->frameSets.size());
    SphereCountReadback& slot = slots[f.res->frameSlot];
    if (!slot.buffer) {
        auto buffer = f.res->device->createBuffer(rhi::BufferDesc().setByteSize(8).setUsage(rhi::BufferUsage::CopyDest)
                                                      .setMemory(rhi::MemoryType::Readback)
                                                      .setDebugName("caustics.sphereCountReadback"));
        if (buffer) slot.buffer = buffer.value();   // without it every frame builds over its allocation
    }
    f.sphereReadback = &slot;
    // The slots this frame's sphere list and AABB list have (ensureSizeResources sized the sphere BLAS
    // for at least as many).
    f.sphereAllocation = std::min(f.res->sphereSlots, sphereSlotLimit(f.width * f.height));
    f.sphereCapacity = std::make_shared<uint32_t>(f.sphereAllocation);
}

uint32_t chooseSphereCapacity(CausticResources::Impl& res, const SphereCountReadback& slot, uint32_t width,
                              uint32_t height, uint32_t allocation) {
    std::optional<uint32_t> earlier;
    uint32_t counts[2] = {0, 0};   // specular pixels, spheres
    if (slot.buffer && slot.recorded && slot.width == width && slot.height == height &&
        res.device->readBuffer(slot.buffer, counts, sizeof(counts)))
        earlier = std::max(counts[0], counts[1]);
    const uint32_t capacity = sphereTlasCapacity(earlier, sphereSlotLimit(width * height));
    // More than allocated: this frame drops the excess (counted), the next graph built grows the allocation.
    if (earlier && capacity > allocation) res.sphereAllocationWanted = std::max(res.sphereAllocationWanted, capacity);
    return std::min(capacity, allocation);
}

void addSphereCountReadbackPass(rg::RenderGraph& graph, CausticFrame& f) {
    graph.addPass("caustics.sphereCount", [&](rg::PassBuilder& b) {
        f.stats = b.read(f.stats, rg::Access::CopySource);
        b.setSideEffects();   // writes a host-visible buffer the graph does not track
        rg::RgBuffer stats = f.stats;
        SphereCountReadback* readback = f.sphereReadback;
        const uint32_t width = f.width, height = f.height;
        return [=](rg::PassContext& ctx) {
            if (!readback->buffer) return;
            // The specular pixels and the spheres: the list is cut at the capacity, its count is not, so
            // a frame that dropped launches still asks for a slot per pixel; one that did not, for its
            // spheres (up to kMaxSpheresPerPixel a pixel).
            ctx.cmd().copyBuffer(readback->buffer, 0, ctx.buffer(stats), uint64_t(kStatSpecularPixels) * 4, 4);
            ctx.cmd().copyBuffer(readback->buffer, 4, ctx.buffer(stats), uint64_t(kStatSpheres) * 4, 4);
            readback->width = width;
            readback->height = height;
            readback->recorded = true;
        };
    });
}

}  // namespace caustics
