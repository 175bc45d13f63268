// The view's filter history (caustic_passes.h, CausticViewHistory; docs/caustics.md "Filter", "Memory"):
// allocated per listed tile, in a pool whose capacity follows the view's caustic coverage.
#include <algorithm>
#include <string>

#include "caustic_filter/caustic_filter.h"
#include "caustic_maps/caustic_internal.h"
#include "caustics/rhi/log.h"

namespace caustics {
namespace {

uint32_t roundUpToPoolRows(uint32_t tiles) {
    return (tiles + kFilterPoolTilesPerRow - 1) / kFilterPoolTilesPerRow * kFilterPoolTilesPerRow;
}

// The tiles the last frame recorded in this frame slot listed (the host waited for it before reusing
// the slot), if it was of this size.
uint32_t tilesWantedBefore(rhi::IDevice& device, const CausticViewHistory& h, uint32_t slot) {
    uint32_t count = 0;
    if (slot < h.tileCounts.size() && h.tileCounts[slot] && h.tileCountRecorded[slot] &&
        device.readBuffer(h.tileCounts[slot], &count, sizeof(count)))
        return count;
    return 0;
}

}  // namespace

uint32_t initialFilterPoolTiles(uint32_t width, uint32_t height, uint32_t requested) {
    const uint32_t screen = roundUpToPoolRows(filterScreenTiles(width, height));
    if (requested > 0) return std::min(screen, roundUpToPoolRows(requested));
    return std::min(screen, std::max(kFilterMinPoolTiles, roundUpToPoolRows(filterScreenTiles(width, height) / kFilterInitialPoolDivisor)));
}

uint32_t initialSecondTypePoolTiles(uint32_t width, uint32_t height, double specularCoverage) {
    const double screen = filterScreenTiles(width, height);
    const double seen = std::clamp(specularCoverage, 0.0, 1.0) * kSecondTypePoolCoverageMargin * screen;
    const uint32_t wanted = roundUpToPoolRows(uint32_t(std::min(seen, screen)));
    return std::min(initialFilterPoolTiles(width, height), std::max(kFilterMinPoolTiles, wanted));
}

uint32_t grownFilterPoolTiles(uint32_t poolTiles, uint32_t wanted, uint32_t width, uint32_t height) {
    if (uint64_t(wanted) * kFilterPoolGrowDenominator <= uint64_t(poolTiles) * kFilterPoolGrowNumerator) return poolTiles;
    return std::max(poolTiles, std::min(roundUpToPoolRows(filterScreenTiles(width, height)), roundUpToPoolRows(wanted + wanted / 2)));
}

Status ensureFilterHistory(CausticResources::Impl& res, CausticViewHistory& h, uint32_t width, uint32_t height,
                           uint32_t requestedPoolTiles) {
    rhi::IDevice& d = *res.device;
    const uint32_t slots = uint32_t(res.frameSets.size());
    if (h.tileCounts.size() != slots) {
        h.tileCounts.assign(slots, nullptr);
        h.tileCountRecorded.assign(slots, 0);
    }
    const bool sized = h.color[0] && h.width == width && h.height == height;
    uint32_t pool = sized ? h.poolTiles : initialFilterPoolTiles(width, height, requestedPoolTiles);
    if (sized) {
        const uint32_t wanted = tilesWantedBefore(d, h, res.frameSlot);
        pool = grownFilterPoolTiles(h.poolTiles, wanted, width, height);
        if (pool != h.poolTiles) {
            // Outgrown: those tiles went unfiltered for a few frames. Nearly full: grown ahead of it.
            const bool overflowed = wanted > h.poolTiles;
            log(overflowed ? LogLevel::Warning : LogLevel::Info,
                "caustics: filter history pool of " + std::to_string(h.poolTiles) + " tiles " +
                    (overflowed ? "overflowed (" : "nearly full (") + std::to_string(wanted) + " listed" +
                    (overflowed ? "; those past it went unfiltered" : "") + "): grown to " + std::to_string(pool) +
                    " (CausticsSettings::filterPoolTiles sizes it up front)");
        }
    }
    if (!h.tileCounts[res.frameSlot]) {
        auto buffer = d.createBuffer(rhi::BufferDesc().setByteSize(4).setUsage(rhi::BufferUsage::CopyDest)
                                         .setMemory(rhi::MemoryType::Readback)
                                         .setDebugName("caustics.filterTileCountReadback"));
        if (buffer) h.tileCounts[res.frameSlot] = buffer.value();   // without it the pool never grows
    }
    if (sized && pool == h.poolTiles) return okStatus();

    auto make = [&](uint32_t w, uint32_t ht, rhi::Format f, std::string name) {
        return d.createTexture(rhi::TextureDesc().setSize(w, ht).setFormat(f)
                                   .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage |
                                             rhi::TextureUsage::CopySource | rhi::TextureUsage::CopyDest)
                                   .setDebugName(name));
    };
    const uint32_t poolW = filterPoolWidth(), poolH = filterPoolHeight(pool);
    rhi::TextureHandle color[2], guides[2];
    for (uint32_t i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i);
        CAUSTICS_TRY(color[i], make(poolW, poolH, rhi::Format::RGBA16_FLOAT, "caustics.historyColor" + n));
        CAUSTICS_TRY(guides[i], make(poolW, poolH, rhi::Format::RG32_UINT, "caustics.historyGuides" + n));
    }
    if (sized) {
        // Grown: the tile state and slot map keep their size and contents, the slots keep their place in
        // the larger pool; the copy the next graph reads moves over (filter_tile_passes.cpp,
        // addPoolGrowthPass). One not yet copied (two growths before a graph was built) moves instead.
        if (!h.growth) h.growth = CausticViewHistory::PoolGrowth{{h.color[0], h.color[1]}, {h.guides[0], h.guides[1]},
                                                                 filterPoolHeight(h.poolTiles) / 8};
        for (uint32_t i = 0; i < 2; ++i) {
            h.color[i] = std::move(color[i]);
            h.guides[i] = std::move(guides[i]);
        }
        h.poolTiles = pool;
        return okStatus();
    }
    const uint32_t tilesX = (width + 7) / 8, tilesY = (height + 7) / 8;
    for (uint32_t i = 0; i < 2; ++i) {
        const std::string n = std::to_string(i);
        h.color[i] = std::move(color[i]);
        h.guides[i] = std::move(guides[i]);
        CAUSTICS_TRY(h.tiles[i], make(tilesX, tilesY, rhi::Format::R32_UINT, "caustics.historyTiles" + n));
        CAUSTICS_TRY(h.slots[i], make(tilesX, tilesY, rhi::Format::R32_UINT, "caustics.historySlots" + n));
    }
    h.poolTiles = pool;
    h.growth.reset();
    h.parity = h.builtParity = 0;
    h.width = width;
    h.height = height;
    h.valid = h.builtValid = false;
    h.lastBuiltFrame.reset();   // the last executed frame stays: a later build for an earlier frame was dropped
    std::fill(h.tileCountRecorded.begin(), h.tileCountRecorded.end(), uint8_t(0));
    return okStatus();
}

}  // namespace caustics
