// The filter's pipelines (caustic_filter.h).
#include "caustic_filter/caustic_filter.h"

#include "caustic_filter/combine_types_bindings.h"
#include "caustic_filter/shaders/combine_types.h"
#include "module/pass_bindings.h"

namespace caustics {

Result<CausticFilterPipelines> CausticFilterPipelines::create(rhi::IDevice& d) {
    const auto CB = rhi::BindingType::ConstantBuffer, RO = rhi::BindingType::StorageBufferRO,
               RW = rhi::BindingType::StorageBufferRW, TX = rhi::BindingType::SampledTexture,
               IM = rhi::BindingType::StorageTexture;
    CausticFilterPipelines p;
    CAUSTICS_TRY(p.resolveLayout, makeBindingLayout(d, {{0, RO}, {1, RO}, {2, IM}, {3, IM}, {4, IM}}));
    // The passes after caustics.filterTiles take the tile list (a RO buffer) and, where they read
    // neighbours, a tile state (docs/caustics.md "Filter", "Tiles").
    CAUSTICS_TRY(p.tilesLayout, makeBindingLayout(d, {{0, CB}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, IM}}));
    CAUSTICS_TRY(p.tileListLayout, makeBindingLayout(d, {{0, IM}, {1, RW}, {2, RW}, {3, IM}}));
    // Pool images (history, variance, a-trous, weights, gradient) and the slot map that finds a screen
    // tile's pool tile (docs/caustics.md "Memory").
    CAUSTICS_TRY(p.temporalLayout, makeBindingLayout(d, {{0, CB}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, TX}, {6, TX},
                                                         {7, TX}, {8, RO}, {9, IM}, {10, IM}, {11, IM}}));
    CAUSTICS_TRY(p.varianceLayout, makeBindingLayout(d, {{0, TX}, {1, TX}, {2, TX}, {3, TX}, {4, IM}, {5, RO}, {6, TX}}));
    CAUSTICS_TRY(p.atrousWeightsLayout, makeBindingLayout(d, {{0, TX}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, TX}, {6, RO},
                                                              {7, IM}}));
    CAUSTICS_TRY(p.atrousLayout, makeBindingLayout(d, {{0, TX}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, TX}, {6, TX},
                                                       {7, RO}, {8, IM}}));
    CAUSTICS_TRY(p.outputLayout, makeBindingLayout(d, {{0, TX}, {1, TX}, {2, RO}, {3, IM}}));
    CAUSTICS_TRY(p.resolve, makeComputePipeline(d, "caustic_filter/resolve.comp", p.resolveLayout, 16));
    CAUSTICS_TRY(p.tiles, makeComputePipeline(d, "caustic_filter/tiles.comp", p.tilesLayout, 8));
    CAUSTICS_TRY(p.tileList, makeComputePipeline(d, "caustic_filter/tile_list.comp", p.tileListLayout, 12));
    CAUSTICS_TRY(p.output, makeComputePipeline(d, "caustic_filter/output.comp", p.outputLayout, 12));
    CAUSTICS_TRY(p.temporal, makeComputePipeline(d, "caustic_filter/temporal.comp", p.temporalLayout, 20));
    CAUSTICS_TRY(p.variance, makeComputePipeline(d, "caustic_filter/variance.comp", p.varianceLayout, 12));
    CAUSTICS_TRY(p.atrousWeights, makeComputePipeline(d, "caustic_filter/atrous_weights.comp", p.atrousWeightsLayout, 16));
    CAUSTICS_TRY(p.atrous, makeComputePipeline(d, "caustic_filter/atrous.comp", p.atrousLayout, 20));
    CAUSTICS_TRY(p.atrousLast, makeComputePipeline(d, "caustic_filter/atrous_last.comp", p.atrousLayout, 20));
    CAUSTICS_TRY(p.combineLayout, createPassBindingLayout(d, shader_bindings::kCombineTypesBindings, 0, rhi::ShaderStage::All));
    CAUSTICS_TRY(p.combine, makeComputePipeline(d, "caustic_filter/combine_types.comp", p.combineLayout,
                                                sizeof(shader::CombineTypesParams)));
    return p;
}

}  // namespace caustics
