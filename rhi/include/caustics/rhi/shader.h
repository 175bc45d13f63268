#pragma once
// Shader code handed to a backend. Vulkan takes SPIR-V; D3D12 takes DXIL, or HLSL that it compiles
// at run time with dxcompiler. One module may hold several entry points (exports).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/rhi/binding.h"

namespace caustics::rhi {

enum class ShaderCodeKind : uint8_t { SPIRV, DXIL, HLSL };

struct ShaderCode {
    ShaderCodeKind kind = ShaderCodeKind::SPIRV;
    std::vector<uint8_t> bytes;
    std::string debugName;   // e.g. the source file, used in every error about this code
};

struct ShaderEntry {
    ShaderCode code;
    std::string entryPoint = "main";
    ShaderStage stage = ShaderStage::Compute;
};

}  // namespace caustics::rhi
