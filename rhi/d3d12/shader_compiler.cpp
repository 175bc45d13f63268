#include "shader_compiler.h"

#include <memory>

#include "d3d12_headers.h"

namespace caustics::rhi::d3d12 {
namespace {

// dxcapi.h ABI. On non-Windows builds DXC's own IUnknown (its WinAdapter.h) declares a virtual
// destructor after Release, which the Itanium C++ ABI lays out as two vtable slots; the WSL IUnknown
// of DirectX-Headers has none. So DXC interfaces get their own base with those two slots.
struct DxcUnknown {
    virtual HRESULT STDMETHODCALLTYPE QueryInterface(REFIID riid, void** object) = 0;
    virtual ULONG STDMETHODCALLTYPE AddRef() = 0;
    virtual ULONG STDMETHODCALLTYPE Release() = 0;
#if !defined(_WIN32)
    virtual void reservedCompleteDestructor() = 0;
    virtual void reservedDeletingDestructor() = 0;
#endif
};
struct DxcBuffer {
    const void* ptr;
    size_t size;
    UINT encoding;
};
constexpr UINT kDxcCpUtf8 = 65001;
struct IDxcBlob : DxcUnknown {
    virtual void* STDMETHODCALLTYPE GetBufferPointer() = 0;
    virtual size_t STDMETHODCALLTYPE GetBufferSize() = 0;
};
struct IDxcOperationResult : DxcUnknown {
    virtual HRESULT STDMETHODCALLTYPE GetStatus(HRESULT* status) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetResult(IDxcBlob** result) = 0;
    virtual HRESULT STDMETHODCALLTYPE GetErrorBuffer(IDxcBlob** errors) = 0;   // an IDxcBlobEncoding
};
struct IDxcCompiler3 : DxcUnknown {
    virtual HRESULT STDMETHODCALLTYPE Compile(const DxcBuffer* source, const wchar_t** arguments, UINT32 argCount,
                                              void* includeHandler, REFIID riid, void** result) = 0;
};
using DxcCreateInstanceProc = HRESULT(STDMETHODCALLTYPE*)(REFCLSID, REFIID, void**);

// GUIDs from dxcapi.h.
constexpr GUID kClsidDxcCompiler = {0x73e22d93, 0xe6ce, 0x47f3, {0xb5, 0xbf, 0xf0, 0x66, 0x4f, 0x39, 0xc1, 0xb0}};
constexpr GUID kIidCompiler3 = {0x228b4687, 0x5a6a, 0x4730, {0x90, 0x0c, 0x97, 0x02, 0xb2, 0x20, 0x3f, 0x54}};
constexpr GUID kIidResult = {0x58346cda, 0xdde7, 0x4497, {0x94, 0x61, 0x6f, 0x87, 0xaf, 0x5e, 0x06, 0x59}};

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
