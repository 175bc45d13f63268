// Graphics pipelines: root signature from the RHI bindings (plus the draw-parameter constants),
// PSO from graphics_pipeline_desc.h with the VS/PS bytecode.
#include "d3d12_device.h"
#include "d3d12_objects.h"

namespace caustics::rhi::d3d12 {

Result<GraphicsPipelineHandle> Device::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
    auto p = std::make_shared<GraphicsPipeline>();
    p->releases = releases_;
    p->desc_ = desc;
    CAUSTICS_TRY(std::unique_ptr<GraphicsPsoDescStorage> storage, GraphicsPsoDescStorage::create(desc));
    CAUSTICS_TRY(p->root, makeRootBinding(*this, desc.bindings, RootSignatureKind::Graphics, desc.debugName));
    CAUSTICS_TRY(std::vector<uint8_t> vs,
                 bytecodeFor(desc.vertexShader.code, desc.vertexShader.entryPoint, ShaderStage::Vertex, false));
    std::vector<uint8_t> ps;
    if (desc.fragmentShader.stage != ShaderStage::None) {   // None: depth-only, no pixel shader
        CAUSTICS_TRY(ps, bytecodeFor(desc.fragmentShader.code, desc.fragmentShader.entryPoint, ShaderStage::Fragment,
                                     false));
    }
    D3D12_GRAPHICS_PIPELINE_STATE_DESC& d = storage->desc();
    d.pRootSignature = p->root.rootSignature.get();
    d.VS = {vs.data(), vs.size()};
    d.PS = {ps.empty() ? nullptr : ps.data(), ps.size()};
    if (!succeeded(device_->CreateGraphicsPipelineState(&d, __uuidof(ID3D12PipelineState), p->pso.putVoid())))
        return makeError("d3d12: CreateGraphicsPipelineState failed for '" + desc.debugName +
                         "' (enable validation for the debug layer's reason)");
    setDebugName(p->pso.get(), desc.debugName);
    p->topology = toPrimitiveTopology(desc.topology);
    p->strides = storage->strides();
    return GraphicsPipelineHandle(p);
}

}  // namespace caustics::rhi::d3d12
