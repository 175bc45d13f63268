#pragma once
// The part of DXC's COM interface the backend calls, declared from the official dxcapi.h
// (github.com/microsoft/DirectXShaderCompiler, include/dxc/dxcapi.h) because no DXC headers are
// installed here. Only the vtable order matters: methods are listed in dxcapi.h's order up to the
// last one used, and tests/unit/d3d12/dxc_interface_test.cpp checks each slot against that order.
// The one C entry point is DxcCreateInstance (loaded from dxcompiler at run time).
#include "d3d12_headers.h"

namespace caustics::rhi::d3d12::dxc {

// dxcapi.h's IUnknown. On non-Windows builds DXC's IUnknown (its WinAdapter.h) declares a virtual
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
#if !defined(_WIN32)
inline constexpr int kUnknownSlots = 5;
#else
inline constexpr int kUnknownSlots = 3;
#endif

struct DxcBuffer {
    const void* ptr;
    size_t size;
    UINT encoding;
};
inline constexpr UINT kDxcCpUtf8 = 65001;   // DXC_CP_UTF8

struct IDxcBlob : DxcUnknown {
    virtual void* STDMETHODCALLTYPE GetBufferPointer() = 0;
    virtual size_t STDMETHODCALLTYPE GetBufferSize() = 0;
};
// IDxcResult derives from it; the backend reads results through these three.
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

// GUIDs from dxcapi.h: CLSID_DxcCompiler, IID_IDxcCompiler3, IID_IDxcResult.
inline constexpr GUID kClsidDxcCompiler = {0x73e22d93, 0xe6ce, 0x47f3, {0xb5, 0xbf, 0xf0, 0x66, 0x4f, 0x39, 0xc1, 0xb0}};
inline constexpr GUID kIidCompiler3 = {0x228b4687, 0x5a6a, 0x4730, {0x90, 0x0c, 0x97, 0x02, 0xb2, 0x20, 0x3f, 0x54}};
inline constexpr GUID kIidResult = {0x58346cda, 0xdde7, 0x4497, {0x94, 0x61, 0x6f, 0x87, 0xaf, 0x5e, 0x06, 0x59}};

}  // namespace caustics::rhi::d3d12::dxc
