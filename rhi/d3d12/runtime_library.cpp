#include "runtime_library.h"

#include <utility>

#if defined(_WIN32)
#include <windows.h>
#else
#include <dlfcn.h>
#endif

namespace caustics::rhi::d3d12 {

RuntimeLibrary::RuntimeLibrary(RuntimeLibrary&& o) noexcept
    : handle_(std::exchange(o.handle_, nullptr)), path_(std::move(o.path_)) {}

RuntimeLibrary& RuntimeLibrary::operator=(RuntimeLibrary&& o) noexcept {
    std::swap(handle_, o.handle_);
    std::swap(path_, o.path_);
    return *this;
}

RuntimeLibrary::~RuntimeLibrary() {
    if (!handle_) return;
#if defined(_WIN32)
    FreeLibrary(static_cast<HMODULE>(handle_));
#else
    dlclose(handle_);
#endif
}

Result<RuntimeLibrary> RuntimeLibrary::open(const std::vector<std::string>& candidates, const std::string& howToGet) {
    std::string tried;
    for (const std::string& name : candidates) {
#if defined(_WIN32)
        void* h = reinterpret_cast<void*>(LoadLibraryA(name.c_str()));
#else
        void* h = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
#endif
        if (h) {
            RuntimeLibrary lib;
            lib.handle_ = h;
            lib.path_ = name;
            return lib;
        }
        tried += (tried.empty() ? "" : ", ") + name;
    }
    return makeError("could not load " + candidates.front() + " (tried " + tried + "). " + howToGet);
}

void* RuntimeLibrary::symbol(const char* name) const {
    if (!handle_) return nullptr;
#if defined(_WIN32)
    return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(handle_), name));
#else
    return dlsym(handle_, name);
#endif
}

std::vector<std::string> d3d12LibraryCandidates() {
#if defined(_WIN32)
    return {"d3d12.dll"};
#else
    // WSL2 mounts the Windows driver's D3D12 user-mode runtime at /usr/lib/wsl/lib.
    return {"libd3d12.so", "/usr/lib/wsl/lib/libd3d12.so"};
#endif
}

std::vector<std::string> dxcoreLibraryCandidates() {
#if defined(_WIN32)
    return {"dxcore.dll"};
#else
    return {"libdxcore.so", "/usr/lib/wsl/lib/libdxcore.so"};
#endif
}

std::vector<std::string> dxcompilerLibraryCandidates() {
#if defined(_WIN32)
    return {"dxcompiler.dll"};
#else
    return {"libdxcompiler.so", "/usr/lib/wsl/lib/libdxcompiler.so"};
#endif
}

std::string d3d12LibraryAdvice() {
    return "The d3d12 backend needs the Direct3D 12 runtime: d3d12.dll on Windows 10/11, or libd3d12.so under "
           "WSL2 (installed with the Windows GPU driver in /usr/lib/wsl/lib). Native Linux has no D3D12: use "
           "--backend vulkan.";
}

std::string dxcompilerLibraryAdvice() {
    return "The d3d12 backend compiles HLSL with the DirectX Shader Compiler: put dxcompiler.dll (Windows SDK or "
           "a DirectXShaderCompiler release) next to the executable, or libdxcompiler.so from a "
           "DirectXShaderCompiler Linux release on LD_LIBRARY_PATH under WSL2.";
}

}  // namespace caustics::rhi::d3d12
