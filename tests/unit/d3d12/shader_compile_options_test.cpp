#include <gtest/gtest.h>

#include <algorithm>

#include "shader_compile_options.h"

namespace caustics::rhi::d3d12 {
namespace {

TEST(D3D12ShaderCode, RayTracingLibrariesCompileAsLib63) {
    EXPECT_EQ(hlslTargetProfile(ShaderStage::RayGen, true).value(), "lib_6_3");
}

TEST(D3D12ShaderCode, StagesCompileToShaderModel60Profiles) {
    EXPECT_EQ(hlslTargetProfile(ShaderStage::Compute, false).value(), "cs_6_0");
    EXPECT_EQ(hlslTargetProfile(ShaderStage::Vertex, false).value(), "vs_6_0");
    EXPECT_EQ(hlslTargetProfile(ShaderStage::Fragment, false).value(), "ps_6_0");
    EXPECT_FALSE(hlslTargetProfile(ShaderStage::ClosestHit, false).ok());
}

// The 64-bit fixed-point words (InterlockedAdd on uint64) exist only from shader model 6.6 on.
TEST(D3D12ShaderCode, ShaderModel66DevicesCompileAsLib66AndCs66) {
    EXPECT_EQ(hlslTargetProfile(ShaderStage::RayGen, true, 0x66).value(), "lib_6_6");
    EXPECT_EQ(hlslTargetProfile(ShaderStage::Compute, false, 0x66).value(), "cs_6_6");
    EXPECT_EQ(hlslTargetProfile(ShaderStage::RayGen, true, 0x65).value(), "lib_6_3");
    EXPECT_EQ(hlslTargetProfile(ShaderStage::Fragment, false, 0x65).value(), "ps_6_0");
}

// SM 6.6 promises 64-bit atomics only on root-descriptor UAVs; the backend binds the radiance buffers
// through descriptor tables, so OPTIONS11 must say yes too.
TEST(D3D12ShaderCode, WideFixedPointNeedsShaderModel66AndDescriptorHeapInt64Atomics) {
    EXPECT_TRUE(wideFixedPointAtomics({11, 0x66, true}));
    EXPECT_TRUE(wideFixedPointAtomics({10, 0x67, true}));
    EXPECT_FALSE(wideFixedPointAtomics({11, 0x66, false}));
    EXPECT_FALSE(wideFixedPointAtomics({11, 0x65, true}));
    EXPECT_FALSE(wideFixedPointAtomics({}));
}

TEST(D3D12ShaderCode, SpirvIsRefusedWithTheShadersName) {
    ShaderCode code{ShaderCodeKind::SPIRV, {1, 2, 3, 4}, "forward_trace.rgen"};
    Status s = checkShaderCodeKind(code);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("SPIR-V"), std::string::npos);
    EXPECT_NE(s.message().find("forward_trace.rgen"), std::string::npos);
}

TEST(D3D12ShaderCode, DxilAndHlslAreAccepted) {
    EXPECT_TRUE(checkShaderCodeKind({ShaderCodeKind::DXIL, {1}, "a"}).ok());
    EXPECT_TRUE(checkShaderCodeKind({ShaderCodeKind::HLSL, {'x'}, "b"}).ok());
}

TEST(D3D12ShaderCode, LibrariesGetNoEntryPointArgument) {
    auto lib = dxcArguments("lib_6_3", "main", true, false);
    EXPECT_EQ(std::find(lib.begin(), lib.end(), L"-E"), lib.end());
    auto cs = dxcArguments("cs_6_0", "csMain", false, false);
    auto e = std::find(cs.begin(), cs.end(), L"-E");
    ASSERT_NE(e, cs.end());
    EXPECT_EQ(*(e + 1), L"csMain");
}

}  // namespace
}  // namespace caustics::rhi::d3d12
