#pragma once
// Steers the photons per frame towards a GPU-time target for the caustic passes
// (CausticsSettings::causticTimeTargetMs; docs/caustics.md, "Photon budget").
//
// The caustic passes cost a fixed part (maps, setup, resolve) plus a part that grows with the photons;
// the timestamps that measure them arrive framesInFlight frames late. A multiplicative step towards the
// target, damped (fourth root of target / measured, at most x2 or /2 per frame), settles on the budget
// whose time is the target without oscillating on a 3-frame delay (a square root overshoots there: the
// three steps in flight add up); from 16x off it is within 1 % after 30 frames (photon_budget_test.cpp).
// A frame without a new measurement keeps the budget.
#include <cstdint>
#include <optional>

namespace caustics {

class PhotonBudgetController {
public:
    static constexpr uint32_t kDefaultStart = 1u << 18;
    static constexpr uint32_t kMinPhotons = 1024;
    static constexpr uint32_t kMaxPhotons = 1u << 28;   // CausticsSettings::kMaxPhotonsPerFrame

    // start: the first frame's budget (0: kDefaultStart).
    explicit PhotonBudgetController(uint32_t start = 0);

    // The budget for the next frame, given the caustic passes' time of the newest measured frame (ms)
    // and the target (ms). No measurement, or a non-positive one: unchanged.
    uint32_t update(std::optional<double> measuredMs, double targetMs);
    uint32_t photons() const { return photons_; }

private:
    uint32_t photons_;
};

}  // namespace caustics
