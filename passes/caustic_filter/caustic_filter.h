#pragma once
// Persistent objects of the caustic filter (docs/caustics.md, "Filter"): the pipelines (one set per
// device) and the sizing of the view's history pool (CausticViewHistory, caustics/caustic_passes.h).
#include <cstdint>
#include <initializer_list>
#include <utility>

#include "caustics/caustic_passes.h"
#include "caustics/rhi/device.h"

namespace caustics {

struct CausticFilterPipelines {
    rhi::BindingLayoutHandle resolveLayout, tilesLayout, tileListLayout, temporalLayout, varianceLayout, atrousPairsLayout, atrousLayout,
        atrousLastLayout, outputLayout, combineLayout;
    rhi::ComputePipelineHandle resolve, tiles, tileList, temporal, variance, atrousPairs, atrous, atrousLast, output;
    rhi::ComputePipelineHandle combine;   // first + second type, each filtered on its own guides
    // The passes that read or write the frame inputs, for the second type in list order
    // (common/specular_list.h; the *_list entries): the same layouts and push constants.
    rhi::ComputePipelineHandle tilesList, temporalList, varianceList, atrousLastList, outputList, combineList;

    static Result<CausticFilterPipelines> create(rhi::IDevice& device);
};

// The filter's pool (passes/caustic_filter/shaders/filter_common.h): 8x8 tiles, one per
// listed tile, kFilterPoolTilesPerRow to a row of the pool images. A view starts with
// CausticsSettings::filterPoolTiles, or else a quarter of its screen tiles, at least kFilterMinPoolTiles
// (rounded up to whole rows, at most all of them), and grows, from the tile counts its frames read back,
// to 1.5 x the tiles a frame wanted once that is over 7/8 of the pool (a frame that wants more than the
// pool holds filters the rest of them not at all and warns). Growing keeps the history: the slots keep
// their place in the larger pool and the next graph copies the last frame's history over.
inline constexpr uint32_t kFilterPoolTilesPerRow = 128;
inline constexpr uint32_t kFilterInitialPoolDivisor = 4;
inline constexpr uint32_t kFilterMinPoolTiles = 1024;   // 2 MiB of history: every view up to 256 x 256
inline constexpr uint32_t kFilterPoolGrowNumerator = 7, kFilterPoolGrowDenominator = 8;   // grown past 7/8 full
inline uint32_t filterScreenTiles(uint32_t width, uint32_t height) { return ((width + 7) / 8) * ((height + 7) / 8); }
inline uint32_t filterPoolWidth() { return kFilterPoolTilesPerRow * 8; }
inline uint32_t filterPoolHeight(uint32_t poolTiles) { return (poolTiles + kFilterPoolTilesPerRow - 1) / kFilterPoolTilesPerRow * 8; }
// requested: CausticsSettings::filterPoolTiles (0: automatic).
uint32_t initialFilterPoolTiles(uint32_t width, uint32_t height, uint32_t requested = 0);
// The second type filtered apart lies only on what the camera sees through specular objects: its pool
// starts at twice the tiles of their image coverage (the fraction of the screen the planner's bounds
// cover, caustic_importance.h; twice for the ring of neighbour tiles the list adds), at least
// kFilterMinPoolTiles, at most the first type's start, and grows like it.
inline constexpr double kSecondTypePoolCoverageMargin = 2.0;
uint32_t initialSecondTypePoolTiles(uint32_t width, uint32_t height, double specularCoverage);
uint32_t grownFilterPoolTiles(uint32_t poolTiles, uint32_t wanted, uint32_t width, uint32_t height);

// Sizes `history` for a width x height view: reallocated, and invalid, when the size changes; a grown pool
// keeps its history (CausticViewHistory::growth). requestedPoolTiles: CausticsSettings::filterPoolTiles.
Status ensureFilterHistory(CausticResources::Impl& res, CausticViewHistory& history, uint32_t width, uint32_t height,
                           uint32_t requestedPoolTiles);


}  // namespace caustics
