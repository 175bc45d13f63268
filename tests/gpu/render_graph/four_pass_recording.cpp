#include "four_pass_recording.h"

#include "gpu_test.h"

#include <string>
#include <string_view>

namespace caustics::test {
using namespace rhi;

namespace {
Result<ShaderEntry> shader(std::string_view path, ShaderStage stage) {
    ShaderEntry e;
    e.code = testShader(path);   // embedded by the GPU test support from tests/gpu/shaders/
    if (e.code.bytes.empty()) return makeError("no embedded shader " + std::string(path));
    e.stage = stage;
    return e;
}

constexpr uint32_t kGroups = (kImageSize + 7) / 8;   // 8x8 work groups in fill.comp and blur.comp
}  // namespace

Result<FourPassPipelines> makeFourPassPipelines(IDevice& device) {
    FourPassPipelines p;
    CAUSTICS_TRY(p.fillLayout, device.createBindingLayout(
                                   BindingLayoutDesc().setVisibility(ShaderStage::Compute).add(0, BindingType::StorageTexture)));
    CAUSTICS_TRY(p.drawLayout, device.createBindingLayout(BindingLayoutDesc()
                                                              .setVisibility(ShaderStage::Fragment)
                                                              .add(0, BindingType::SampledTexture)
                                                              .add(1, BindingType::Sampler)));
    CAUSTICS_TRY(p.blurLayout, device.createBindingLayout(BindingLayoutDesc()
                                                              .setVisibility(ShaderStage::Compute)
                                                              .add(0, BindingType::SampledTexture)
                                                              .add(1, BindingType::Sampler)
                                                              .add(2, BindingType::StorageTexture)));
    CAUSTICS_TRY(p.nearest, device.createSampler(SamplerDesc().setFilter(FilterMode::Nearest).setAddress(AddressMode::ClampToEdge)));

    ComputePipelineDesc fill;
    CAUSTICS_TRY(fill.shader, shader("render_graph/fill.comp", ShaderStage::Compute));
    fill.bindings.layouts = {p.fillLayout};
    fill.debugName = "rg test fill";
    CAUSTICS_TRY(p.fill, device.createComputePipeline(fill));

    ComputePipelineDesc blur;
    CAUSTICS_TRY(blur.shader, shader("render_graph/blur.comp", ShaderStage::Compute));
    blur.bindings.layouts = {p.blurLayout};
    blur.debugName = "rg test blur";
    CAUSTICS_TRY(p.blur, device.createComputePipeline(blur));

    GraphicsPipelineDesc draw;
    CAUSTICS_TRY(draw.vertexShader, shader("render_graph/draw.vert", ShaderStage::Vertex));
    CAUSTICS_TRY(draw.fragmentShader, shader("render_graph/draw.frag", ShaderStage::Fragment));
    draw.bindings.layouts = {p.drawLayout};
    draw.colorFormats = {kImageFormat};
    draw.depthTest = false;
    draw.depthWrite = false;
    draw.debugName = "rg test draw";
    CAUSTICS_TRY(p.draw, device.createGraphicsPipeline(draw));
    return p;
}

Status recordFill(IDevice& device, ICommandList& cmd, const FourPassPipelines& p, const TextureHandle& pattern,
                  std::vector<BindingSetHandle>& keep) {
    CAUSTICS_TRY(BindingSetHandle set,
                 device.createBindingSet(BindingSetDesc().add(BindingSetItem::storageTexture(0, pattern)), p.fillLayout));
    keep.push_back(set);
    cmd.setComputePipeline(p.fill);
    cmd.setBindingSet(0, set);
    cmd.dispatch(kGroups, kGroups);
    return okStatus();
}

Status recordDraw(IDevice& device, ICommandList& cmd, const FourPassPipelines& p, const TextureHandle& pattern,
                  const TextureHandle& target, std::vector<BindingSetHandle>& keep) {
    CAUSTICS_TRY(BindingSetHandle set, device.createBindingSet(BindingSetDesc()
                                                                   .add(BindingSetItem::sampledTexture(0, pattern))
                                                                   .add(BindingSetItem::samplerItem(1, p.nearest)),
                                                               p.drawLayout));
    keep.push_back(set);
    RenderingDesc rendering;
    ColorAttachment color;
    color.texture = target;
    color.clear = true;
    color.clearValue[0] = 0.1f;
    color.clearValue[3] = 1.0f;
    rendering.colors.push_back(color);
    rendering.width = kImageSize;
    rendering.height = kImageSize;
    cmd.beginRendering(rendering);
    cmd.setGraphicsPipeline(p.draw);
    cmd.setBindingSet(0, set);
    cmd.setViewport(0, 0, float(kImageSize), float(kImageSize));
    cmd.draw(3);
    cmd.endRendering();
    return okStatus();
}

Status recordBlur(IDevice& device, ICommandList& cmd, const FourPassPipelines& p, const TextureHandle& source,
                  const TextureHandle& blurred, std::vector<BindingSetHandle>& keep) {
    CAUSTICS_TRY(BindingSetHandle set, device.createBindingSet(BindingSetDesc()
                                                                   .add(BindingSetItem::sampledTexture(0, source))
                                                                   .add(BindingSetItem::samplerItem(1, p.nearest))
                                                                   .add(BindingSetItem::storageTexture(2, blurred)),
                                                               p.blurLayout));
    keep.push_back(set);
    cmd.setComputePipeline(p.blur);
    cmd.setBindingSet(0, set);
    cmd.dispatch(kGroups, kGroups);
    return okStatus();
}

void recordCopy(ICommandList& cmd, const TextureHandle& blurred, const BufferHandle& readback) {
    cmd.copyTextureToBuffer(readback, 0, blurred);
}

}  // namespace caustics::test
