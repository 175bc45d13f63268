#include "cli_numbers.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace caustics::sample {

Result<uint32_t> parseWholeNumber(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi) {
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    // from_chars reports a well-formed number too large for 32 bits apart from garbage.
    if (ec == std::errc::result_out_of_range && end == text.data() + text.size())
        return makeError(option + ": " + text + " is out of range " + range);
    if (ec != std::errc() || end != text.data() + text.size())
        return makeError(option + ": '" + text + "' is not a whole number in " + range);
    if (value < lo || value > hi) return makeError(option + ": " + text + " is outside " + range);
    return value;
}

Result<float> parsePositiveNumber(const std::string& option, const std::string& text, float hi) {
    char* end = nullptr;
    float value = std::strtof(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
        return makeError(option + ": '" + text + "' is not a number");
    if (value <= 0.0f || value > hi) {
        std::ostringstream s;
        s << option << ": " << text << " is outside (0, " << hi << "]";
        return makeError(s.str());
    }
    return value;
}

}  // namespace caustics::sample
