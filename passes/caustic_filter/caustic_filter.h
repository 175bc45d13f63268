#pragma once
// Persistent objects of the caustic filter (docs/caustics.md, "Filter"): the pipelines (one set per
// device). The history is per view: CausticViewHistory (caustics/caustic_passes.h).
#include <cstdint>
#include <initializer_list>
#include <utility>

#include "caustics/rhi/device.h"

namespace caustics {

struct CausticFilterPipelines {
    rhi::BindingLayoutHandle resolveLayout, tilesLayout, tileListLayout, temporalLayout, varianceLayout,
        atrousWeightsLayout, atrousLayout, outputLayout;
    rhi::ComputePipelineHandle resolve, tiles, tileList, temporal, variance, atrousWeights, atrous, output;

    static Result<CausticFilterPipelines> create(rhi::IDevice& device);
};

// Small helpers for the passes' persistent pipelines (defined in caustic_maps/caustic_resources.cpp).
Result<rhi::BindingLayoutHandle> makeBindingLayout(rhi::IDevice& device,
                                                   std::initializer_list<std::pair<uint32_t, rhi::BindingType>> items);
Result<rhi::ComputePipelineHandle> makeComputePipeline(rhi::IDevice& device, const char* shaderPath,
                                                       const rhi::BindingLayoutHandle& layout, uint32_t pushBytes);

}  // namespace caustics
