// The caustic filter's temporal history test (passes/caustic_filter/shaders/temporal.h) compiled as C++:
// a caustic that moves drops the history, stray photons and one firefly do not, and the second type
// waits a frame before a rise drops it (docs/caustics.md "Moving caustics").
#include <gtest/gtest.h>

#include "caustic_filter/shaders/temporal.h"

namespace caustics::shader {
namespace {

constexpr float kHistory = 0.5f;     // each tap's history mean
constexpr float kVariance = 0.01f;   // each tap's per-frame variance (the 3x3's sum 0.09: 3 deviations 0.9)

// Nine taps of history kHistory; this frame's luminance per tap.
TemporalTaps taps(const float (&now)[9]) {
    TemporalTaps t = temporalTapsNone();
    for (float l : now) t = temporalTapAdd(t, l, kHistory, kVariance);
    return t;
}

TEST(TemporalBody, OneFireflyKeepsTheHistoryACausticThatMovesDropsIt) {
    // Nothing changed, up to noise: kept.
    EXPECT_FALSE(temporalTapsContradict(taps({0.5f, 0.6f, 0.4f, 0.5f, 0.55f, 0.45f, 0.5f, 0.5f, 0.5f})));
    // One sample 46x the mean (the atrium's firefly): kept, and it was what the plain sums would reject.
    const TemporalTaps firefly = taps({0.5f, 0.5f, 0.5f, 0.5f, 23.0f, 0.5f, 0.5f, 0.5f, 0.5f});
    EXPECT_FALSE(temporalTapsContradict(firefly));
    EXPECT_TRUE(temporalContradicts(firefly.c, firefly.h, firefly.v, firefly.quantum));
    // A caustic that moves in brightens more than one tap: dropped; so does one tap rising to within 4x
    // of another (a bright line through the 3x3, not a lone sample).
    EXPECT_TRUE(temporalTapsContradict(taps({0.5f, 0.5f, 0.5f, 3.0f, 3.0f, 0.5f, 0.5f, 0.5f, 0.5f})));
    EXPECT_TRUE(temporalTapsContradict(taps({0.5f, 0.5f, 0.5f, 0.5f, 7.9f, 0.5f, 0.5f, 0.5f, 2.0f})));
    EXPECT_FALSE(temporalTapsContradict(taps({0.5f, 0.5f, 0.5f, 0.5f, 8.1f, 0.5f, 0.5f, 0.5f, 2.0f})));
    // One that leaves: dropped, even from a single tap (a fall is never left out).
    TemporalTaps left = temporalTapsNone();
    for (int i = 0; i < 9; ++i) left = temporalTapAdd(left, i == 4 ? 0.0f : 0.5f, i == 4 ? 8.0f : 0.5f, kVariance);
    EXPECT_TRUE(temporalTapsContradict(left));
    // A dark history: equal photons are no firefly, three start a new history (more than 2 quanta); a
    // lone bright photon does not.
    TemporalTaps three = temporalTapsNone(), lone = temporalTapsNone();
    for (int i = 0; i < 9; ++i) {
        three = temporalTapAdd(three, i < 3 ? 1.0f : 0.0f, 0.0f, 0.0f);
        lone = temporalTapAdd(lone, i == 0 ? 30.0f : 0.0f, 0.0f, 0.0f);
    }
    EXPECT_TRUE(temporalTapsContradict(three));
    EXPECT_FALSE(temporalTapsContradict(lone));
}

// The second type's rule (temporalVerdict with confirmRises): one photon lies in the gather disks of
// several neighbouring pixels, so three lit taps over a dark history may be one photon; such a rise keeps
// the history and waits a frame, and drops it only when that frame had risen too. A fall drops it at once.
TEST(TemporalBody, SecondTypeRiseDropsTheHistoryOnlyWhenTheFrameBeforeRoseToo) {
    TemporalTaps dash = temporalTapsNone();   // one photon's dash over a dark history
    for (int i = 0; i < 9; ++i) dash = temporalTapAdd(dash, i < 3 ? 1.0f : 0.0f, 0.0f, 0.0f);
    ASSERT_TRUE(temporalTapsContradict(dash));
    ASSERT_TRUE(temporalTapsRose(dash));
    EXPECT_EQ(temporalVerdict(dash, false, false), kTemporalDrop) << "the first type: three photons moved in";
    EXPECT_EQ(temporalVerdict(dash, true, false), kTemporalKeepRisePending);
    EXPECT_EQ(temporalVerdict(dash, true, true), kTemporalDrop) << "a rise two frames running: the caustic moved in";
    TemporalTaps left = temporalTapsNone();   // a caustic that left
    for (int i = 0; i < 9; ++i) left = temporalTapAdd(left, 0.0f, 2.0f, 0.01f);
    ASSERT_TRUE(temporalTapsContradict(left));
    EXPECT_FALSE(temporalTapsRose(left));
    EXPECT_EQ(temporalVerdict(left, true, false), kTemporalDrop);
    const float still[9] = {0.5f, 0.6f, 0.4f, 0.5f, 0.55f, 0.45f, 0.5f, 0.5f, 0.5f};
    EXPECT_EQ(temporalVerdict(taps(still), true, true), kTemporalKeep) << "nothing changed: the pending rise clears";
    // The firefly is left out of the direction too: a lone bright tap over a history that fell elsewhere.
    TemporalTaps fireflyAndFall = temporalTapsNone();
    for (int i = 0; i < 9; ++i) fireflyAndFall = temporalTapAdd(fireflyAndFall, i == 4 ? 40.0f : 0.1f, 0.5f, kVariance);
    ASSERT_TRUE(temporalTapsContradict(fireflyAndFall));
    EXPECT_FALSE(temporalTapsRose(fireflyAndFall));
    EXPECT_EQ(temporalVerdict(fireflyAndFall, true, false), kTemporalDrop);
}

}  // namespace
}  // namespace caustics::shader
