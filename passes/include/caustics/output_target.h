#pragma once
// The host's output target (FrameInputs::outputTarget; docs/embedding.md "Output target"): which
// formats and usages the module writes into, and how.
#include <cstdint>

#include "caustics/rhi/resources.h"
#include "caustics/rhi/result.h"

namespace caustics {

// How settings.causticsOnly writes caustic radiance x FrameInputs::outputScale into the target.
enum class OutputWrite : uint8_t {
    Replace,   // target.rgb = value, alpha 1: the target holds the caustics alone
    Add,       // target.rgb += value, alpha kept: onto the host's lit HDR buffer (the usual case)
};
const char* outputWriteName(OutputWrite write);

// Formats the caustics-only output draws into: every float or unorm colour format of rhi::Format with
// three or four channels (RGBA8_UNORM, RGBA8_SRGB, BGRA8_UNORM, RGB10A2_UNORM, RGBA16_FLOAT,
// R11G11B10_FLOAT, RGBA32_FLOAT). Refused:
// integer and depth formats (no blending, no colour), one- and two-channel formats (they would drop
// green and blue without a word) and RGB32_FLOAT (vertex data only). RGBA8_SRGB is accepted: the
// hardware encodes on store and blends in linear, so the stored value is the sRGB encoding of the
// radiance (plus the decoded host value, for Add). Unorm formats clamp to [0, 1].
bool causticsOutputFormatSupported(rhi::Format format);

// Checks a caustics-only target for an image of width x height: a supported format, RenderTarget
// usage, a 2D texture of one layer and that size. The error names `field`, the texture, its format and
// what is needed.
Status checkCausticsOutputTarget(const rhi::TextureDesc& desc, uint32_t width, uint32_t height,
                                 const char* field = "outputTarget");

}  // namespace caustics
