// Compute pipelines (root signature from the RHI bindings + PSO); graphics pipelines are in
// d3d12_graphics_pipeline.cpp.
#include "d3d12_device.h"
#include "d3d12_objects.h"

namespace caustics::rhi::d3d12 {

Result<RootBinding> makeRootBinding(Device& device, const PipelineBindings& bindings, RootSignatureKind kind,
                                    const std::string& name) {
    std::vector<BindingLayoutDesc> descs;
    for (const BindingLayoutHandle& l : bindings.layouts) {
        if (!l) return makeError("d3d12 '" + name + "': null binding layout");
        descs.push_back(l->desc());
    }
    RootBinding root;
    CAUSTICS_TRY(root.layout, rootSignatureLayoutFromBindings(descs, bindings.pushConstantBytes, kind));
    CAUSTICS_TRY(root.rootSignature, device.createRootSignature(root.layout, name));
    return root;
}

Result<ComputePipelineHandle> Device::createComputePipeline(const ComputePipelineDesc& desc) {
    auto p = std::make_shared<ComputePipeline>();
    p->releases = releases_;
    p->desc_ = desc;
    CAUSTICS_TRY(p->root, makeRootBinding(*this, desc.bindings, RootSignatureKind::Compute, desc.debugName));
    CAUSTICS_TRY(std::vector<uint8_t> code,
                 bytecodeFor(desc.shader.code, desc.shader.entryPoint, ShaderStage::Compute, false));
    D3D12_COMPUTE_PIPELINE_STATE_DESC d{};
    d.pRootSignature = p->root.rootSignature.get();
    d.CS = {code.data(), code.size()};
    if (!succeeded(device_->CreateComputePipelineState(&d, __uuidof(ID3D12PipelineState), p->pso.putVoid())))
        return makeError("d3d12: CreateComputePipelineState failed for '" + desc.debugName + "'");
    setDebugName(p->pso.get(), desc.debugName);
    return ComputePipelineHandle(p);
}

}  // namespace caustics::rhi::d3d12
