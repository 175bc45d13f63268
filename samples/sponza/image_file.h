#pragma once
// Writes images with OpenImageIO: .exr keeps linear float values, .png gets 8-bit values as given.
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/rhi/result.h"

namespace caustics::sample {

struct FloatImage {
    uint32_t width = 0, height = 0, channels = 4;
    std::vector<float> pixels;   // row-major, top row first
};

Status writeImage(const std::string& path, const FloatImage& image);
Status writeImage8(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8);
Result<FloatImage> readImage(const std::string& path);
// A rendered frame to `path`: .exr gets the linear RGBA32F `hdr`, anything else the RGBA8 `display`.
Status writeRenderedImage(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& display,
                          const std::vector<float>& hdr);

}  // namespace caustics::sample
