#pragma once
// Steers the photons per frame towards a GPU-time target for the caustic passes
// (CausticsSettings::causticTimeTargetMs; docs/caustics.md, "Photon budget").
//
// The caustic passes cost a part that follows the photons (caustics.forward and caustics.gather, whose
// work is the photons and their stored hits) and a part that does not (maps, setup, the second type's
// camera-side passes, resolve), which moves with the view and is large at 4K. Each measured frame is
// matched with the budget it ran with (the n-th timed caustics.forward is the n-th frame planned with a
// forward pass; timestamps arrive frames late), the budget whose photon part fills the target minus the
// fixed part is solved for, and the budget moves half-way there (at most x2 or /2 per frame): the steps
// still in flight on a 3-frame delay then add up to no overshoot (photon_budget_test.cpp).
#include <cstdint>
#include <deque>
#include <optional>

namespace caustics {

// One frame's caustic time as the render graph measured it.
struct CausticTimeSample {
    uint64_t forwardOrdinal = 0;   // which timed caustics.forward (0-based) it is
    double totalMs = 0.0;          // every caustics.* pass
    double photonMs = 0.0;         // caustics.forward + caustics.gather
};

class PhotonBudgetController {
public:
    static constexpr uint32_t kDefaultStart = 1u << 18;
    static constexpr uint32_t kMinPhotons = 1024;
    static constexpr uint32_t kMaxPhotons = 1u << 28;   // CausticsSettings::kMaxPhotonsPerFrame

    // start: the first frame's budget (0: kDefaultStart).
    explicit PhotonBudgetController(uint32_t start = 0);

    // The budget of a frame that records a forward pass; call once per such frame, in order.
    uint32_t planFrame();
    // A new measurement (none: keeps the budget). Returns the budget the next planFrame() gives.
    uint32_t update(std::optional<CausticTimeSample> sample, double targetMs);
    uint32_t photons() const { return photons_; }

private:
    uint32_t photons_;
    uint64_t planned_ = 0;                      // frames planned so far (the next one's ordinal)
    std::deque<uint32_t> history_;              // budgets of ordinals [planned_ - size, planned_)
    uint64_t lastOrdinal_ = ~0ull;
};

}  // namespace caustics
