#pragma once
// Byte sizes of shader structs read from source text, under the packing rule that applies where the
// struct is used: GLSL push constants (std430), HLSL constant buffers / root constants (16-byte
// registers a vector may not straddle), and ray payloads / attributes (4-byte scalar packing, what
// D3D12_RAYTRACING_SHADER_CONFIG sizes count). Sizes end at the last member (no tail padding): the
// bytes a push must provide.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace caustics::test {

enum class LayoutRules : uint8_t { Std430, HlslCbuffer, Scalar };

struct StructMember {
    std::string type;
    uint32_t count = 1;   // array length
};
using StructTable = std::map<std::string, std::vector<StructMember>>;

// Every `struct Name { ... };` in the (preprocessed) text.
StructTable readStructs(const std::string& text);

struct StructLayoutResult {
    uint32_t bytes = 0;
    uint32_t alignment = 4;
    std::string problem;   // names the type that could not be sized
};

// `type` is a struct name, a built-in (uint, float3, vec4, float4x4, ...) or a `{ members }` body.
StructLayoutResult structSize(const std::string& type, const StructTable& structs, LayoutRules rules);

}  // namespace caustics::test
