#pragma once
// The four passes of the render-graph GPU test (compute fill -> raster draw -> compute blur -> copy),
// each recorded without barriers so that the graph and the hand-written reference share them.
#include <cstdint>
#include <vector>

#include "caustics/rhi/rhi.h"

namespace caustics::test {

inline constexpr uint32_t kImageSize = 64;
inline constexpr rhi::Format kImageFormat = rhi::Format::RGBA8_UNORM;

struct FourPassPipelines {
    rhi::BindingLayoutHandle fillLayout, drawLayout, blurLayout;
    rhi::ComputePipelineHandle fill, blur;
    rhi::GraphicsPipelineHandle draw;
    rhi::SamplerHandle nearest;
};

// Fails (with the message) when a shader or pipeline cannot be created.
Result<FourPassPipelines> makeFourPassPipelines(rhi::IDevice& device);

// Binding sets are appended to `keep`: they must outlive the submission.
Status recordFill(rhi::IDevice& device, rhi::ICommandList& cmd, const FourPassPipelines& p,
                  const rhi::TextureHandle& pattern, std::vector<rhi::BindingSetHandle>& keep);
Status recordDraw(rhi::IDevice& device, rhi::ICommandList& cmd, const FourPassPipelines& p,
                  const rhi::TextureHandle& pattern, const rhi::TextureHandle& target,
                  std::vector<rhi::BindingSetHandle>& keep);
Status recordBlur(rhi::IDevice& device, rhi::ICommandList& cmd, const FourPassPipelines& p,
                  const rhi::TextureHandle& source, const rhi::TextureHandle& blurred,
                  std::vector<rhi::BindingSetHandle>& keep);
void recordCopy(rhi::ICommandList& cmd, const rhi::TextureHandle& blurred, const rhi::BufferHandle& readback);

}  // namespace caustics::test
