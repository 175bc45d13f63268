#include "shader_declarations.h"

#include <map>
#include <regex>

#include "shader_preprocessor.h"
#include "struct_layout.h"

namespace caustics::test {
namespace {

using rhi::BindingType;

std::string squeeze(const std::string& s) { return std::regex_replace(s, std::regex("\\s+"), " "); }

uint32_t arrayCount(const std::string& brackets, std::vector<std::string>& problems, const std::string& name) {
    if (brackets.empty()) return 1;
    std::smatch m;
    std::string inner = brackets.substr(1, brackets.size() - 2);
    if (std::regex_match(inner, m, std::regex("\\s*(\\d+)\\s*"))) return uint32_t(std::stoul(m[1]));
    problems.push_back("array size of '" + name + "' is not a number: " + brackets);
    return 1;
}

// layout(...) [qualifiers] uniform|buffer <type or block name> [{ ... }] [name][array];
void readGlslBindings(const std::string& text, const StructTable& structs, ShaderInterface& out) {
    static const std::regex decl(
        "layout\\s*\\(([^)]*)\\)\\s*((?:\\w+\\s+)*?)(uniform|buffer)\\s+"
        "((?:(?:readonly|writeonly|coherent|volatile|restrict|highp|mediump|lowp)\\s+)*)"
        "(\\w+)\\s*(\\{[^}]*\\})?\\s*(\\w*)\\s*(\\[[^\\]]*\\])?\\s*;");
    for (std::sregex_iterator it(text.begin(), text.end(), decl), end; it != end; ++it) {
        const std::smatch& m = *it;
        std::string args = m[1], qualifiers = std::string(m[2]) + " " + std::string(m[4]), storage = m[3],
                    typeName = m[5], block = m[6];
        std::smatch a;
        if (std::regex_search(args, std::regex("push_constant"))) {
            StructLayoutResult size = structSize(block.empty() ? typeName : block, structs, LayoutRules::Std430);
            if (!size.problem.empty()) out.problems.push_back("push constants: " + size.problem);
            out.pushConstantBytes = size.bytes;
            continue;
        }
        DeclaredBinding b;
        b.spelling = squeeze(m.str());
        b.name = m[7].length() ? std::string(m[7]) : typeName;
        if (std::regex_search(args, a, std::regex("\\bset\\s*=\\s*(\\d+)"))) b.space = uint32_t(std::stoul(a[1]));
        if (!std::regex_search(args, a, std::regex("\\bbinding\\s*=\\s*(\\w+)")) || !std::isdigit(a.str(1)[0])) {
            out.problems.push_back("no numeric binding in: " + b.spelling);
            continue;
        }
        b.slot = uint32_t(std::stoul(a[1]));
        b.arraySize = arrayCount(m[8], out.problems, b.name);
        if (storage == "buffer") {
            b.type = std::regex_search(qualifiers, std::regex("\\breadonly\\b")) ? BindingType::StorageBufferRO
                                                                                 : BindingType::StorageBufferRW;
        } else if (!block.empty()) {
            b.type = BindingType::ConstantBuffer;
        } else if (typeName == "accelerationStructureEXT") {
            b.type = BindingType::AccelStruct;
        } else if (typeName == "sampler") {
            b.type = BindingType::Sampler;
        } else if (std::regex_match(typeName, std::regex("[iu]?image\\w*"))) {
            b.type = BindingType::StorageTexture;
        } else if (std::regex_match(typeName, std::regex("[iu]?(texture|sampler)\\w+"))) {
            b.type = BindingType::SampledTexture;
        } else {
            out.problems.push_back("unknown GLSL resource type '" + typeName + "' in: " + b.spelling);
            continue;
        }
        out.bindings.push_back(b);
    }
    static const std::regex payload("\\b(rayPayloadEXT|rayPayloadInEXT|hitAttributeEXT)\\s+(\\w+)\\s+\\w+\\s*;");
    for (std::sregex_iterator it(text.begin(), text.end(), payload), end; it != end; ++it) {
        StructLayoutResult size = structSize((*it)[2], structs, LayoutRules::Scalar);
        if (!size.problem.empty()) out.problems.push_back(size.problem);
        auto& list = (*it)[1] == "hitAttributeEXT" ? out.attributes : out.payloads;
        list.push_back({(*it)[2], size.bytes});
    }
}

BindingType hlslType(char cls, const std::string& type, bool& ok) {
    ok = true;
    switch (cls) {
        case 'b': ok = type.rfind("ConstantBuffer", 0) == 0; return BindingType::ConstantBuffer;
        case 's': ok = type.rfind("SamplerState", 0) == 0 || type.rfind("SamplerComparisonState", 0) == 0;
                  return BindingType::Sampler;
        case 't':
            if (type == "RaytracingAccelerationStructure") return BindingType::AccelStruct;
            if (type.rfind("Texture", 0) == 0) return BindingType::SampledTexture;
            ok = type == "ByteAddressBuffer" || type.rfind("StructuredBuffer", 0) == 0 || type.rfind("Buffer", 0) == 0;
            return BindingType::StorageBufferRO;
        case 'u':
            if (type.rfind("RWTexture", 0) == 0) return BindingType::StorageTexture;
            ok = type == "RWByteAddressBuffer" || type.rfind("RWStructuredBuffer", 0) == 0 || type.rfind("RWBuffer", 0) == 0;
            return BindingType::StorageBufferRW;
        default: ok = false; return BindingType::ConstantBuffer;
    }
}

void readHlslBindings(const std::string& text, const StructTable& structs, ShaderInterface& out) {
    static const std::regex decl(
        "(\\w+)\\s*(<[^<>;{}()]*>)?\\s+(\\w+)\\s*(\\[[^\\]]*\\])?\\s*:\\s*register\\s*\\(\\s*([btus])(\\d+)\\s*(?:,\\s*space(\\d+))?\\s*\\)");
    for (std::sregex_iterator it(text.begin(), text.end(), decl), end; it != end; ++it) {
        const std::smatch& m = *it;
        DeclaredBinding b;
        b.spelling = squeeze(m.str());
        b.name = m[3];
        b.slot = uint32_t(std::stoul(m[6]));
        b.space = m[7].matched ? uint32_t(std::stoul(m[7])) : 0;
        b.arraySize = arrayCount(m[4], out.problems, b.name);
        bool ok = true;
        b.type = hlslType(std::string(m[5])[0], m[1], ok);
        if (!ok) {
            out.problems.push_back("HLSL type '" + std::string(m[1]) + "' cannot live in register class " +
                                   std::string(m[5]) + ": " + b.spelling);
            continue;
        }
        if (b.space == 999 && b.type == BindingType::ConstantBuffer) {   // push constants (root_signature_layout.h)
            std::string inner = m[2].matched ? std::string(m[2]).substr(1, m[2].length() - 2) : "";
            StructLayoutResult size = structSize(inner, structs, LayoutRules::HlslCbuffer);
            if (!size.problem.empty()) out.problems.push_back("push constants: " + size.problem);
            out.pushConstantBytes = size.bytes;
            continue;
        }
        out.bindings.push_back(b);
    }
    // Payloads and attributes: `inout P payload` / `in A attribs` parameters, and the variable passed
    // to TraceRay / ReportHit.
    auto add = [&](std::vector<std::pair<std::string, uint32_t>>& list, const std::string& type) {
        StructLayoutResult size = structSize(type, structs, LayoutRules::Scalar);
        if (!size.problem.empty()) out.problems.push_back(size.problem);
        list.push_back({type, size.bytes});
    };
    const std::sregex_iterator end;
    static const std::regex entry("\\[shader\\(\"(\\w+)\"\\)\\]\\s*void\\s+\\w+\\s*\\(([^)]*)\\)");
    static const std::regex param("\\b(inout|in)\\s+(\\w+)\\s+\\w+");
    for (std::sregex_iterator it(text.begin(), text.end(), entry); it != end; ++it) {
        const std::string params = (*it)[2];
        for (std::sregex_iterator p(params.begin(), params.end(), param); p != end; ++p)
            add((*p)[1] == "inout" ? out.payloads : out.attributes, (*p)[2]);
    }
    static const std::regex call("\\b(TraceRay|ReportHit)\\s*\\(([^;]*),\\s*(\\w+)\\s*\\)\\s*;");
    for (std::sregex_iterator it(text.begin(), text.end(), call); it != end; ++it) {
        std::string var = (*it)[3], type;
        const std::regex declaration("\\b(\\w+)\\s+" + var + "\\s*[;=]");
        for (std::sregex_iterator v(text.begin(), text.end(), declaration); v != end && type.empty(); ++v)
            if ((*v)[1] != "return") type = (*v)[1];
        if (type.empty()) {
            out.problems.push_back("cannot find the type of '" + var + "' passed to " + std::string((*it)[1]));
            continue;
        }
        add((*it)[1] == "TraceRay" ? out.payloads : out.attributes, type);
    }
}

}  // namespace

const char* bindingTypeName(BindingType type) {
    switch (type) {
        case BindingType::ConstantBuffer: return "ConstantBuffer";
        case BindingType::StorageBufferRO: return "StorageBufferRO";
        case BindingType::StorageBufferRW: return "StorageBufferRW";
        case BindingType::SampledTexture: return "SampledTexture";
        case BindingType::StorageTexture: return "StorageTexture";
        case BindingType::Sampler: return "Sampler";
        case BindingType::AccelStruct: return "AccelStruct";
    }
    return "?";
}

ShaderInterface readShaderInterface(ShaderLanguage language, const std::string& source,
                                    const std::vector<std::string>& includeDirs, const IncludeReader& read) {
    std::map<std::string, std::string> predefined;
    if (language == ShaderLanguage::Hlsl) predefined["__HLSL_VERSION"] = "2021";
    PreprocessedShader pre = preprocessShader(source, predefined, includeDirs, read);
    ShaderInterface out;
    out.problems = pre.problems;
    StructTable structs = readStructs(pre.text);
    if (language == ShaderLanguage::Glsl) readGlslBindings(pre.text, structs, out);
    else readHlslBindings(pre.text, structs, out);
    return out;
}

}  // namespace caustics::test
