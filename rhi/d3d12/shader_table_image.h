#pragma once
// The bytes of a D3D12 shader table and the DispatchRays regions pointing into it, device-free.
// Layout from rhi::computeShaderTableLayout with D3D12's fixed numbers (DXR spec "Shader tables"):
// 32-byte identifiers, records aligned to D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT (32), tables to
// D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT (64), stride at most 4096. Each record is
// identifier + local data (the local root constants).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "d3d12_headers.h"
#include "caustics/rhi/result.h"
#include "caustics/rhi/shader_table_layout.h"
#include "caustics/rhi/state_object.h"

namespace caustics::rhi::d3d12 {

ShaderTableAlignment d3d12ShaderTableAlignment();

struct ShaderTableImage {
    ShaderTableLayout layout;
    std::vector<uint8_t> bytes;   // layout.totalBytes long, zero where nothing is written
};

// identifierOf returns the 32-byte identifier of an export or hit group, or empty if unknown.
using IdentifierLookup = std::function<std::vector<uint8_t>(const std::string&)>;

Result<ShaderTableImage> buildShaderTableImage(const ShaderTableDesc& desc, uint32_t localDataBytes,
                                               const IdentifierLookup& identifierOf);

// The regions of DispatchRays for a table uploaded at `baseAddress` (a multiple of 64).
D3D12_DISPATCH_RAYS_DESC makeDispatchRaysDesc(const ShaderTableLayout& layout, uint64_t baseAddress, uint32_t width,
                                              uint32_t height, uint32_t depth);

}  // namespace caustics::rhi::d3d12
