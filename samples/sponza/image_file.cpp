#include "image_file.h"

#include <OpenImageIO/imageio.h>

namespace caustics::sample {

namespace OIIO = OIIO_NAMESPACE;

Status writeImage(const std::string& path, const FloatImage& image) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return makeError("cannot write '" + path + "': " + OIIO::geterror());
    OIIO::ImageSpec spec(int(image.width), int(image.height), int(image.channels), OIIO::TypeDesc::FLOAT);
    if (!out->open(path, spec)) return makeError("cannot open '" + path + "': " + out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()))
        return makeError("cannot write '" + path + "': " + out->geterror());
    out->close();
    return okStatus();
}

Status writeImage8(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return makeError("cannot write '" + path + "': " + OIIO::geterror());
    OIIO::ImageSpec spec(int(width), int(height), 4, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec)) return makeError("cannot open '" + path + "': " + out->geterror());
    if (!out->write_image(OIIO::TypeDesc::UINT8, rgba8.data()))
        return makeError("cannot write '" + path + "': " + out->geterror());
    out->close();
    return okStatus();
}

Status writeRenderedImage(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& display,
                          const std::vector<float>& hdr) {
    bool exr = path.size() > 4 && path.substr(path.size() - 4) == ".exr";
    return exr ? writeImage(path, FloatImage{width, height, 4, hdr}) : writeImage8(path, width, height, display);
}

Result<FloatImage> readImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return makeError("cannot read '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    FloatImage image;
    image.width = uint32_t(spec.width);
    image.height = uint32_t(spec.height);
    image.channels = uint32_t(spec.nchannels);
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        return makeError("cannot decode '" + path + "': " + in->geterror());
    return image;
}

}  // namespace caustics::sample
