#pragma once
// What a GLSL or HLSL shader declares about its interface, read from its text: resource bindings
// (GLSL `layout(set=, binding=)`, HLSL `register(tN/uN/bN/sN, spaceM)`), the push-constant block and
// the ray payload / hit attribute types with their sizes. A small preprocessor runs first (object-like
// #define, #undef, #ifdef/#ifndef/#if defined/#elif/#else/#endif, GLSL #include "..."), so macros
// such as SCENE_NO_TLAS or CAUSTICS_STAGE_FRAG resolve as the compiler would resolve them.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "caustics/rhi/binding.h"

namespace caustics::test {

enum class ShaderLanguage : uint8_t { Glsl, Hlsl };

struct DeclaredBinding {
    uint32_t space = 0;     // GLSL set / HLSL register space
    uint32_t slot = 0;      // GLSL binding / HLSL register number
    rhi::BindingType type = rhi::BindingType::ConstantBuffer;
    uint32_t arraySize = 1;
    std::string name;       // the variable or block name, for messages
    std::string spelling;   // the declaration as written (after macro expansion)
};

struct ShaderInterface {
    std::vector<DeclaredBinding> bindings;
    std::optional<uint32_t> pushConstantBytes;   // the push-constant block (GLSL std430 / HLSL cbuffer rules)
    std::vector<std::pair<std::string, uint32_t>> payloads;     // payload type -> bytes
    std::vector<std::pair<std::string, uint32_t>> attributes;   // hit attribute type -> bytes
    std::vector<std::string> problems;   // what could not be read (unknown type, bad directive)
};

// Returns the text of a quoted #include target, or nullopt when it does not exist.
using IncludeReader = std::function<std::optional<std::string>(const std::string& path)>;

// `source` is the entry file's text; GLSL includes are resolved against `includeDirs` through `read`
// (HLSL from the embedded sources has its includes inlined already).
ShaderInterface readShaderInterface(ShaderLanguage language, const std::string& source,
                                    const std::vector<std::string>& includeDirs = {}, const IncludeReader& read = {});

const char* bindingTypeName(rhi::BindingType type);

}  // namespace caustics::test
