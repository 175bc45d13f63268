#pragma once
// What the D3D12 backend accepts as shader code and how it asks dxcompiler for it, device-free.
// DXIL is used as is; HLSL is compiled at run time (lib_6_3 for ray-tracing libraries: the first DXR
// shader model; cs/vs/ps_6_0 otherwise); SPIR-V is refused.
#include <string>
#include <vector>

#include "caustics/rhi/result.h"
#include "caustics/rhi/shader.h"

namespace caustics::rhi::d3d12 {

// Target profile for dxcompiler: "lib_6_3" when `library`, else by stage.
Result<std::string> hlslTargetProfile(ShaderStage stage, bool library);

// Ok for DXIL/HLSL; an error naming the shader for SPIR-V or empty code.
Status checkShaderCodeKind(const ShaderCode& code);

// dxcompiler arguments (IDxcCompiler3::Compile): -T profile, -E entry (not for libraries), -HV 2021,
// and debug info (-Zi -Qembed_debug) when asked, -O3 otherwise. Matrix packing stays DXC's default
// (column-major), which is glm's memory order.
std::vector<std::wstring> dxcArguments(const std::string& profile, const std::string& entryPoint, bool library,
                                       bool debugInfo);

}  // namespace caustics::rhi::d3d12
