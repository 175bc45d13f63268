#pragma once
// Golden images of tests/image: linear RGB, stored as half-float EXR (relative step 2^-11 = 0.05 %).
// Regenerate every golden with scripts/update-goldens.sh (UPDATE_GOLDEN=1 for the image tests).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace caustics::test {

struct RgbImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgb;  // 3 floats per pixel, row 0 at the top
};

// The RGB of an RGBA32F readback.
RgbImage rgbFromRgba(const std::vector<float>& rgba, uint32_t width, uint32_t height);

bool writeExr(const std::string& path, const RgbImage& image, bool halfFloat);
std::optional<RgbImage> readExr(const std::string& path);

// UPDATE_GOLDEN=1 in the environment: the test writes its golden instead of comparing.
bool updateGoldenRequested();

struct ImageDiff {
    double relativeRmse = 0.0;    // sqrt(mean((a - g)^2)) / mean(|g|), over all channels
    double energyRatio = 0.0;     // sum(a) / sum(g)
    double offFraction = 0.0;     // pixels with a channel off by more than pixelRelative |g| + pixelAbsolute
    RgbImage absoluteDifference;  // |a - g| per channel
};

// Mean over factor x factor blocks (edges: the partial blocks' own means). Caustic images are
// sparse photon splats; comparing block means measures the light where it lands without letting a
// single bright splat dominate.
RgbImage boxDownsample(const RgbImage& image, uint32_t factor);

// sum |a - g| / sum |g| over all channels (equal sizes).
double relativeL1(const RgbImage& actual, const RgbImage& golden);

// Requires equal sizes (the caller checks).
ImageDiff compareImages(const RgbImage& actual, const RgbImage& golden, double pixelRelative, double pixelAbsolute);

}  // namespace caustics::test
