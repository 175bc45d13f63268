// The host's output target (caustics/output_target.h, docs/embedding.md "Output target"): the formats
// the caustics-only output draws into, and the checks of FrameInputs::outputTarget, made before any pass
// is declared so that a refusal leaves the host's graph as it was.
#include <cmath>
#include <string>

#include "output_target_check.h"

namespace caustics {

namespace {
std::string quoted(const rhi::TextureDesc& desc) { return desc.debugName.empty() ? "" : " '" + desc.debugName + "'"; }
}  // namespace

const char* outputWriteName(OutputWrite write) { return write == OutputWrite::Add ? "Add" : "Replace"; }

bool causticsOutputFormatSupported(rhi::Format format) {
    switch (format) {
        case rhi::Format::RGBA8_UNORM:
        case rhi::Format::RGBA8_SRGB:
        case rhi::Format::BGRA8_UNORM:
        case rhi::Format::RGBA16_FLOAT:
        case rhi::Format::RGBA32_FLOAT:
        case rhi::Format::R11G11B10_FLOAT:
        case rhi::Format::RGB10A2_UNORM: return true;
        default: return false;
    }
}

Status checkCausticsOutputTarget(const rhi::TextureDesc& desc, uint32_t width, uint32_t height, const char* field) {
    const std::string what = std::string("CausticsModule::addPasses: ") + field + quoted(desc) + " (" +
                             rhi::formatInfo(desc.format).name + ")";
    if (!causticsOutputFormatSupported(desc.format)) {
        const rhi::FormatInfo& info = rhi::formatInfo(desc.format);
        const char* why = "fewer than three channels (green and blue would be dropped)";
        if (info.isDepth) why = "a depth format";
        else if (info.isInteger) why = "an integer format (no blending, no colour conversion)";
        else if (desc.format == rhi::Format::RGB32_FLOAT) why = "a vertex format";
        else if (desc.format == rhi::Format::Unknown) why = "no format";
        return makeError(what + " is " + why + ": caustics-only output needs a float or unorm colour format with "
                         "three or four channels: RGBA8_UNORM, RGBA8_SRGB, BGRA8_UNORM, RGB10A2_UNORM, RGBA16_FLOAT, "
                         "R11G11B10_FLOAT or RGBA32_FLOAT");
    }
    if (!rhi::hasAny(desc.usage, rhi::TextureUsage::RenderTarget))
        return makeError(what + " lacks RenderTarget usage: the caustics are drawn into it as a colour attachment");
    if (desc.dimension != rhi::TextureDimension::Texture2D || desc.arrayLayers != 1 || desc.mipLevels != 1)
        return makeError(what + " must be a 2D texture of one layer and one mip level (it has " +
                         std::to_string(desc.arrayLayers) + " layers, " + std::to_string(desc.mipLevels) + " mips)");
    if (desc.width != width || desc.height != height)
        return makeError(what + " is " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                         ", the image (FrameInputs::width x height) is " + std::to_string(width) + "x" +
                         std::to_string(height));
    return okStatus();
}

Status checkOutputTarget(const FrameInputs& in, bool causticsOnly) {
    if (!in.outputTarget) return okStatus();
    const rhi::TextureDesc& d = in.outputTarget->desc();
    if (causticsOnly) {
        if (!std::isfinite(in.outputScale) || in.outputScale < 0.0f)
            return makeError("CausticsModule::addPasses: outputScale " + std::to_string(in.outputScale) +
                             " must be finite and >= 0 (the host's exposure of outputTarget)");
        return checkCausticsOutputTarget(d, in.width, in.height, "outputTarget");
    }
    const std::string what = "CausticsModule::addPasses: outputTarget" + quoted(d) + " (" +
                             rhi::formatInfo(d.format).name + ", " + std::to_string(d.width) + "x" +
                             std::to_string(d.height) + ")";
    if (d.format != rhi::Format::RGBA8_UNORM || !rhi::hasAny(d.usage, rhi::TextureUsage::Storage) ||
        d.width != in.width || d.height != in.height)
        return makeError(what + ": the display image needs RGBA8_UNORM with Storage usage of the image size " +
                         std::to_string(in.width) + "x" + std::to_string(in.height) +
                         " (any float or unorm colour target takes the caustics with settings.causticsOnly)");
    if (in.outputWrite != OutputWrite::Replace || in.outputScale != 1.0f)
        return makeError(what + ": outputWrite " + outputWriteName(in.outputWrite) + " and outputScale " +
                         std::to_string(in.outputScale) + " apply to settings.causticsOnly; the display image "
                         "replaces the target (Replace, 1; settings.exposure sets its exposure)");
    return okStatus();
}

}  // namespace caustics
