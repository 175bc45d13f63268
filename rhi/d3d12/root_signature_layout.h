#pragma once
// Root signatures from RHI binding layouts, device-free. The convention (docs/d3d12.md):
//  - global root signature, parameter 0: the push-constant block as root constants in register
//    b0, space kPushConstantSpace (999), when PipelineBindings::pushConstantBytes > 0;
//  - then for binding layout i, in order: its CBV/SRV/UAV descriptor table, then its sampler table,
//    each range in register space i at the register given by the item's slot;
//  - local root signature (shader records): root constants of localDataBytes / 4 values in
//    register b0, space kLocalDataSpace (1000), right after the 32-byte shader identifier.
// HLSL side: `ConstantBuffer<Push> push : register(b0, space999);`,
//            `ConstantBuffer<Local> local : register(b0, space1000);`.
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "d3d12_headers.h"
#include "descriptor_layout.h"

namespace caustics::rhi::d3d12 {

constexpr uint32_t kPushConstantSpace = 999;
constexpr uint32_t kLocalDataSpace = 1000;
// Graphics only: {base vertex, first instance} of the current draw as root constants in b0, space998
// (HLSL: `ConstantBuffer<DrawParameters> drawParams : register(b0, space998);`), set at every draw.
constexpr uint32_t kDrawParametersSpace = 998;
constexpr uint32_t kMaxPushConstantBytes = 128;   // Vulkan's guaranteed minimum; the RHI contract

enum class RootSignatureKind : uint8_t {
    Compute,          // compute and ray tracing (global)
    Graphics,         // adds ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT
    LocalRayTracing,  // D3D12_ROOT_SIGNATURE_FLAG_LOCAL_ROOT_SIGNATURE
};

struct RootDescriptorRange {
    RegisterClass registerClass = RegisterClass::Cbv;
    uint32_t baseRegister = 0;
    uint32_t count = 1;
    uint32_t space = 0;
    uint32_t tableOffset = 0;   // OffsetInDescriptorsFromTableStart
};

struct RootParameterLayout {
    enum class Kind : uint8_t { DescriptorTable, Constants } kind = Kind::DescriptorTable;
    D3D12_SHADER_VISIBILITY visibility = D3D12_SHADER_VISIBILITY_ALL;
    std::vector<RootDescriptorRange> ranges;   // DescriptorTable
    bool samplerTable = false;                 // DescriptorTable: sampler heap, else CBV/SRV/UAV heap
    uint32_t bindingLayoutIndex = 0;           // DescriptorTable: which binding layout feeds it
    uint32_t shaderRegister = 0, registerSpace = 0, num32BitValues = 0;   // Constants
};

struct RootSignatureLayout {
    RootSignatureKind kind = RootSignatureKind::Compute;
    std::vector<RootParameterLayout> parameters;
    int32_t pushConstantParameter = -1;
    int32_t drawParametersParameter = -1;   // Graphics: the last parameter
    // Per binding layout: root parameter index of its resource / sampler table, -1 if it has none.
    std::vector<int32_t> resourceTableParameter, samplerTableParameter;
    std::vector<DescriptorTableLayout> tables;   // per binding layout
};

D3D12_SHADER_VISIBILITY toShaderVisibility(ShaderStage stages);

Result<RootSignatureLayout> rootSignatureLayoutFromBindings(std::span<const BindingLayoutDesc> layouts,
                                                            uint32_t pushConstantBytes,
                                                            RootSignatureKind kind = RootSignatureKind::Compute);
Result<RootSignatureLayout> localRootSignatureLayout(uint32_t localDataBytes);

// Owns the D3D12_VERSIONED_ROOT_SIGNATURE_DESC (version 1.1) of a layout and everything it points to.
class RootSignatureDescStorage {
public:
    explicit RootSignatureDescStorage(const RootSignatureLayout& layout);
    RootSignatureDescStorage(const RootSignatureDescStorage&) = delete;
    RootSignatureDescStorage& operator=(const RootSignatureDescStorage&) = delete;
    const D3D12_VERSIONED_ROOT_SIGNATURE_DESC& desc() const { return desc_; }

private:
    std::vector<D3D12_ROOT_PARAMETER1> parameters_;
    std::deque<std::vector<D3D12_DESCRIPTOR_RANGE1>> ranges_;   // deque: stable addresses
    D3D12_VERSIONED_ROOT_SIGNATURE_DESC desc_{};
};

}  // namespace caustics::rhi::d3d12
