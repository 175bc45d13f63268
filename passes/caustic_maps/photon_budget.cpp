// The time-target photon budget (caustics/photon_budget.h).
#include "caustics/photon_budget.h"

#include <algorithm>
#include <cmath>

namespace caustics {

PhotonBudgetController::PhotonBudgetController(uint32_t start)
    : photons_(std::clamp(start ? start : kDefaultStart, kMinPhotons, kMaxPhotons)) {}

uint32_t PhotonBudgetController::update(std::optional<double> measuredMs, double targetMs) {
    if (!measuredMs || !(*measuredMs > 0.0) || !(targetMs > 0.0)) return photons_;
    const double step = std::clamp(std::pow(targetMs / *measuredMs, 0.25), 0.5, 2.0);
    const double next = std::clamp(double(photons_) * step, double(kMinPhotons), double(kMaxPhotons));
    photons_ = uint32_t(next);
    return photons_;
}

}  // namespace caustics
