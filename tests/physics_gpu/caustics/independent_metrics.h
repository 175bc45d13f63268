#pragma once
// Measures of a second-type image against the independent reference (second_type_independent_test.cpp):
// 3x3 peak and its position, energy, and an optional dump for looking at the images.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image_analysis.h"

namespace caustics::test {

struct PeakAt {
    double value = 0.0;
    double x = 0.0, y = 0.0;   // pixel centre of the brightest 3x3 box, refined by the box's centroid
};

inline double lum(const glm::dvec3& v) { return 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z; }

inline std::vector<double> luminances(const std::vector<glm::vec3>& img) {
    std::vector<double> l(img.size());
    for (size_t i = 0; i < img.size(); ++i) l[i] = luminance(img[i]);
    return l;
}

inline std::vector<double> luminances(const std::vector<glm::dvec3>& img) {
    std::vector<double> l(img.size());
    for (size_t i = 0; i < img.size(); ++i) l[i] = lum(img[i]);
    return l;
}

inline PeakAt peak3x3At(const std::vector<double>& l, uint32_t size) {
    PeakAt p;
    for (uint32_t y = 1; y + 1 < size; ++y)
        for (uint32_t x = 1; x + 1 < size; ++x) {
            double sum = 0.0, sx = 0.0, sy = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    double v = l[size_t(y + dy) * size + x + dx];
                    sum += v;
                    sx += v * (x + dx + 0.5);
                    sy += v * (y + dy + 0.5);
                }
            if (sum / 9.0 > p.value) p = {sum / 9.0, sx / sum, sy / sum};
        }
    return p;
}

// Centre of the brightest feature: the luminance-weighted centroid of the pixels within `window` px of
// (cx, cy) that exceed half of the largest value there. Steadier than the 3x3 argmax on a flat-topped
// caustic (a disk, a band), where the argmax hops between nearly equal boxes from one seed to the next.
inline void featureCentroid(const std::vector<double>& l, uint32_t size, double cx, double cy, double window, double& x, double& y) {
    double top = 0.0;
    auto inside = [&](uint32_t px, uint32_t py) { return std::hypot(px + 0.5 - cx, py + 0.5 - cy) <= window; };
    for (uint32_t py = 0; py < size; ++py)
        for (uint32_t px = 0; px < size; ++px)
            if (inside(px, py)) top = std::max(top, l[size_t(py) * size + px]);
    double sw = 0.0, sx = 0.0, sy = 0.0;
    for (uint32_t py = 0; py < size; ++py)
        for (uint32_t px = 0; px < size; ++px) {
            double v = l[size_t(py) * size + px];
            if (!inside(px, py) || v < 0.5 * top) continue;
            sw += v;
            sx += v * (px + 0.5);
            sy += v * (py + 0.5);
        }
    x = sw > 0.0 ? sx / sw : cx;
    y = sw > 0.0 ? sy / sw : cy;
}

inline double total(const std::vector<double>& l) {
    double s = 0.0;
    for (double v : l) s += v;
    return s;
}

// CAUSTICS_INDEPENDENT_DUMP=DIR writes DIR/<name>.pfm (little-endian greyscale PFM, row 0 = bottom).
inline void dumpLuminance(const std::string& name, const std::vector<double>& l, uint32_t size) {
    const char* dir = std::getenv("CAUSTICS_INDEPENDENT_DUMP");
    if (!dir) return;
    std::string path = std::string(dir) + "/" + name + ".pfm";
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "Pf\n%u %u\n-1.0\n", size, size);
    for (uint32_t y = size; y-- > 0;)
        for (uint32_t x = 0; x < size; ++x) {
            float v = float(l[size_t(y) * size + x]);
            std::fwrite(&v, 4, 1, f);
        }
    std::fclose(f);
}

}  // namespace caustics::test
