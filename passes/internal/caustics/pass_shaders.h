#pragma once
// Shader code of every pass for the device's backend, embedded into caustics_passes at build time:
// SPIR-V compiled from the GLSL entries (passes/CMakeLists.txt) and HLSL text (compiled at run time by
// the D3D12 backend). Looked up as "<pass>/<file>": a pass's own passes/<pass>/shaders/<file>
// (docs/shaders.md), e.g. "composite/composite.comp"; the HLSL entry of the same name mirrors it.
#include <cstdint>
#include <span>
#include <string_view>

#include "caustics/rhi/result.h"
#include "caustics/rhi/device.h"
#include "caustics/rhi/shader.h"
#include "caustics/rhi/state_object.h"

namespace caustics::pass_shaders {

// Empty span when no embedded shader has that name.
std::span<const uint32_t> spirv(std::string_view name);

// The embedded code for `backend` (SPIR-V for Vulkan, HLSL for D3D12); an error naming the shader
// when it is missing.
Result<rhi::ShaderCode> shaderCode(rhi::Backend backend, std::string_view name);

// A ray-tracing library of one file whose entry point `main` is exported as `exportName`.
Result<rhi::ShaderLibraryDesc> shaderLibrary(rhi::Backend backend, std::string_view name, std::string exportName,
                                             rhi::ShaderStage stage);

}  // namespace caustics::pass_shaders
