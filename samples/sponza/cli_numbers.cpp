#include "cli_numbers.h"

#include <charconv>

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

}  // namespace caustics::sample
