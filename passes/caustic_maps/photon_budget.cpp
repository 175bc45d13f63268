// The time-target photon budget (caustics/photon_budget.h).
#include "caustics/photon_budget.h"

#include <algorithm>
#include <cmath>

namespace caustics {
namespace {
constexpr size_t kHistory = 64;   // frames of delay the matching covers
}

PhotonBudgetController::PhotonBudgetController(uint32_t start)
    : photons_(std::clamp(start ? start : kDefaultStart, kMinPhotons, kMaxPhotons)) {}

uint32_t PhotonBudgetController::planFrame() {
    history_.push_back(photons_);
    if (history_.size() > kHistory) history_.pop_front();
    ++planned_;
    return photons_;
}

uint32_t PhotonBudgetController::update(std::optional<CausticTimeSample> s, double targetMs) {
    if (!s || s->forwardOrdinal == lastOrdinal_ || !(s->totalMs > 0.0) || !(targetMs > 0.0)) return photons_;
    lastOrdinal_ = s->forwardOrdinal;
    const uint64_t first = planned_ - history_.size();
    // The budget the measured frame ran with; unknown (older than the history): the current one.
    const double measuredPhotons = s->forwardOrdinal >= first && s->forwardOrdinal < planned_
                                       ? double(history_[size_t(s->forwardOrdinal - first)])
                                       : double(photons_);
    double wanted;
    if (s->photonMs > 0.0) {
        const double fixedMs = std::max(s->totalMs - s->photonMs, 0.0);
        wanted = targetMs > fixedMs ? measuredPhotons * (targetMs - fixedMs) / s->photonMs : 0.0;
    } else {
        wanted = measuredPhotons * targetMs / s->totalMs;
    }
    const double step = wanted > 0.0 ? std::clamp(std::sqrt(wanted / double(photons_)), 0.5, 2.0) : 0.5;
    photons_ = uint32_t(std::clamp(double(photons_) * step, double(kMinPhotons), double(kMaxPhotons)));
    return photons_;
}

}  // namespace caustics
