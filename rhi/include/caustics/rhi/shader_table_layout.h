#pragma once
// Device-free shader-binding-table layout, shared by both backends and unit-tested.
// Rules (DXR spec "Shader tables"; Vulkan vkCmdTraceRaysKHR valid usage):
//   record stride = align(handleSize + max local data in the region, handleAlignment)
//   each region starts at a multiple of baseAlignment; the raygen region holds one record and its
//   size equals its stride (Vulkan requires size == stride for raygen).
#include <cstdint>

namespace caustics::rhi {

struct ShaderTableAlignment {
    uint32_t handleSize = 32;        // Vulkan shaderGroupHandleSize; D3D12 32
    uint32_t handleAlignment = 32;   // Vulkan shaderGroupHandleAlignment; D3D12 32
    uint32_t baseAlignment = 64;     // Vulkan shaderGroupBaseAlignment; D3D12 64
    uint32_t maxStride = 4096;       // Vulkan maxShaderGroupStride; D3D12 4096
};

struct ShaderTableRegion {
    uint64_t offset = 0;   // from the start of the table buffer
    uint64_t stride = 0;
    uint64_t size = 0;     // stride * count (0 when the region is empty)
    uint32_t count = 0;
};

struct ShaderTableLayout {
    ShaderTableRegion rayGen, miss, hitGroup, callable;
    uint64_t totalBytes = 0;
};

struct ShaderTableCounts {
    uint32_t missCount = 0, hitGroupCount = 0, callableCount = 0;
    // The largest local data carried by any record of each region.
    uint32_t rayGenDataBytes = 0, missDataBytes = 0, hitGroupDataBytes = 0, callableDataBytes = 0;
};

// Returns false (and leaves `out` untouched) when a stride would exceed alignment.maxStride.
bool computeShaderTableLayout(const ShaderTableAlignment& alignment, const ShaderTableCounts& counts,
                              ShaderTableLayout& out);

constexpr uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return alignment == 0 ? value : (value + alignment - 1) / alignment * alignment;
}

}  // namespace caustics::rhi
