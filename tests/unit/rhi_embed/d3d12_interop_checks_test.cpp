// Device-free parts of d3d12_interop.h (DirectX-Headers only, no D3D12 runtime): the feature check
// of a host's device, the RHI state of host D3D12_RESOURCE_STATES (round trip through the backend's
// own toD3D12States) and the RHI desc of a host texture with its use checks.
#include <gtest/gtest.h>

#include "caustics/rhi/d3d12_interop.h"
#include "d3d12_headers.h"
#include "resource_states.h"

namespace caustics::rhi {
namespace {

TEST(D3D12DeviceRequirements, DxrTier10ShaderModel63AndTypedUavLoadsAreEnough) {
    EXPECT_TRUE(checkD3D12DeviceRequirements({D3D12_RAYTRACING_TIER_1_0, D3D_SHADER_MODEL_6_3, false, true}, true, "gpu").ok());
}

TEST(D3D12DeviceRequirements, RayTracingWithoutTypedUavLoadsIsRefused) {
    Status s = checkD3D12DeviceRequirements({D3D12_RAYTRACING_TIER_1_0, D3D_SHADER_MODEL_6_3, false, false}, true, "gpu");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("TypedUAVLoadAdditionalFormats"), std::string::npos) << s.message();
}

TEST(D3D12DeviceRequirements, OneErrorNamesEveryMissingFeature) {
    Status s = checkD3D12DeviceRequirements({D3D12_RAYTRACING_TIER_NOT_SUPPORTED, D3D_SHADER_MODEL_6_0}, true, "old gpu");
    ASSERT_FALSE(s.ok());
    for (const char* part : {"'old gpu'", "RaytracingTier 1.0", "NOT_SUPPORTED", "shader model 6.3", "reports 6.0",
                             "TypedUAVLoadAdditionalFormats"})
        EXPECT_NE(s.message().find(part), std::string::npos) << "missing '" << part << "' in: " << s.message();
}

TEST(D3D12DeviceRequirements, WithoutRayTracingShaderModel60Suffices) {
    EXPECT_TRUE(checkD3D12DeviceRequirements({D3D12_RAYTRACING_TIER_NOT_SUPPORTED, D3D_SHADER_MODEL_6_0}, false, "gpu").ok());
}

TEST(D3D12ResourceStates, EveryAcceptedStateRoundTripsThroughTheBackend) {
    for (uint32_t states : {uint32_t(D3D12_RESOURCE_STATE_COMMON), uint32_t(D3D12_RESOURCE_STATE_RENDER_TARGET),
                            uint32_t(D3D12_RESOURCE_STATE_UNORDERED_ACCESS), uint32_t(D3D12_RESOURCE_STATE_DEPTH_WRITE),
                            uint32_t(D3D12_RESOURCE_STATE_DEPTH_READ), uint32_t(D3D12_RESOURCE_STATE_ALL_SHADER_RESOURCE),
                            uint32_t(D3D12_RESOURCE_STATE_COPY_DEST), uint32_t(D3D12_RESOURCE_STATE_COPY_SOURCE),
                            uint32_t(D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE),
                            uint32_t(D3D12_RESOURCE_STATE_ALL_SHADER_RESOURCE | D3D12_RESOURCE_STATE_DEPTH_READ)}) {
        auto state = resourceStateFromD3D12(states);
        ASSERT_TRUE(state.ok()) << states << ": " << state.message();
        EXPECT_EQ(uint32_t(d3d12::toD3D12States(state.value())), states) << states;
    }
}

TEST(D3D12ResourceStates, PartialOrUnknownStatesAreRefusedNamingTheBits) {
    auto pixelOnly = resourceStateFromD3D12(D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE);
    ASSERT_FALSE(pixelOnly.ok());
    EXPECT_NE(pixelOnly.message().find("0xC0"), std::string::npos) << pixelOnly.message();   // the nearest it takes
    auto resolve = resourceStateFromD3D12(D3D12_RESOURCE_STATE_RESOLVE_DEST);
    ASSERT_FALSE(resolve.ok());
    EXPECT_NE(resolve.message().find("0x1000"), std::string::npos) << resolve.message();
}

D3D12TextureFacts facts(DXGI_FORMAT format, D3D12_RESOURCE_FLAGS flags) {
    return {uint32_t(D3D12_RESOURCE_DIMENSION_TEXTURE2D), uint32_t(format), 640, 360, 1, 1, uint32_t(flags)};
}

TEST(D3D12TextureImport, DescCarriesSizeFormatAndUses) {
    auto desc = textureDescFromD3D12(facts(DXGI_FORMAT_R16G16B16A16_FLOAT, D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS),
                                     TextureUsage::Storage | TextureUsage::Sampled, false, "host output");
    ASSERT_TRUE(desc.ok()) << desc.message();
    EXPECT_EQ(desc->width, 640u);
    EXPECT_EQ(desc->height, 360u);
    EXPECT_EQ(desc->format, Format::RGBA16_FLOAT);
    EXPECT_EQ(desc->debugName, "host output");
}

TEST(D3D12TextureImport, TypelessDepthResourceIsTheRhiDepthFormat) {
    auto desc = textureDescFromD3D12(facts(DXGI_FORMAT_R32_TYPELESS, D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL),
                                     TextureUsage::Sampled, false, "host depth");
    ASSERT_TRUE(desc.ok()) << desc.message();
    EXPECT_EQ(desc->format, Format::D32_FLOAT);
}

TEST(D3D12TextureImport, UseTheFlagsForbidIsRefusedNamingTextureAndFlag) {
    auto noUav = textureDescFromD3D12(facts(DXGI_FORMAT_R8G8B8A8_UNORM, D3D12_RESOURCE_FLAG_ALLOW_RENDER_TARGET),
                                      TextureUsage::Storage, false, "host colour");
    ASSERT_FALSE(noUav.ok());
    EXPECT_NE(noUav.message().find("'host colour'"), std::string::npos) << noUav.message();
    EXPECT_NE(noUav.message().find("D3D12_RESOURCE_FLAG_ALLOW_UNORDERED_ACCESS"), std::string::npos) << noUav.message();
    auto denied = textureDescFromD3D12(facts(DXGI_FORMAT_D32_FLOAT, D3D12_RESOURCE_FLAGS(D3D12_RESOURCE_FLAG_ALLOW_DEPTH_STENCIL |
                                                                                          D3D12_RESOURCE_FLAG_DENY_SHADER_RESOURCE)),
                                       TextureUsage::Sampled, false, "host depth");
    ASSERT_FALSE(denied.ok());
    EXPECT_NE(denied.message().find("DENY_SHADER_RESOURCE"), std::string::npos) << denied.message();
}

TEST(D3D12TextureImport, BuffersAndUnknownFormatsAreNotTextures) {
    D3D12TextureFacts buffer = facts(DXGI_FORMAT_UNKNOWN, D3D12_RESOURCE_FLAG_NONE);
    buffer.dimension = uint32_t(D3D12_RESOURCE_DIMENSION_BUFFER);
    EXPECT_FALSE(textureDescFromD3D12(buffer, TextureUsage::Sampled, false, "b").ok());
    auto bc1 = textureDescFromD3D12(facts(DXGI_FORMAT_BC1_UNORM, D3D12_RESOURCE_FLAG_NONE), TextureUsage::Sampled, false, "bc");
    ASSERT_FALSE(bc1.ok());
    EXPECT_NE(bc1.message().find("has no RHI format"), std::string::npos);
}

}  // namespace
}  // namespace caustics::rhi
