// The filter history pool's capacity (passes/caustic_filter/caustic_filter.h; docs/caustics.md "Memory"):
// where it starts, and when and how far it grows, from the tile counts the frames read back.
#include <gtest/gtest.h>

#include "caustic_filter/caustic_filter.h"

namespace caustics {
namespace {

TEST(FilterPool, StartsAtAQuarterOfTheViewAtLeast1024TilesInWholeRows) {
    EXPECT_EQ(initialFilterPoolTiles(1920, 1080), 8192u);   // 32,400 tiles / 4 = 8,100, rounded to 64 rows
    EXPECT_EQ(initialFilterPoolTiles(256, 256), 1024u);
    EXPECT_EQ(initialFilterPoolTiles(96, 96), 256u);        // 144 tiles: two rows, never more than the view
}

TEST(FilterPool, StartsWhereTheHostAsksInWholeRowsAtMostTheView) {
    EXPECT_EQ(initialFilterPoolTiles(1920, 1080, 30000), 30080u);
    EXPECT_EQ(initialFilterPoolTiles(1920, 1080, 1), kFilterPoolTilesPerRow);
    EXPECT_EQ(initialFilterPoolTiles(96, 96, 100000), 256u);
}

TEST(FilterPool, GrowsOnceOverSevenEighthsFullToOneAndAHalfTimesTheTilesWanted) {
    EXPECT_EQ(grownFilterPoolTiles(8192, 7168, 1920, 1080), 8192u);    // 7/8 exactly: room enough
    EXPECT_EQ(grownFilterPoolTiles(8192, 7169, 1920, 1080), 10880u);   // ahead of an overflow
    EXPECT_EQ(grownFilterPoolTiles(8192, 18066, 1920, 1080), 27136u);  // overflowed: 1.5 x 18,066 in rows
    EXPECT_EQ(grownFilterPoolTiles(28544, 30142, 1920, 1080), 32512u); // never past the view's tiles
    EXPECT_EQ(grownFilterPoolTiles(32512, 32400, 1920, 1080), 32512u); // nor shrinks
}

}  // namespace
}  // namespace caustics
