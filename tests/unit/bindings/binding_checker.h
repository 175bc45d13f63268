#pragma once
// Checks a pass pipeline's shaders against its C++ description (the truth, pass_pipeline_recorder.h):
// every binding a shader declares must exist in the C++ layout of that set/space with the same slot,
// type and array size; the push-constant block must be exactly PipelineBindings::pushConstantBytes;
// the largest ray payload / hit attribute must be exactly StateObjectDesc::maxPayloadBytes /
// maxAttributeBytes (DXR sizes its stacks from these). Each mismatch is one message naming the
// pipeline, the shader file, the declaration and what C++ says, so whoever changed one side sees
// which other side to change.
#include <optional>
#include <string>
#include <vector>

#include "pass_pipeline_recorder.h"
#include "shader_declarations.h"

namespace caustics::test {

// Reads a file by path; nullopt when it does not exist.
std::optional<std::string> readTextFile(const std::string& path);

// GLSL is read through `glslFiles` (entry points shaders/vulkan/<name> and their includes from
// shaders/vulkan and shaders/ of `sourceDir`); HLSL is the recorded text (what the D3D12 backend
// compiles). Tests plant mismatches through either.
std::vector<std::string> checkPipelineBindings(const RecordedPipeline& pipeline, ShaderLanguage language,
                                               const std::string& sourceDir,
                                               const IncludeReader& glslFiles = readTextFile,
                                               size_t* bindingsChecked = nullptr);

}  // namespace caustics::test
