#include "shader_compiler.h"

#include <memory>

#include "d3d12_headers.h"
#include "dxc_interface.h"

namespace caustics::rhi::d3d12 {
namespace {

using namespace dxc;

template <typename T>
struct DxcPtr {
    T* p = nullptr;
    ~DxcPtr() { if (p) p->Release(); }
    void** put() { return reinterpret_cast<void**>(&p); }
};

}  // namespace

struct ShaderCompiler::Impl {
    IDxcCompiler3* compiler = nullptr;
};

Result<std::unique_ptr<ShaderCompiler>> ShaderCompiler::create(const RuntimeLibrary& dxcompiler) {
    auto createInstance = reinterpret_cast<DxcCreateInstanceProc>(dxcompiler.symbol("DxcCreateInstance"));
    if (!createInstance) return makeError("d3d12: " + dxcompiler.path() + " has no DxcCreateInstance");
    auto out = std::unique_ptr<ShaderCompiler>(new ShaderCompiler());
    out->impl_ = new Impl();
    if (!succeeded(createInstance(kClsidDxcCompiler, kIidCompiler3, reinterpret_cast<void**>(&out->impl_->compiler))))
        return makeError("d3d12: " + dxcompiler.path() + " could not create IDxcCompiler3 (DXC older than 1.5?)");
    return out;
}

ShaderCompiler::~ShaderCompiler() {
    if (impl_ && impl_->compiler) impl_->compiler->Release();
    delete impl_;
}

Result<std::vector<uint8_t>> ShaderCompiler::compile(const std::string& source, const std::string& debugName,
                                                     const std::vector<std::wstring>& arguments) {
    std::vector<const wchar_t*> args;
    for (const std::wstring& a : arguments) args.push_back(a.c_str());
    DxcBuffer buffer{source.data(), source.size(), kDxcCpUtf8};
    DxcPtr<IDxcOperationResult> result;   // IDxcResult derives from IDxcOperationResult
    HRESULT hr = impl_->compiler->Compile(&buffer, args.data(), UINT32(args.size()), nullptr, kIidResult, result.put());
    if (!succeeded(hr) || !result.p) return makeError("d3d12: dxcompiler failed to run on '" + debugName + "'");
    HRESULT status = 0;
    result.p->GetStatus(&status);
    if (!succeeded(status)) {
        DxcPtr<IDxcBlob> errors;
        std::string text;
        if (succeeded(result.p->GetErrorBuffer(&errors.p)) && errors.p && errors.p->GetBufferSize())
            text.assign(static_cast<const char*>(errors.p->GetBufferPointer()), errors.p->GetBufferSize());
        return makeError("d3d12: HLSL '" + debugName + "' failed to compile:\n" + text);
    }
    DxcPtr<IDxcBlob> object;
    if (!succeeded(result.p->GetResult(&object.p)) || !object.p)
        return makeError("d3d12: dxcompiler returned no DXIL for '" + debugName + "'");
    const auto* bytes = static_cast<const uint8_t*>(object.p->GetBufferPointer());
    return std::vector<uint8_t>(bytes, bytes + object.p->GetBufferSize());
}

}  // namespace caustics::rhi::d3d12
