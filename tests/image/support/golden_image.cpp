#include "golden_image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace caustics::test {

namespace OIIO = OIIO_NAMESPACE;

RgbImage rgbFromRgba(const std::vector<float>& rgba, uint32_t width, uint32_t height) {
    RgbImage out{width, height, std::vector<float>(size_t(width) * height * 3)};
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = rgba[4 * i + c];
    return out;
}

bool writeExr(const std::string& path, const RgbImage& image, bool halfFloat) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec{int(image.width), int(image.height), 3, halfFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT};
    spec.attribute("compression", "zip");
    if (!out->open(path, spec)) return false;
    bool ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
    out->close();
    return ok;
}

std::optional<RgbImage> readExr(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in || in->spec().nchannels < 3) return std::nullopt;
    RgbImage image{uint32_t(in->spec().width), uint32_t(in->spec().height), {}};
    image.rgb.resize(size_t(image.width) * image.height * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data())) return std::nullopt;
    return image;
}

bool updateGoldenRequested() {
    const char* update = std::getenv("UPDATE_GOLDEN");
    return update && std::string(update) == "1";
}

ImageDiff compareImages(const RgbImage& actual, const RgbImage& golden, double pixelRelative, double pixelAbsolute) {
    ImageDiff d;
    d.absoluteDifference = RgbImage{actual.width, actual.height, std::vector<float>(actual.rgb.size())};
    double sumSq = 0.0, sumGolden = 0.0, sumActual = 0.0;
    size_t off = 0;
    const size_t pixels = size_t(actual.width) * actual.height;
    for (size_t i = 0; i < pixels; ++i) {
        bool pixelOff = false;
        for (int c = 0; c < 3; ++c) {
            double a = actual.rgb[3 * i + c], g = golden.rgb[3 * i + c];
            double diff = a - g;
            sumSq += diff * diff;
            sumGolden += std::abs(g);
            sumActual += a;
            d.absoluteDifference.rgb[3 * i + c] = float(std::abs(diff));
            if (std::abs(diff) > pixelRelative * std::abs(g) + pixelAbsolute) pixelOff = true;
        }
        off += pixelOff ? 1 : 0;
    }
    const double values = double(actual.rgb.size());
    d.relativeRmse = std::sqrt(sumSq / values) / std::max(sumGolden / values, 1e-30);
    d.energyRatio = sumActual / std::max(sumGolden, 1e-30);
    d.offFraction = double(off) / double(std::max<size_t>(pixels, 1));
    return d;
}

}  // namespace caustics::test
