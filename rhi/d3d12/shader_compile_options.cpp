#include "shader_compile_options.h"

namespace caustics::rhi::d3d12 {

Result<std::string> hlslTargetProfile(ShaderStage stage, bool library) {
    if (library) return std::string("lib_6_3");
    switch (stage) {
        case ShaderStage::Compute: return std::string("cs_6_0");
        case ShaderStage::Vertex: return std::string("vs_6_0");
        case ShaderStage::Fragment: return std::string("ps_6_0");
        default: return makeError("d3d12: ray-tracing stages are compiled as a library (lib_6_3), not alone");
    }
}

Status checkShaderCodeKind(const ShaderCode& code) {
    if (code.kind == ShaderCodeKind::SPIRV)
        return makeError("d3d12 backend: shader '" + code.debugName +
                         "' is SPIR-V; D3D12 takes DXIL or HLSL (compiled at run time with dxcompiler)");
    if (code.bytes.empty()) return makeError("d3d12 backend: shader '" + code.debugName + "' has no code");
    return okStatus();
}

std::vector<std::wstring> dxcArguments(const std::string& profile, const std::string& entryPoint, bool library,
                                       bool debugInfo) {
    auto w = [](const std::string& s) { return std::wstring(s.begin(), s.end()); };
    std::vector<std::wstring> args = {L"-T", w(profile), L"-HV", L"2021"};
    if (!library) {
        args.push_back(L"-E");
        args.push_back(w(entryPoint));
    }
    if (debugInfo) {
        args.push_back(L"-Zi");
        args.push_back(L"-Qembed_debug");
    } else {
        args.push_back(L"-O3");
    }
    return args;
}

}  // namespace caustics::rhi::d3d12
