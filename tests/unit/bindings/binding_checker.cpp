#include "binding_checker.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace caustics::test {
namespace {

// "<pass>/<file>": a moved pass's own shaders/ folder, else shaders/vulkan/ (docs/shaders.md).
bool isPassOwned(const std::string& sourceDir, const std::string& name) {
    const size_t slash = name.find('/');
    return slash != std::string::npos &&
           std::filesystem::exists(sourceDir + "/passes/" + name.substr(0, slash) + "/shaders/" + name.substr(slash + 1));
}

std::string glslFile(const std::string& sourceDir, const std::string& name) {
    if (!isPassOwned(sourceDir, name)) return "shaders/vulkan/" + name;
    const size_t slash = name.find('/');
    return "passes/" + name.substr(0, slash) + "/shaders/" + name.substr(slash + 1);
}

std::string fileOf(ShaderLanguage language, const std::string& sourceDir, const std::string& name) {
    if (language == ShaderLanguage::Glsl) return glslFile(sourceDir, name);
    if (!isPassOwned(sourceDir, name)) return "shaders/d3d12/" + name + ".hlsl";
    const std::string glsl = glslFile(sourceDir, name);
    return glsl.substr(0, glsl.rfind('.')) + ".hlsl";
}

std::string describe(const DeclaredBinding& b, ShaderLanguage language) {
    const char* setWord = language == ShaderLanguage::Glsl ? "set" : "space";
    return "'" + b.name + "' (" + setWord + " " + std::to_string(b.space) + ", slot " + std::to_string(b.slot) + ", " +
           bindingTypeName(b.type) + (b.arraySize > 1 ? "[" + std::to_string(b.arraySize) + "]" : "") + ")";
}

// Backend-owned register spaces (root_signature_layout.h): draw parameters and local root data.
bool isBackendSpace(uint32_t space) { return space == 998 || space == 1000; }

void checkBinding(const RecordedPipeline& p, ShaderLanguage language, const std::string& where,
                  const DeclaredBinding& b, std::vector<std::string>& errors) {
    if (language == ShaderLanguage::Hlsl && isBackendSpace(b.space)) return;
    const std::string prefix = p.debugName + " / " + where + ": " + describe(b, language);
    if (b.space >= p.layouts.size()) {
        errors.push_back(prefix + ": the C++ pipeline has only " + std::to_string(p.layouts.size()) +
                         " binding layouts (sets/spaces 0.." + std::to_string(int(p.layouts.size()) - 1) + ")");
        return;
    }
    const auto& items = p.layouts[b.space].items;
    auto it = std::find_if(items.begin(), items.end(), [&](const rhi::BindingLayoutItem& i) { return i.slot == b.slot; });
    if (it == items.end()) {
        std::string slots;
        for (const auto& i : items) slots += (slots.empty() ? "" : ", ") + std::to_string(i.slot);
        errors.push_back(prefix + ": the C++ layout " + std::to_string(b.space) + " has no slot " + std::to_string(b.slot) +
                         " (it has slots " + slots + ")");
        return;
    }
    if (it->type != b.type)
        errors.push_back(prefix + ": the C++ layout " + std::to_string(b.space) + " declares slot " + std::to_string(b.slot) +
                         " as " + bindingTypeName(it->type));
    if (it->arraySize != b.arraySize)
        errors.push_back(prefix + ": the C++ layout declares an array of " + std::to_string(it->arraySize));
}

void checkSize(const std::string& what, const std::vector<std::pair<std::string, uint32_t>>& types, uint32_t cpp,
               const std::string& cppField, const std::string& where, std::vector<std::string>& errors) {
    if (types.empty()) return;
    auto largest = *std::max_element(types.begin(), types.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
    if (largest.second != cpp)
        errors.push_back(where + ": the largest " + what + " is " + largest.first + " (" + std::to_string(largest.second) +
                         " bytes) but C++ sets " + cppField + " = " + std::to_string(cpp));
}

}  // namespace

std::optional<std::string> readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> checkPipelineBindings(const RecordedPipeline& p, ShaderLanguage language,
                                               const std::string& sourceDir, const IncludeReader& glslFiles,
                                               size_t* bindingsChecked) {
    std::vector<std::string> errors;
    std::vector<std::pair<std::string, uint32_t>> payloads, attributes;
    std::vector<std::string> seen;
    for (const RecordedShader& shader : p.shaders) {
        if (std::find(seen.begin(), seen.end(), shader.name) != seen.end()) continue;
        seen.push_back(shader.name);
        const std::string where = fileOf(language, sourceDir, shader.name);
        std::optional<std::string> source;
        std::vector<std::string> includeDirs;
        if (language == ShaderLanguage::Glsl) {
            std::string entry = sourceDir + "/" + glslFile(sourceDir, shader.name);
            source = glslFiles(entry);
            // The include path of the GLSL build (passes/CMakeLists.txt), generated bindings included.
            includeDirs = {entry.substr(0, entry.rfind('/')), sourceDir + "/shaders", sourceDir + "/shaders/vulkan",
                           std::string(CAUSTICS_GENERATED_SHADERS_DIR) + "/glsl"};
        } else if (!shader.hlsl.empty()) {
            source = shader.hlsl;
        }
        if (!source) {
            errors.push_back(p.debugName + ": " + where + " does not exist");
            continue;
        }
        ShaderInterface iface = readShaderInterface(language, *source, includeDirs, glslFiles);
        for (const std::string& problem : iface.problems) errors.push_back(p.debugName + " / " + where + ": " + problem);
        for (const DeclaredBinding& b : iface.bindings) checkBinding(p, language, where, b, errors);
        if (bindingsChecked) *bindingsChecked += iface.bindings.size();
        if (iface.pushConstantBytes && *iface.pushConstantBytes != p.pushConstantBytes)
            errors.push_back(p.debugName + " / " + where + ": the push-constant block is " +
                             std::to_string(*iface.pushConstantBytes) + " bytes but C++ sets pushConstantBytes = " +
                             std::to_string(p.pushConstantBytes));
        payloads.insert(payloads.end(), iface.payloads.begin(), iface.payloads.end());
        attributes.insert(attributes.end(), iface.attributes.begin(), iface.attributes.end());
    }
    if (p.kind == PipelineKind::RayTracing) {
        const std::string where = p.debugName + " (" + (language == ShaderLanguage::Glsl ? "GLSL" : "HLSL") + ")";
        checkSize("ray payload", payloads, p.maxPayloadBytes, "maxPayloadBytes", where, errors);
        checkSize("hit attribute", attributes, p.maxAttributeBytes, "maxAttributeBytes", where, errors);
    }
    return errors;
}

}  // namespace caustics::test
