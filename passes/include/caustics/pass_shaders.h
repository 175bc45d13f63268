#pragma once
// SPIR-V of every shader under shaders/vulkan/, embedded into caustics_passes at build time
// (passes/CMakeLists.txt). Look up by the path relative to shaders/vulkan/, e.g. "gbuffer/gbuffer.vert".
#include <cstdint>
#include <span>
#include <string_view>

#include "rhi/result.h"
#include "rhi/shader.h"

namespace caustics::pass_shaders {

// Empty span when no embedded shader has that name.
std::span<const uint32_t> spirv(std::string_view name);

// The embedded SPIR-V as rhi::ShaderCode; an error naming the shader when it is missing.
Result<rhi::ShaderCode> shaderCode(std::string_view name);

}  // namespace caustics::pass_shaders
