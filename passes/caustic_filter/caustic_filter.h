#pragma once
// Persistent objects of the caustic filter (docs/caustics.md, "Filter"): the pipelines (one set per
// device) and the history (one per view; a host rendering several views keeps one each).
#include <cstdint>
#include <initializer_list>
#include <utility>

#include "caustics/rhi/device.h"

namespace caustics {

struct CausticFilterPipelines {
    rhi::BindingLayoutHandle resolveLayout, temporalLayout, varianceLayout, atrousWeightsLayout, atrousLayout,
        historyLayout;
    rhi::ComputePipelineHandle resolve, temporal, variance, atrousWeights, atrous, history;

    static Result<CausticFilterPipelines> create(rhi::IDevice& device);
};

// Last frame's temporal accumulation and what the disocclusion test compares against.
struct CausticFilterHistory {
    rhi::TextureHandle color;        // RGBA32F accumulated radiance (before the spatial passes)
    rhi::TextureHandle moments;      // RGBA32F x E[l], y E[l^2] of luminance, z history length n
    rhi::TextureHandle linearDepth;  // R32F
    rhi::TextureHandle normal;       // RGBA16F
    rhi::TextureHandle objectId;     // R32UI
    uint32_t width = 0, height = 0;
    bool valid = false;              // holds a frame (false after creation and after a resize)

    // (Re)creates the textures when the size changes; the history is then invalid.
    Status ensure(rhi::IDevice& device, uint32_t width, uint32_t height);
};

// Small helpers for the passes' persistent pipelines (defined in caustic_maps/caustic_resources.cpp).
Result<rhi::BindingLayoutHandle> makeBindingLayout(rhi::IDevice& device,
                                                   std::initializer_list<std::pair<uint32_t, rhi::BindingType>> items);
Result<rhi::ComputePipelineHandle> makeComputePipeline(rhi::IDevice& device, const char* shaderPath,
                                                       const rhi::BindingLayoutHandle& layout, uint32_t pushBytes);

}  // namespace caustics
