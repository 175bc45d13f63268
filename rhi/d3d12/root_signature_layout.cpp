#include "root_signature_layout.h"

#include <string>

namespace caustics::rhi::d3d12 {

D3D12_SHADER_VISIBILITY toShaderVisibility(ShaderStage stages) {
    // One stage of the graphics pipeline can be targeted; anything else (compute, ray tracing, or
    // several stages) must be ALL, which is also what DXR requires of state-object root signatures.
    if (stages == ShaderStage::Vertex) return D3D12_SHADER_VISIBILITY_VERTEX;
    if (stages == ShaderStage::Fragment) return D3D12_SHADER_VISIBILITY_PIXEL;
    return D3D12_SHADER_VISIBILITY_ALL;
}

Result<RootSignatureLayout> rootSignatureLayoutFromBindings(std::span<const BindingLayoutDesc> layouts,
                                                            uint32_t pushConstantBytes, RootSignatureKind kind) {
    RootSignatureLayout out;
    out.kind = kind;
    if (pushConstantBytes > kMaxPushConstantBytes || pushConstantBytes % 4 != 0)
        return makeError("d3d12 root signature: push constants of " + std::to_string(pushConstantBytes) +
                         " bytes (must be a multiple of 4 and at most 128)");
    if (pushConstantBytes > 0) {
        RootParameterLayout p;
        p.kind = RootParameterLayout::Kind::Constants;
        p.shaderRegister = 0;
        p.registerSpace = kPushConstantSpace;
        p.num32BitValues = pushConstantBytes / 4;
        out.pushConstantParameter = int32_t(out.parameters.size());
        out.parameters.push_back(std::move(p));
    }
    for (uint32_t space = 0; space < layouts.size(); ++space) {
        auto table = computeDescriptorTableLayout(layouts[space]);
        if (!table) return makeError("binding layout " + std::to_string(space) + ": " + table.message());
        RootParameterLayout resources, samplers;
        resources.bindingLayoutIndex = samplers.bindingLayoutIndex = space;
        resources.visibility = samplers.visibility = toShaderVisibility(layouts[space].visibility);
        samplers.samplerTable = true;
        for (const DescriptorPlacement& item : table->items) {
            RootDescriptorRange r{item.registerClass, item.slot, item.arraySize, space, item.heapOffset};
            (item.registerClass == RegisterClass::Sampler ? samplers : resources).ranges.push_back(r);
        }
        int32_t resourceIndex = -1, samplerIndex = -1;
        if (!resources.ranges.empty()) {
            resourceIndex = int32_t(out.parameters.size());
            out.parameters.push_back(std::move(resources));
        }
        if (!samplers.ranges.empty()) {
            samplerIndex = int32_t(out.parameters.size());
            out.parameters.push_back(std::move(samplers));
        }
        out.resourceTableParameter.push_back(resourceIndex);
        out.samplerTableParameter.push_back(samplerIndex);
        out.tables.push_back(std::move(table).value());
    }
    if (kind == RootSignatureKind::Graphics) {
        // SV_InstanceID starts at 0 whatever StartInstanceLocation is (unlike gl_InstanceIndex), and
        // no shader model before 6.8 reads the draw's base values, so the command list passes them.
        RootParameterLayout p;
        p.kind = RootParameterLayout::Kind::Constants;
        p.shaderRegister = 0;
        p.registerSpace = kDrawParametersSpace;
        p.num32BitValues = 2;
        p.visibility = D3D12_SHADER_VISIBILITY_VERTEX;
        out.drawParametersParameter = int32_t(out.parameters.size());
        out.parameters.push_back(std::move(p));
    }
    return out;
}

Result<RootSignatureLayout> localRootSignatureLayout(uint32_t localDataBytes) {
    // Shader record = 32-byte identifier + root arguments; stride at most 4096 (DXR spec).
    if (localDataBytes % 4 != 0 || localDataBytes + D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES > 4096)
        return makeError("d3d12 local root signature: localDataBytes " + std::to_string(localDataBytes) +
                         " must be a multiple of 4 and fit a 4096-byte shader record");
    RootSignatureLayout out;
    out.kind = RootSignatureKind::LocalRayTracing;
    if (localDataBytes > 0) {
        RootParameterLayout p;
        p.kind = RootParameterLayout::Kind::Constants;
        p.registerSpace = kLocalDataSpace;
        p.num32BitValues = localDataBytes / 4;
        out.pushConstantParameter = 0;
        out.parameters.push_back(std::move(p));
    }
    return out;
}

namespace {
D3D12_DESCRIPTOR_RANGE_TYPE rangeType(RegisterClass c) {
    switch (c) {
        case RegisterClass::Cbv: return D3D12_DESCRIPTOR_RANGE_TYPE_CBV;
        case RegisterClass::Srv: return D3D12_DESCRIPTOR_RANGE_TYPE_SRV;
        case RegisterClass::Uav: return D3D12_DESCRIPTOR_RANGE_TYPE_UAV;
        case RegisterClass::Sampler: return D3D12_DESCRIPTOR_RANGE_TYPE_SAMPLER;
    }
    return D3D12_DESCRIPTOR_RANGE_TYPE_CBV;
}
}  // namespace

RootSignatureDescStorage::RootSignatureDescStorage(const RootSignatureLayout& layout) {
    for (const RootParameterLayout& p : layout.parameters) {
        D3D12_ROOT_PARAMETER1 param{};
        param.ShaderVisibility = p.visibility;
        if (p.kind == RootParameterLayout::Kind::Constants) {
            param.ParameterType = D3D12_ROOT_PARAMETER_TYPE_32BIT_CONSTANTS;
            param.Constants = {p.shaderRegister, p.registerSpace, p.num32BitValues};
        } else {
            auto& ranges = ranges_.emplace_back();
            for (const RootDescriptorRange& r : p.ranges) {
                D3D12_DESCRIPTOR_RANGE1 range{};
                range.RangeType = rangeType(r.registerClass);
                range.NumDescriptors = r.count;
                range.BaseShaderRegister = r.baseRegister;
                range.RegisterSpace = r.space;
                // Buffers change between dispatches under render-graph barriers, so the driver may not
                // assume static data (root signature 1.1 "data volatility"); samplers take no data flags.
                range.Flags = r.registerClass == RegisterClass::Sampler ? D3D12_DESCRIPTOR_RANGE_FLAG_NONE
                                                                        : D3D12_DESCRIPTOR_RANGE_FLAG_DATA_VOLATILE;
                range.OffsetInDescriptorsFromTableStart = r.tableOffset;
                ranges.push_back(range);
            }
            param.ParameterType = D3D12_ROOT_PARAMETER_TYPE_DESCRIPTOR_TABLE;
            param.DescriptorTable = {UINT(ranges.size()), ranges.data()};
        }
        parameters_.push_back(param);
    }
    D3D12_ROOT_SIGNATURE_FLAGS flags = D3D12_ROOT_SIGNATURE_FLAG_NONE;
    if (layout.kind == RootSignatureKind::Graphics) flags = D3D12_ROOT_SIGNATURE_FLAG_ALLOW_INPUT_ASSEMBLER_INPUT_LAYOUT;
    if (layout.kind == RootSignatureKind::LocalRayTracing) flags = D3D12_ROOT_SIGNATURE_FLAG_LOCAL_ROOT_SIGNATURE;
    desc_.Version = D3D_ROOT_SIGNATURE_VERSION_1_1;
    desc_.Desc_1_1.NumParameters = UINT(parameters_.size());
    desc_.Desc_1_1.pParameters = parameters_.empty() ? nullptr : parameters_.data();
    desc_.Desc_1_1.NumStaticSamplers = 0;
    desc_.Desc_1_1.pStaticSamplers = nullptr;
    desc_.Desc_1_1.Flags = flags;
}

}  // namespace caustics::rhi::d3d12
