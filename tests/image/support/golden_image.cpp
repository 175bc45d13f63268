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

RgbImage boxDownsample(const RgbImage& image, uint32_t factor) {
    RgbImage out{(image.width + factor - 1) / factor, (image.height + factor - 1) / factor, {}};
    out.rgb.assign(size_t(out.width) * out.height * 3, 0.0f);
    std::vector<uint32_t> counts(size_t(out.width) * out.height, 0);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            size_t o = size_t(y / factor) * out.width + x / factor;
            ++counts[o];
            for (int c = 0; c < 3; ++c) out.rgb[3 * o + c] += image.rgb[3 * (size_t(y) * image.width + x) + c];
        }
    for (size_t o = 0; o < counts.size(); ++o)
        for (int c = 0; c < 3; ++c) out.rgb[3 * o + c] /= float(std::max(counts[o], 1u));
    return out;
}

double relativeL1(const RgbImage& actual, const RgbImage& golden) {
    double diff = 0.0, sum = 0.0;
    for (size_t i = 0; i < actual.rgb.size(); ++i) {
        diff += std::abs(double(actual.rgb[i]) - double(golden.rgb[i]));
        sum += std::abs(double(golden.rgb[i]));
    }
    return diff / std::max(sum, 1e-30);
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
