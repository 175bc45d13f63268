#include <algorithm>

#include "viewer_state.h"

namespace caustics::sample {

void History::add(float value) {
    values_.push_back(value);
    if (values_.size() > kLength) values_.erase(values_.begin());
}

float History::median() const {
    if (values_.empty()) return 0.0f;
    std::vector<float> sorted = values_;
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    return sorted[sorted.size() / 2];
}

}  // namespace caustics::sample
