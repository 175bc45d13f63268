#include "debug_marker.h"

#include <cstdint>

namespace caustics::rhi::d3d12 {

std::u16string markerPayload(std::string_view s) {
    std::u16string out;
    size_t i = 0;
    while (i < s.size()) {
        const auto b = uint8_t(s[i]);
        // Sequence length from the lead byte (RFC 3629 section 3).
        const int extra = b < 0x80 ? 0 : (b >> 5) == 0x6 ? 1 : (b >> 4) == 0xE ? 2 : (b >> 3) == 0x1E ? 3 : -1;
        uint32_t cp = extra == 0 ? b : extra == 1 ? b & 0x1F : extra == 2 ? b & 0x0F : b & 0x07;
        bool valid = extra >= 0;
        for (int k = 1; valid && k <= extra; ++k) {
            if (i + size_t(k) >= s.size() || (uint8_t(s[i + k]) >> 6) != 0x2) { valid = false; break; }
            cp = (cp << 6) | (uint8_t(s[i + k]) & 0x3F);
        }
        if (!valid) { out.push_back(u'\uFFFD'); ++i; continue; }
        i += size_t(extra) + 1;
        if (cp >= 0x10000) {   // surrogate pair (RFC 2781 section 2.1)
            cp -= 0x10000;
            out.push_back(char16_t(0xD800 + (cp >> 10)));
            out.push_back(char16_t(0xDC00 + (cp & 0x3FF)));
        } else {
            out.push_back(char16_t(cp));
        }
    }
    out.push_back(u'\0');
    return out;
}

}  // namespace caustics::rhi::d3d12
