#pragma once
// FrameInputs::outputTarget, outputWrite and outputScale checked before any pass is declared
// (docs/embedding.md "Output target"): caustics-only draws into any format causticsOutputFormatSupported
// accepts (RenderTarget usage); the display path stores RGBA8_UNORM through a storage image and only
// replaces. The error names the field, the texture, its format and what is needed.
#include "caustics/caustics_module.h"

namespace caustics {

Status checkOutputTarget(const FrameInputs& inputs, bool causticsOnly);

}  // namespace caustics
