#pragma once
// The last guard against non-finite radiance (docs/viewer.md, "Untrusted glTF"): the loader clamps
// lights and emission, but radiance can still overflow the renderer's half-float targets (about 6.5e4
// cd/m^2) near a bright light. Every image the headless sample writes goes through here: NaN or inf
// pixels are written as 0 and reported, never passed on silently.
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/rhi/result.h"

namespace caustics::sample {

// Pixels of an RGBA32F image with a NaN or infinite channel.
size_t countNonFinitePixels(const std::vector<float>& rgba);

// As writeRenderedImage (image_file.h), with the non-finite pixels of `hdr` set to 0 and a warning on
// stderr naming the file and the count.
Status writeFiniteRenderedImage(const std::string& path, uint32_t width, uint32_t height,
                                const std::vector<uint8_t>& display, const std::vector<float>& hdr);

}  // namespace caustics::sample
