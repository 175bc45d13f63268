#pragma once
// HLSL -> DXIL through dxcompiler, loaded at run time. The few DXC interfaces used are declared in
// dxc_interface.h from the public dxcapi.h ABI (IDxcCompiler3::Compile, IDxcResult); the compile
// flags come from shader_compile_options.h only.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/rhi/result.h"
#include "runtime_library.h"

namespace caustics::rhi::d3d12 {

class ShaderCompiler {
public:
    // `dxcompiler` must stay loaded while this object lives.
    static Result<std::unique_ptr<ShaderCompiler>> create(const RuntimeLibrary& dxcompiler);
    ~ShaderCompiler();
    Result<std::vector<uint8_t>> compile(const std::string& source, const std::string& debugName,
                                         const std::vector<std::wstring>& arguments);

private:
    ShaderCompiler() = default;
    struct Impl;
    Impl* impl_ = nullptr;
};

}  // namespace caustics::rhi::d3d12
