#pragma once
// rhi acceleration-structure descriptions -> D3D12 build inputs (DXR spec "Acceleration structure
// build"), device-free: buffer addresses come from IBuffer::deviceAddress().
#include <vector>

#include "d3d12_headers.h"
#include "caustics/rhi/accel_struct.h"

namespace caustics::rhi::d3d12 {

D3D12_RAYTRACING_GEOMETRY_FLAGS toD3D12GeometryFlags(GeometryFlags flags);
D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAGS toD3D12BuildFlags(AccelBuildFlags flags, bool update);
D3D12_RAYTRACING_GEOMETRY_DESC toD3D12Geometry(const GeometryDesc& geometry);

// Owns the geometry array that `inputs` points to.
struct BottomLevelInputs {
    std::vector<D3D12_RAYTRACING_GEOMETRY_DESC> geometries;
    D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS inputs{};
};
void makeBottomLevelInputs(const AccelStructDesc& desc, bool update, BottomLevelInputs& out);

D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS makeTopLevelInputs(const AccelStructDesc& desc,
                                                                        uint64_t instanceAddress,
                                                                        uint32_t instanceCount, bool update);

}  // namespace caustics::rhi::d3d12
