#include "shader_compile_options.h"

namespace caustics::rhi::d3d12 {

namespace {
constexpr uint32_t kShaderModel66 = 0x66;   // D3D_SHADER_MODEL_6_6
}

Result<std::string> hlslTargetProfile(ShaderStage stage, bool library, uint32_t deviceShaderModel) {
    const bool sm66 = deviceShaderModel >= kShaderModel66;
    if (library) return std::string(sm66 ? "lib_6_6" : "lib_6_3");
    const std::string model = sm66 ? "_6_6" : "_6_0";
    switch (stage) {
        case ShaderStage::Compute: return "cs" + model;
        case ShaderStage::Vertex: return "vs" + model;
        case ShaderStage::Fragment: return "ps" + model;
        default: return makeError("d3d12: ray-tracing stages are compiled as a library (lib_6_3), not alone");
    }
}

bool wideFixedPointAtomics(const D3D12FeatureReport& report) {
    return report.highestShaderModel >= kShaderModel66 && report.atomicInt64OnDescriptorHeapResource;
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
