#pragma once
// How the backend clears a whole texture (ICommandList::clearTexture*), device-free. The RHI hands
// over the texture in CopyDest; D3D12 clears UAVs with ClearUnorderedAccessView{Float,Uint}, render
// targets with ClearRenderTargetView and depth with ClearDepthStencilView, each needing its own state,
// so those paths transition to it and back. Textures that are none of these (sampled + copy only), and
// value kinds a view cannot take (uint bit patterns on a float UAV, uint values on a render target,
// whose clear colour is float), are filled by a buffer -> texture copy of the encoded pixel.
#include <cstdint>
#include <vector>

#include "caustics/rhi/resources.h"

namespace caustics::rhi::d3d12 {

enum class ClearMethod : uint8_t { UavFloat, UavUint, RenderTarget, DepthStencil, Copy };

ClearMethod chooseClearMethod(const TextureDesc& desc, bool uintValues);

// One pixel of `format` holding the value, as a copy source. Float clears convert to the format
// (UNORM: round(saturate(v) x 255); SRGB: IEC 61966-2-1 encode first; 16-bit float: IEEE half, round
// to nearest even; integer formats: the floats' bit patterns, as the RHI says). Uint clears store the
// low bits of each value for integer formats and reinterpret the bits as floats for float formats.
std::vector<uint8_t> encodeClearPixel(Format format, const float value[4]);
std::vector<uint8_t> encodeClearPixel(Format format, const uint32_t value[4]);

uint16_t floatToHalf(float value);

}  // namespace caustics::rhi::d3d12
