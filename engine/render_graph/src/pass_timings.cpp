#include "caustics/render_graph/pass_timings.h"

#include <algorithm>
#include <vector>

namespace caustics::rg {

void PassTimings::setWindow(uint32_t frames) {
    window_ = frames ? frames : 1;
    for (auto& [name, samples] : samples_)
        while (samples.size() > window_) samples.pop_front();
}

void PassTimings::add(const std::string& pass, double milliseconds) {
    auto& samples = samples_[pass];
    samples.push_back(milliseconds);
    ++added_[pass];
    while (samples.size() > window_) samples.pop_front();
}

std::optional<double> PassTimings::medianMs(std::string_view pass) const {
    auto it = samples_.find(pass);
    if (it == samples_.end() || it->second.empty()) return std::nullopt;
    std::vector<double> sorted(it->second.begin(), it->second.end());
    std::sort(sorted.begin(), sorted.end());
    size_t n = sorted.size();
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

std::optional<double> PassTimings::latestMs(std::string_view pass) const {
    auto it = samples_.find(pass);
    if (it == samples_.end() || it->second.empty()) return std::nullopt;
    return it->second.back();
}

std::optional<double> PassTimings::latestTotalMs(std::string_view prefix) const {
    double total = 0.0;
    bool any = false;
    for (auto it = samples_.lower_bound(prefix); it != samples_.end() && it->first.starts_with(prefix); ++it) {
        if (it->second.empty()) continue;
        total += it->second.back();
        any = true;
    }
    return any ? std::optional<double>(total) : std::nullopt;
}

uint64_t PassTimings::samplesAdded(std::string_view pass) const {
    auto it = added_.find(pass);
    return it == added_.end() ? 0u : it->second;
}

uint32_t PassTimings::sampleCount(std::string_view pass) const {
    auto it = samples_.find(pass);
    return it == samples_.end() ? 0u : uint32_t(it->second.size());
}

}  // namespace caustics::rg
