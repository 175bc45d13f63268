#include "finite_output.h"

#include <cmath>
#include <cstdio>

#include "image_file.h"

namespace caustics::sample {

size_t countNonFinitePixels(const std::vector<float>& rgba) {
    size_t count = 0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4)
        if (!std::isfinite(rgba[i]) || !std::isfinite(rgba[i + 1]) || !std::isfinite(rgba[i + 2]) || !std::isfinite(rgba[i + 3]))
            ++count;
    return count;
}

Status writeFiniteRenderedImage(const std::string& path, uint32_t width, uint32_t height,
                                const std::vector<uint8_t>& display, const std::vector<float>& hdr) {
    size_t bad = countNonFinitePixels(hdr);
    if (bad == 0) return writeRenderedImage(path, width, height, display, hdr);
    std::fprintf(stderr,
                 "caustics-sponza: warning: %s: %zu of %zu pixels have non-finite radiance (NaN or inf), written as 0; "
                 "the scene's radiance overflows the renderer's half-float range (about 6.5e4 cd/m^2): lower the "
                 "brightest light or emission (see the loader's warnings)\n",
                 path.c_str(), bad, size_t(width) * height);
    std::vector<float> finite = hdr;
    for (float& v : finite)
        if (!std::isfinite(v)) v = 0.0f;
    return writeRenderedImage(path, width, height, display, finite);
}

}  // namespace caustics::sample
