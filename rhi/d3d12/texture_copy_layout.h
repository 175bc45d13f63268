#pragma once
// Texture <-> buffer copy footprints, device-free. D3D12 copies between a texture subresource and a
// buffer through a placed footprint whose rows are D3D12_TEXTURE_DATA_PITCH_ALIGNMENT (256) bytes
// apart and whose offset is a multiple of D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT (512)
// (D3D12 docs, "D3D12_PLACED_SUBRESOURCE_FOOTPRINT"; CopyTextureRegion). The RHI's writeTexture and
// copyTextureToBuffer use tightly packed rows instead, so the backend repacks through a pitched
// staging buffer unless the tight layout already satisfies both alignments.
#include <cstdint>
#include <span>

#include "caustics/rhi/resources.h"
#include "caustics/rhi/result.h"

namespace caustics::rhi::d3d12 {

constexpr uint64_t kTexturePitchAlignment = 256;       // D3D12_TEXTURE_DATA_PITCH_ALIGNMENT
constexpr uint64_t kTexturePlacementAlignment = 512;   // D3D12_TEXTURE_DATA_PLACEMENT_ALIGNMENT

struct TextureCopyLayout {
    uint32_t width = 0, height = 0;   // of the mip level
    uint32_t subresource = 0;         // D3D12CalcSubresource(mip, layer, 0, mipLevels, arrayLayers)
    uint64_t tightRowBytes = 0;       // width x bytes per pixel: the RHI's row size
    uint64_t tightBytes = 0;          // tightRowBytes x height
    uint64_t rowPitch = 0;            // tightRowBytes aligned up to 256: the footprint's RowPitch
    uint64_t stagingBytes = 0;        // rowPitch x height: a staging buffer holding the footprint
};

// Fails for an out-of-range mip/layer or a format without a byte size (Unknown).
Result<TextureCopyLayout> textureCopyLayout(const TextureDesc& desc, uint32_t layer, uint32_t mip);

// Whether a footprint can point straight at `bufferOffset` of the caller's buffer: tight rows already
// have the pitch alignment and the offset the placement alignment.
bool copyNeedsNoRepack(const TextureCopyLayout& layout, uint64_t bufferOffset);

// Tight rows -> pitched rows (writeTexture) and back (copyTextureToBuffer read on the CPU side).
// `pitched` holds stagingBytes, `tight` holds tightBytes.
void packRowsToPitch(const TextureCopyLayout& layout, std::span<const uint8_t> tight, std::span<uint8_t> pitched);
void unpackRowsFromPitch(const TextureCopyLayout& layout, std::span<const uint8_t> pitched, std::span<uint8_t> tight);

}  // namespace caustics::rhi::d3d12
