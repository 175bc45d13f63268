#pragma once
// Per-pass GPU time as the median over the last N frames (median, not mean: one frame stalled by the
// OS or a shader compile should not move the number).
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace caustics::rg {

class PassTimings {
public:
    explicit PassTimings(uint32_t window = 32) : window_(window ? window : 1) {}

    void setWindow(uint32_t frames);
    uint32_t window() const { return window_; }
    void add(const std::string& pass, double milliseconds);
    std::optional<double> medianMs(std::string_view pass) const;
    std::optional<double> latestMs(std::string_view pass) const;   // the newest sample (history plots)
    uint32_t sampleCount(std::string_view pass) const;
    // Sum of the newest sample of every pass whose name starts with `prefix` (e.g. "caustics."): one
    // frame's cost of a pass family; none when no such pass was timed.
    std::optional<double> latestTotalMs(std::string_view prefix) const;
    // Samples of `pass` ever added (never capped by the window): which execution of the pass the newest
    // sample measures (the count minus one).
    uint64_t samplesAdded(std::string_view pass) const;
    void clear() { samples_.clear(); }

private:
    uint32_t window_;
    std::map<std::string, uint64_t, std::less<>> added_;
    std::map<std::string, std::deque<double>, std::less<>> samples_;
};

}  // namespace caustics::rg
