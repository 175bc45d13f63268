#include "caustics/rhi/shader_table_layout.h"

namespace caustics::rhi {

bool computeShaderTableLayout(const ShaderTableAlignment& alignment, const ShaderTableCounts& counts,
                              ShaderTableLayout& out) {
    auto strideFor = [&](uint32_t dataBytes) {
        return alignUp(uint64_t(alignment.handleSize) + dataBytes, alignment.handleAlignment);
    };
    ShaderTableLayout layout;
    uint64_t cursor = 0;
    auto place = [&](ShaderTableRegion& region, uint32_t count, uint32_t dataBytes) {
        region.count = count;
        region.stride = count ? strideFor(dataBytes) : 0;
        region.size = region.stride * count;
        cursor = alignUp(cursor, alignment.baseAlignment);
        region.offset = count ? cursor : 0;
        cursor += region.size;
        return region.stride <= alignment.maxStride;
    };
    bool fits = place(layout.rayGen, 1, counts.rayGenDataBytes);
    fits &= place(layout.miss, counts.missCount, counts.missDataBytes);
    fits &= place(layout.hitGroup, counts.hitGroupCount, counts.hitGroupDataBytes);
    fits &= place(layout.callable, counts.callableCount, counts.callableDataBytes);
    if (!fits) return false;
    layout.totalBytes = alignUp(cursor, alignment.baseAlignment);
    out = layout;
    return true;
}

}  // namespace caustics::rhi
