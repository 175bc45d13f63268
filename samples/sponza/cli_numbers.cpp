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

namespace {

// Parsed in double, so a well-formed number past the float range (1e39) is "outside" the option's range
// rather than "not a number"; inf and nan are not numbers here.
Result<double> parseReal(const std::string& option, const std::string& text) {
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
        return makeError(option + ": '" + text + "' is not a number");
    return value;
}

std::string rangeText(char open, float lo, float hi) {
    std::ostringstream s;
    s << open << lo << ", " << hi << "]";
    return s.str();
}

}  // namespace

Result<float> parseNumberIn(const std::string& option, const std::string& text, float lo, float hi) {
    CAUSTICS_TRY(double value, parseReal(option, text));
    if (value < double(lo) || value > double(hi)) return makeError(option + ": " + text + " is outside " + rangeText('[', lo, hi));
    return float(value);
}

Result<float> parsePositiveNumber(const std::string& option, const std::string& text, float hi) {
    CAUSTICS_TRY(double value, parseReal(option, text));
    if (value <= 0.0 || value > double(hi)) return makeError(option + ": " + text + " is outside " + rangeText('(', 0.0f, hi));
    return float(value);
}

}  // namespace caustics::sample
