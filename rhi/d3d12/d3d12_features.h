#pragma once
// The features the module reads from a D3D12 device (ours or a host's), as the device-free report that
// checkD3D12DeviceRequirements and the capability rules in shader_compile_options.h take.
#include "caustics/rhi/d3d12_interop.h"
#include "d3d12_headers.h"

namespace caustics::rhi::d3d12 {

D3D12FeatureReport queryD3D12Features(ID3D12Device5* device);

// CAUSTICS_FORCE_FIXED_POINT=32 reports no 64-bit atomics on either backend, so the narrow fixed-point
// words can be exercised on a device that has wide ones (docs/d3d12.md).
bool narrowFixedPointForced();

}  // namespace caustics::rhi::d3d12
