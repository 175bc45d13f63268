#pragma once
// What the D3D12 backend accepts as shader code and how it asks dxcompiler for it, device-free.
// DXIL is used as is; HLSL is compiled at run time (lib_6_3 for ray-tracing libraries: the first DXR
// shader model; cs/vs/ps_6_0 otherwise; *_6_6 on a device of shader model 6.6, which the 64-bit
// fixed-point atomics need); SPIR-V is refused.
#include <string>
#include <vector>

#include "caustics/rhi/d3d12_interop.h"
#include "caustics/rhi/result.h"
#include "caustics/rhi/shader.h"

namespace caustics::rhi::d3d12 {

// Target profile for dxcompiler: "lib_6_3" when `library`, else by stage at 6.0; both at 6.6 when the
// device's highest shader model (D3D_SHADER_MODEL, 0x66 = 6.6) reaches it.
Result<std::string> hlslTargetProfile(ShaderStage stage, bool library, uint32_t deviceShaderModel = 0);

// Whether the caustic passes may accumulate in 64-bit fixed-point words (Capabilities::
// shaderBufferInt64Atomics): SM 6.6 InterlockedAdd on uint64 and, since the radiance buffers are bound
// through descriptor tables, OPTIONS11's AtomicInt64OnDescriptorHeapResourceSupported (docs/d3d12.md).
bool wideFixedPointAtomics(const D3D12FeatureReport& report);

// Ok for DXIL/HLSL; an error naming the shader for SPIR-V or empty code.
Status checkShaderCodeKind(const ShaderCode& code);

// dxcompiler arguments (IDxcCompiler3::Compile): -T profile, -E entry (not for libraries), -HV 2021,
// and debug info (-Zi -Qembed_debug) when asked, -O3 otherwise. Matrix packing stays DXC's default
// (column-major), which is glm's memory order.
std::vector<std::wstring> dxcArguments(const std::string& profile, const std::string& entryPoint, bool library,
                                       bool debugInfo);

}  // namespace caustics::rhi::d3d12
