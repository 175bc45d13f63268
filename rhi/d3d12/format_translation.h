#pragma once
// rhi::Format -> DXGI_FORMAT, device-free. Depth formats have three faces in D3D12: a typeless
// resource format (so one texture can be both a depth target and a shader resource), a DSV format and
// an SRV format (D3D12 "Format support for typed UAV/SRV"; DXGI_FORMAT docs).
#include "d3d12_headers.h"
#include "caustics/rhi/format.h"

namespace caustics::rhi::d3d12 {

// The view format for colour textures and buffers; DXGI_FORMAT_UNKNOWN where D3D12 has none.
DXGI_FORMAT toDxgiFormat(Format format);
// The format to create the resource with (typeless for depth so it can also be sampled).
DXGI_FORMAT toDxgiResourceFormat(Format format);
// The format of a shader-resource view of the texture (depth read as R32_FLOAT / R24_UNORM_X8).
DXGI_FORMAT toDxgiSrvFormat(Format format);
// The format of a depth-stencil view; DXGI_FORMAT_UNKNOWN for colour formats.
DXGI_FORMAT toDxgiDsvFormat(Format format);

}  // namespace caustics::rhi::d3d12
