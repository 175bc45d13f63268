// Device-free parts of d3d12_interop.h: the feature check of a host's device, the RHI state of a
// host's D3D12_RESOURCE_STATES, and the RHI desc of a host's texture. Unit-tested on Linux
// (tests/unit/d3d12/interop_checks_test.cpp).
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "caustics/rhi/d3d12_interop.h"
#include "d3d12_headers.h"
#include "format_translation.h"
#include "resource_states.h"

namespace caustics::rhi {
namespace {

std::string hex(uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof(text), "0x%X", v);
    return text;
}

std::string shaderModelName(uint32_t model) {
    return std::to_string(model >> 4) + "." + std::to_string(model & 0xF);
}

}  // namespace

Status checkD3D12DeviceRequirements(const D3D12FeatureReport& report, bool requireRayTracing,
                                    std::string_view deviceName) {
    std::vector<std::string> missing;
    if (requireRayTracing && report.raytracingTier < uint32_t(D3D12_RAYTRACING_TIER_1_0))
        missing.push_back("DXR: RaytracingTier 1.0 (device reports " +
                          (report.raytracingTier == 0 ? std::string("NOT_SUPPORTED")
                                                      : std::to_string(report.raytracingTier / 10) + "." +
                                                            std::to_string(report.raytracingTier % 10)) + ")");
    // Ray-tracing passes compile as lib_6_3 libraries, compute and raster as *_6_0 (shader_compile_options.cpp).
    const uint32_t neededModel = requireRayTracing ? uint32_t(D3D_SHADER_MODEL_6_3) : uint32_t(D3D_SHADER_MODEL_6_0);
    if (report.highestShaderModel < neededModel)
        missing.push_back("shader model " + shaderModelName(neededModel) + " (device reports " +
                          shaderModelName(report.highestShaderModel) + ")");
    if (requireRayTracing && !report.typedUavLoadAdditionalFormats)
        missing.push_back("TypedUAVLoadAdditionalFormats (RGBA16F and RGBA32F storage-texture loads; device reports none)");
    if (missing.empty()) return okStatus();
    std::string message = "d3d12: host device '" + std::string(deviceName) + "' cannot run the module: missing ";
    for (size_t i = 0; i < missing.size(); ++i) message += (i ? "; " : "") + missing[i];
    return makeError(message);
}

Result<ResourceState> resourceStateFromD3D12(uint32_t states) {
    if (states == D3D12_RESOURCE_STATE_COMMON) return ResourceState::Common;   // == PRESENT
    struct Bit {
        uint32_t d3d12;
        ResourceState rhi;
    };
    const Bit bits[] = {
        {D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER, ResourceState::VertexBuffer | ResourceState::ConstantBuffer},
        {D3D12_RESOURCE_STATE_INDEX_BUFFER, ResourceState::IndexBuffer},
        {D3D12_RESOURCE_STATE_RENDER_TARGET, ResourceState::RenderTarget},
        {D3D12_RESOURCE_STATE_UNORDERED_ACCESS, ResourceState::UnorderedAccess},
        {D3D12_RESOURCE_STATE_DEPTH_WRITE, ResourceState::DepthWrite},
        {D3D12_RESOURCE_STATE_DEPTH_READ, ResourceState::DepthRead},
        {D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE | D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE,
         ResourceState::ShaderResource},
        {D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT, ResourceState::IndirectArgument},
        {D3D12_RESOURCE_STATE_COPY_DEST, ResourceState::CopyDest},
        {D3D12_RESOURCE_STATE_COPY_SOURCE, ResourceState::CopySource},
        {D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE, ResourceState::AccelStructRead},
    };
    ResourceState state = ResourceState::Undefined;
    uint32_t covered = 0;
    for (const Bit& b : bits)
        if (states & b.d3d12) {
            state = state | b.rhi;
            covered |= states & b.d3d12;
        }
    if (covered != states)
        return makeError("d3d12: D3D12_RESOURCE_STATES " + hex(states) + " has bits " + hex(states & ~covered) +
                         " the RHI has no state for (stream out, resolve, shading rate, video)");
    // The RHI's barriers start from toD3D12States(state): it must give back exactly the host's state,
    // or the first transition would name a wrong StateBefore (e.g. PIXEL_SHADER_RESOURCE alone).
    const uint32_t roundTrip = uint32_t(d3d12::toD3D12States(state));
    if (roundTrip != states)
        return makeError("d3d12: D3D12_RESOURCE_STATES " + hex(states) + " is not one the RHI reproduces (nearest: " +
                         hex(roundTrip) + "); transition the resource to " + hex(roundTrip) + " before importing it");
    return state;
}

Result<TextureDesc> textureDescFromD3D12(const D3D12TextureFacts& facts, TextureUsage uses, bool cube,
                                         const std::string& debugName) {
    const std::string what = "d3d12: cannot import texture '" + debugName + "'";
    if (facts.dimension != uint32_t(D3D12_RESOURCE_DIMENSION_TEXTURE2D))
        return makeError(what + ": only D3D12_RESOURCE_DIMENSION_TEXTURE2D resources are textures here (got dimension " +
                         std::to_string(facts.dimension) + ")");
    if (facts.width == 0 || facts.width > UINT32_MAX || facts.height == 0)
        return makeError(what + ": size " + std::to_string(facts.width) + "x" + std::to_string(facts.height));
    std::optional<Format> format;
    for (uint32_t f = uint32_t(Format::R8_UNORM); f <= uint32_t(kLastFormat) && !format; ++f)
        if (Format(f) != Format::RGB32_FLOAT &&
            (uint32_t(d3d12::toDxgiFormat(Format(f))) == facts.dxgiFormat ||
             uint32_t(d3d12::toDxgiResourceFormat(Format(f))) == facts.dxgiFormat))
            format = Format(f);
    if (!format) return makeError(what + ": DXGI_FORMAT " + std::to_string(facts.dxgiFormat) + " has no RHI format");
    if (cube && facts.arrayLayers % 6 != 0)
        return makeError(what + ": a cube needs a multiple of 6 array layers, got " + std::to_string(facts.arrayLayers));

    struct Rule {
        TextureUsage use;
        const char* useName;
        uint32_t flag;
        bool denied;   // the flag forbids the use instead of allowing it
        const char* flagName;
    };
    const Rule rules[] = {
        {TextureUsage::Storage, "Storage", D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS, false,
         "D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS"},
        {TextureUsage::RenderTarget, "RenderTarget", D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET, false,
         "D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET"},
        {TextureUsage::DepthStencil, "DepthStencil", D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL, false,
         "D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL"},
        {TextureUsage::Sampled, "Sampled", D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE, true,
         "D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE"},
    };
    std::string problems;
    for (const Rule& r : rules) {
        if (!hasAny(uses, r.use)) continue;
        const bool has = (facts.flags & r.flag) != 0;
        if (has == r.denied)
            problems += std::string(problems.empty() ? "" : "; ") + "use " + r.useName +
                        (r.denied ? " is forbidden by " : " needs ") + r.flagName;
    }
    if (!problems.empty()) return makeError(what + ": " + problems);

    TextureDesc desc;
    desc.dimension = cube ? TextureDimension::TextureCube
                   : facts.arrayLayers > 1 ? TextureDimension::Texture2DArray : TextureDimension::Texture2D;
    desc.width = uint32_t(facts.width);
    desc.height = facts.height;
    desc.arrayLayers = facts.arrayLayers;
    desc.mipLevels = facts.mipLevels;
    desc.format = *format;
    desc.usage = uses;
    desc.debugName = debugName;
    return desc;
}

}  // namespace caustics::rhi
