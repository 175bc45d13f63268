#pragma once
// Numbers on the command line. Whole numbers, for every option that takes one: garbage is "not a whole
// number", a number too large for 32 bits is "out of range", one outside the option's range is "outside".
#include <cstdint>
#include <string>

#include "caustics/rhi/result.h"

namespace caustics::sample {

Result<uint32_t> parseWholeNumber(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi);

// A finite number in [lo, hi]; one past the float range (1e39) is "outside", not "not a number".
Result<float> parseNumberIn(const std::string& option, const std::string& text, float lo, float hi);
// A finite number in (0, hi]: zero and negatives are refused, not clamped.
Result<float> parsePositiveNumber(const std::string& option, const std::string& text, float hi);

}  // namespace caustics::sample
