// The filter's pipelines (caustic_filter.h).
#include "caustic_filter/atrous_bindings.h"
#include "caustic_filter/caustic_filter.h"
#include "caustic_filter/output_bindings.h"
#include "caustic_filter/resolve_bindings.h"
#include "caustic_filter/shaders/atrous.h"
#include "caustic_filter/shaders/output.h"
#include "caustic_filter/shaders/resolve.h"
#include "caustic_filter/shaders/temporal.h"
#include "caustic_filter/shaders/tiles.h"
#include "caustic_filter/shaders/variance.h"
#include "caustic_filter/temporal_bindings.h"
#include "caustic_filter/tiles_bindings.h"
#include "caustic_filter/variance_bindings.h"
#include "module/pass_bindings.h"

#include "caustic_filter/combine_types_bindings.h"
#include "caustic_filter/shaders/combine_types.h"
#include "module/pass_bindings.h"

namespace caustics {

static_assert(sizeof(shader::AtrousParams) == 32);
static_assert(shader::kFilterPoolTilesPerRow == kFilterPoolTilesPerRow);

Result<CausticFilterPipelines> CausticFilterPipelines::create(rhi::IDevice& d) {
    // Every layout from the pass's one declaration (*_bindings.h; docs/shaders.md "Bindings"). The passes
    // after caustics.filterTiles take the tile list and, where they read neighbours, the slot map that
    // finds a screen tile's pool tile (docs/caustics.md "Tiles", "Memory").
    auto layout = [&](const shader_bindings::PassBindings& declared) {
        return createPassBindingLayout(d, declared, 0, rhi::ShaderStage::Compute);
    };
    CausticFilterPipelines p;
    CAUSTICS_TRY(p.resolveLayout, layout(shader_bindings::kCausticResolveBindings));
    CAUSTICS_TRY(p.tilesLayout, layout(shader_bindings::kCausticFilterTilesBindings));
    CAUSTICS_TRY(p.tileListLayout, layout(shader_bindings::kCausticTileListBindings));
    CAUSTICS_TRY(p.temporalLayout, layout(shader_bindings::kCausticTemporalBindings));
    CAUSTICS_TRY(p.varianceLayout, layout(shader_bindings::kCausticVarianceBindings));
    CAUSTICS_TRY(p.atrousPairsLayout, layout(shader_bindings::kCausticAtrousPairsBindings));
    CAUSTICS_TRY(p.atrousLayout, layout(shader_bindings::kCausticAtrousBindings));
    CAUSTICS_TRY(p.atrousLastLayout, layout(shader_bindings::kCausticAtrousLastBindings));
    CAUSTICS_TRY(p.outputLayout, layout(shader_bindings::kCausticFilterOutputBindings));
    CAUSTICS_TRY(p.resolve, createPassComputePipeline(d, "caustic_filter/resolve.comp", {p.resolveLayout}, sizeof(shader::ResolveParams)));
    CAUSTICS_TRY(p.tiles, createPassComputePipeline(d, "caustic_filter/tiles.comp", {p.tilesLayout}, sizeof(shader::FilterTilesParams)));
    CAUSTICS_TRY(p.tileList, createPassComputePipeline(d, "caustic_filter/tile_list.comp", {p.tileListLayout}, sizeof(shader::TileListParams)));
    CAUSTICS_TRY(p.output, createPassComputePipeline(d, "caustic_filter/output.comp", {p.outputLayout}, sizeof(shader::FilterOutputParams)));
    CAUSTICS_TRY(p.temporal, createPassComputePipeline(d, "caustic_filter/temporal.comp", {p.temporalLayout}, sizeof(shader::TemporalParams)));
    CAUSTICS_TRY(p.variance, createPassComputePipeline(d, "caustic_filter/variance.comp", {p.varianceLayout}, sizeof(shader::VarianceParams)));
    CAUSTICS_TRY(p.atrousPairs, createPassComputePipeline(d, "caustic_filter/atrous_pairs.comp", {p.atrousPairsLayout},
                                                        sizeof(shader::AtrousParams)));
    CAUSTICS_TRY(p.atrous, createPassComputePipeline(d, "caustic_filter/atrous.comp", {p.atrousLayout}, sizeof(shader::AtrousParams)));
    CAUSTICS_TRY(p.atrousLast,
                 createPassComputePipeline(d, "caustic_filter/atrous_last.comp", {p.atrousLastLayout}, sizeof(shader::AtrousParams)));
    CAUSTICS_TRY(p.combineLayout, createPassBindingLayout(d, shader_bindings::kCombineTypesBindings, 0, rhi::ShaderStage::All));
    CAUSTICS_TRY(p.combine, createPassComputePipeline(d, "caustic_filter/combine_types.comp", {p.combineLayout},
                                                sizeof(shader::CombineTypesParams)));
    CAUSTICS_TRY(p.tilesList, createPassComputePipeline(d, "caustic_filter/tiles_list.comp", {p.tilesLayout}, sizeof(shader::FilterTilesParams)));
    CAUSTICS_TRY(p.temporalList, createPassComputePipeline(d, "caustic_filter/temporal_list.comp", {p.temporalLayout},
                                                     sizeof(shader::TemporalParams)));
    CAUSTICS_TRY(p.varianceList, createPassComputePipeline(d, "caustic_filter/variance_list.comp", {p.varianceLayout},
                                                     sizeof(shader::VarianceParams)));
    CAUSTICS_TRY(p.atrousLastList, createPassComputePipeline(d, "caustic_filter/atrous_last_list.comp", {p.atrousLastLayout},
                                                       sizeof(shader::AtrousParams)));
    CAUSTICS_TRY(p.outputList, createPassComputePipeline(d, "caustic_filter/output_list.comp", {p.outputLayout},
                                                   sizeof(shader::FilterOutputParams)));
    CAUSTICS_TRY(p.combineList, createPassComputePipeline(d, "caustic_filter/combine_types_list.comp", {p.combineLayout},
                                                    sizeof(shader::CombineTypesParams)));
    return p;
}

}  // namespace caustics
