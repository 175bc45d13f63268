// The time-target controller (caustics/photon_budget.h) settles on the budget whose time is the target
// for a cost a + b N measured framesInFlight frames late, and keeps the budget without a new measurement.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "caustics/photon_budget.h"

namespace caustics {
namespace {

TEST(PhotonBudget, SettlesOnTheTargetWithThreeFramesOfDelay) {
    // 0.2 ms fixed + 1 ms per 2^20 photons: 1.0 ms target -> 0.8 x 2^20 photons.
    auto cost = [](uint32_t photons) { return 0.2 + double(photons) / double(1u << 20); };
    PhotonBudgetController c(1u << 16);
    std::deque<double> inFlight;
    uint32_t photons = c.photons();
    for (int frame = 0; frame < 60; ++frame) {
        inFlight.push_back(cost(photons));
        std::optional<double> measured;
        if (inFlight.size() > 3) {
            measured = inFlight.front();
            inFlight.pop_front();
        }
        photons = c.update(measured, 1.0);
    }
    EXPECT_NEAR(cost(photons), 1.0, 0.01) << photons << " photons";
}

TEST(PhotonBudget, KeepsTheBudgetWithoutANewMeasurement) {
    PhotonBudgetController c(100000);
    EXPECT_EQ(c.update(std::nullopt, 1.0), 100000u);
    EXPECT_EQ(c.update(0.0, 1.0), 100000u);
    EXPECT_EQ(c.update(2.0, 1.0), uint32_t(100000 * std::pow(0.5, 0.25)));
}

TEST(PhotonBudget, StepIsBoundedAndBudgetClamped) {
    PhotonBudgetController c(1u << 20);
    EXPECT_EQ(c.update(1e6, 1.0), 1u << 19) << "at most halved per frame";
    PhotonBudgetController low(2000);
    for (int i = 0; i < 10; ++i) low.update(1e6, 1.0);
    EXPECT_EQ(low.photons(), PhotonBudgetController::kMinPhotons);
    PhotonBudgetController high(PhotonBudgetController::kMaxPhotons);
    EXPECT_EQ(high.update(0.001, 1.0), PhotonBudgetController::kMaxPhotons);
}

}  // namespace
}  // namespace caustics
