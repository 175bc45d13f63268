#include "caustics/hlsl_sources.h"

namespace caustics::hlsl {
namespace {

std::string_view withSuffix(std::string_view name, std::string& storage) {
    constexpr std::string_view kSuffix = ".hlsl";
    if (name.size() >= kSuffix.size() && name.substr(name.size() - kSuffix.size()) == kSuffix) return name;
    storage.assign(name);
    storage += kSuffix;
    return storage;
}

}  // namespace

std::string_view source(std::string_view name) {
    std::string storage;
    const std::string_view key = withSuffix(name, storage);
    for (size_t i = 0; i < generated::kEntryCount; ++i)
        if (generated::kEntries[i].name == key) return generated::kEntries[i].text;
    return {};
}

std::vector<std::string_view> names() {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < generated::kEntryCount; ++i) out.push_back(generated::kEntries[i].name);
    return out;
}

rhi::ShaderCode shaderCode(std::string_view name) {
    rhi::ShaderCode code;
    code.kind = rhi::ShaderCodeKind::HLSL;
    std::string storage;
    code.debugName = std::string(withSuffix(name, storage));   // the text's #line markers name the files
    const std::string_view text = source(name);
    code.bytes.assign(text.begin(), text.end());
    return code;
}

}  // namespace caustics::hlsl
