#pragma once
// Run-time loading of the D3D12 runtime and the shader compiler (LoadLibrary / dlopen), so the
// library builds and runs everywhere and fails with a message, not a missing-symbol crash.
#include <string>
#include <vector>

#include "caustics/rhi/result.h"

namespace caustics::rhi::d3d12 {

class RuntimeLibrary {
public:
    RuntimeLibrary() = default;
    RuntimeLibrary(RuntimeLibrary&& o) noexcept;
    RuntimeLibrary& operator=(RuntimeLibrary&& o) noexcept;
    RuntimeLibrary(const RuntimeLibrary&) = delete;
    RuntimeLibrary& operator=(const RuntimeLibrary&) = delete;
    ~RuntimeLibrary();

    // Tries each candidate in order; the error lists every candidate and ends with `howToGet`.
    static Result<RuntimeLibrary> open(const std::vector<std::string>& candidates, const std::string& howToGet);

    void* symbol(const char* name) const;
    const std::string& path() const { return path_; }

private:
    void* handle_ = nullptr;
    std::string path_;
};

// Candidate names and the advice for each library the backend needs, per platform.
std::vector<std::string> d3d12LibraryCandidates();
std::vector<std::string> dxcoreLibraryCandidates();
std::vector<std::string> dxcompilerLibraryCandidates();
std::string d3d12LibraryAdvice();
std::string dxcompilerLibraryAdvice();

}  // namespace caustics::rhi::d3d12
