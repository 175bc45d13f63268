#pragma once
// Maps a host G-buffer's own object ids to the module's (instance row + 1) on the GPU, through the
// host's HostGBuffer::objectIdMap (docs/embedding.md, "Instance ids"). Writes a module-owned R32_UINT
// texture that replaces the host's objectId channel for every later pass. Compute.
#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/device.h"

namespace caustics {

class ObjectIdRemapPass {
public:
    static Result<ObjectIdRemapPass> create(rhi::IDevice& device);
    // hostIds: the imported host objectId texture; map: the imported (hostId, moduleId) pairs.
    rg::RgTexture addToGraph(rg::RenderGraph& graph, rg::RgTexture hostIds, rg::RgBuffer map, uint32_t pairCount,
                             uint32_t width, uint32_t height) const;

private:
    rhi::BindingLayoutHandle layout_;
    rhi::ComputePipelineHandle pipeline_;
};

}  // namespace caustics
