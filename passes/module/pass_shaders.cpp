#include "caustics/pass_shaders.h"

#include <cstring>
#include <string>

namespace caustics::pass_shaders {

Result<rhi::ShaderCode> shaderCode(std::string_view name) {
    std::span<const uint32_t> words = spirv(name);
    if (words.empty()) return makeError("caustics: no embedded shader named '" + std::string(name) + "'");
    rhi::ShaderCode code;
    code.kind = rhi::ShaderCodeKind::SPIRV;
    code.bytes.resize(words.size_bytes());
    std::memcpy(code.bytes.data(), words.data(), words.size_bytes());
    code.debugName = std::string(name);
    return code;
}

}  // namespace caustics::pass_shaders
