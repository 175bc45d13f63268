// The filter's pipelines (caustic_filter.h).
#include "caustic_filter/atrous_bindings.h"
#include "caustic_filter/caustic_filter.h"
#include "caustic_filter/shaders/atrous.h"
#include "caustic_filter/output_bindings.h"
#include "caustic_filter/resolve_bindings.h"
#include "caustic_filter/shaders/output.h"
#include "caustic_filter/shaders/resolve.h"
#include "caustic_filter/shaders/variance.h"
#include "caustic_filter/variance_bindings.h"
#include "module/pass_bindings.h"

namespace caustics {

static_assert(sizeof(shader::AtrousParams) == 20);
static_assert(shader::kFilterPoolTilesPerRow == kFilterPoolTilesPerRow);

Result<CausticFilterPipelines> CausticFilterPipelines::create(rhi::IDevice& d) {
    const auto CB = rhi::BindingType::ConstantBuffer, RO = rhi::BindingType::StorageBufferRO,
               RW = rhi::BindingType::StorageBufferRW, TX = rhi::BindingType::SampledTexture,
               IM = rhi::BindingType::StorageTexture;
    CausticFilterPipelines p;
    CAUSTICS_TRY(p.resolveLayout, createPassBindingLayout(d, shader_bindings::kCausticResolveBindings, 0, rhi::ShaderStage::Compute));
    // The passes after caustics.filterTiles take the tile list (a RO buffer) and, where they read
    // neighbours, a tile state (docs/caustics.md "Filter", "Tiles").
    CAUSTICS_TRY(p.tilesLayout, makeBindingLayout(d, {{0, CB}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, IM}}));
    CAUSTICS_TRY(p.tileListLayout, makeBindingLayout(d, {{0, IM}, {1, RW}, {2, RW}, {3, IM}}));
    // Pool images (history, variance, a-trous, the packed a-trous guide) and the slot map that finds a screen
    // tile's pool tile (docs/caustics.md "Memory").
    CAUSTICS_TRY(p.temporalLayout, makeBindingLayout(d, {{0, CB}, {1, TX}, {2, TX}, {3, TX}, {4, TX}, {5, TX}, {6, TX},
                                                         {7, TX}, {8, RO}, {9, IM}, {10, IM}, {11, IM}}));
    CAUSTICS_TRY(p.varianceLayout, createPassBindingLayout(d, shader_bindings::kCausticVarianceBindings, 0, rhi::ShaderStage::Compute));
    // caustics.atrous.N: declared once (atrous_bindings.h, docs/shaders.md "Bindings").
    CAUSTICS_TRY(p.atrousLayout, createPassBindingLayout(d, shader_bindings::kCausticAtrousBindings, 0, rhi::ShaderStage::Compute));
    CAUSTICS_TRY(p.atrousLastLayout,
                 createPassBindingLayout(d, shader_bindings::kCausticAtrousLastBindings, 0, rhi::ShaderStage::Compute));
    CAUSTICS_TRY(p.outputLayout,
                 createPassBindingLayout(d, shader_bindings::kCausticFilterOutputBindings, 0, rhi::ShaderStage::Compute));
    CAUSTICS_TRY(p.resolve, makeComputePipeline(d, "caustic_filter/resolve.comp", p.resolveLayout, sizeof(shader::ResolveParams)));
    CAUSTICS_TRY(p.tiles, makeComputePipeline(d, "caustic_filter/tiles.comp", p.tilesLayout, 8));
    CAUSTICS_TRY(p.tileList, makeComputePipeline(d, "caustic_filter/tile_list.comp", p.tileListLayout, 12));
    CAUSTICS_TRY(p.output, makeComputePipeline(d, "caustic_filter/output.comp", p.outputLayout, sizeof(shader::FilterOutputParams)));
    CAUSTICS_TRY(p.temporal, makeComputePipeline(d, "caustic_filter/temporal.comp", p.temporalLayout, 16));
    CAUSTICS_TRY(p.variance, makeComputePipeline(d, "caustic_filter/variance.comp", p.varianceLayout, sizeof(shader::VarianceParams)));
    CAUSTICS_TRY(p.atrous, makeComputePipeline(d, "caustic_filter/atrous.comp", p.atrousLayout, sizeof(shader::AtrousParams)));
    CAUSTICS_TRY(p.atrousLast,
                 makeComputePipeline(d, "caustic_filter/atrous_last.comp", p.atrousLastLayout, sizeof(shader::AtrousParams)));
    return p;
}

}  // namespace caustics
