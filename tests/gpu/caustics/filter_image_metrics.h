#pragma once
// Measures the caustic filter tests compare images with: luminance energy, relative L1 against a
// reference, and the 3x3 mean around a point (the "3x3 peak"). Images are row-major, row 0 = top.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace caustics::test {

inline double filterLuminance(const glm::vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

inline double energy(const std::vector<glm::vec3>& img) {
    double sum = 0.0;
    for (const glm::vec3& c : img) sum += filterLuminance(c);
    return sum;
}

// sum |l - l_ref| / sum l_ref over the whole image.
inline double relativeL1(const std::vector<glm::vec3>& img, const std::vector<glm::vec3>& ref) {
    double diff = 0.0, total = 0.0;
    for (size_t i = 0; i < img.size() && i < ref.size(); ++i) {
        diff += std::abs(filterLuminance(img[i]) - filterLuminance(ref[i]));
        total += filterLuminance(ref[i]);
    }
    return total > 0.0 ? diff / total : 0.0;
}

inline double mean3x3(const std::vector<glm::vec3>& img, uint32_t w, uint32_t h, int x, int y) {
    double sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int qx = glm::clamp(x + dx, 0, int(w) - 1), qy = glm::clamp(y + dy, 0, int(h) - 1);
            sum += filterLuminance(img[size_t(qy) * w + size_t(qx)]);
        }
    return sum / 9.0;
}

struct PeakLocation {
    int x = 0, y = 0;
    double value = 0.0;   // 3x3 mean luminance
};

// Where the 3x3 mean luminance is largest.
inline PeakLocation brightest3x3(const std::vector<glm::vec3>& img, uint32_t w, uint32_t h) {
    PeakLocation best;
    for (uint32_t y = 1; y + 1 < h; ++y)
        for (uint32_t x = 1; x + 1 < w; ++x) {
            double v = mean3x3(img, w, h, int(x), int(y));
            if (v > best.value) best = {int(x), int(y), v};
        }
    return best;
}

// With CAUSTICS_FILTER_IMAGES=<folder> set, writes the luminance as an 8-bit PGM scaled so that `white`
// maps to 255 (for looking at the images; nothing is written otherwise).
inline void dumpLuminance(const std::string& name, const std::vector<glm::vec3>& img, uint32_t w, uint32_t h,
                          double white) {
    const char* folder = std::getenv("CAUSTICS_FILTER_IMAGES");
    if (!folder || white <= 0.0) return;
    FILE* f = std::fopen((std::string(folder) + "/" + name + ".pgm").c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "P5\n%u %u\n255\n", w, h);
    for (const glm::vec3& c : img) {
        double v = std::sqrt(glm::clamp(filterLuminance(c) / white, 0.0, 1.0));   // gamma 2 for the dark tail
        std::fputc(int(v * 255.0 + 0.5), f);
    }
    std::fclose(f);
    FILE* raw = std::fopen((std::string(folder) + "/" + name + ".f32").c_str(), "wb");
    if (!raw) return;
    for (const glm::vec3& c : img) {
        float l = float(filterLuminance(c));
        std::fwrite(&l, 4, 1, raw);
    }
    std::fclose(raw);
}

}  // namespace caustics::test
