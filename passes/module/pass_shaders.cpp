#include "caustics/pass_shaders.h"

#include <cstring>
#include <string>

#include "caustics/hlsl_sources.h"

namespace caustics::pass_shaders {

Result<rhi::ShaderCode> shaderCode(rhi::Backend backend, std::string_view name) {
    rhi::ShaderCode code;
    if (backend == rhi::Backend::D3D12) {
        code = hlsl::shaderCode(name);
        if (code.bytes.empty()) return makeError("caustics: no embedded HLSL shader named '" + std::string(name) + "'");
        return code;
    }
    std::span<const uint32_t> words = spirv(name);
    if (words.empty()) return makeError("caustics: no embedded shader named '" + std::string(name) + "'");
    code.kind = rhi::ShaderCodeKind::SPIRV;
    code.bytes.resize(words.size_bytes());
    std::memcpy(code.bytes.data(), words.data(), words.size_bytes());
    code.debugName = std::string(name);
    return code;
}

Result<rhi::ShaderLibraryDesc> shaderLibrary(rhi::Backend backend, std::string_view name, std::string exportName,
                                             rhi::ShaderStage stage) {
    rhi::ShaderLibraryDesc lib;
    CAUSTICS_TRY(lib.code, shaderCode(backend, name));
    lib.exports.push_back({std::move(exportName), "main", stage});
    return lib;
}

}  // namespace caustics::pass_shaders
