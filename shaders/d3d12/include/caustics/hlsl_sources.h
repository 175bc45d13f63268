#pragma once
// The HLSL of every pass for the D3D12 backend, embedded at build time (shaders/d3d12/CMakeLists.txt):
// a pass's own passes/<pass>/shaders/<x>.hlsl (docs/shaders.md) once per GLSL entry <x>.<stage> beside
// it, and shaders/d3d12/<pass>/<glsl file name>.hlsl of the passes not yet moved, each stored with its
// includes inlined, so the text compiles on its own with dxcompiler. Names mirror the SPIR-V lookup,
// e.g. source("composite/composite.comp") or source("forward_trace/forward.rgen") (".hlsl" may be
// appended). Every file's entry point is `main` (as in GLSL).
#include <cstddef>
#include <string_view>
#include <vector>

#include "caustics/rhi/shader.h"

namespace caustics::hlsl {

// The self-contained HLSL text; empty if there is no such shader.
std::string_view source(std::string_view name);
// Every embedded name (with the .hlsl suffix), sorted as generated.
std::vector<std::string_view> names();
// ShaderCode{HLSL, text, "<name>.hlsl"} for the D3D12 backend; bytes empty if unknown.
rhi::ShaderCode shaderCode(std::string_view name);

namespace generated {
struct Entry {
    std::string_view name;
    std::string_view text;
};
extern const Entry kEntries[];
extern const size_t kEntryCount;
}  // namespace generated

}  // namespace caustics::hlsl
