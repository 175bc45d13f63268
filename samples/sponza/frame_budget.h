#pragma once
// Checks an image size against the device's limits before anything is allocated, so that
// `--width 16384 --height 16384` is refused with the limit named instead of failing deep in an
// allocation after the scene has been uploaded.
#include <cstdint>

#include "caustics/caustics_settings.h"
#include "caustics/rhi/device.h"

namespace caustics::sample {

// Lower bound of the device memory one frame of W x H needs (bytes), from the per-pixel resources
// the module and the sample allocate (docs/viewer.md lists them).
uint64_t estimateFrameBytes(uint32_t width, uint32_t height, const CausticsSettings& settings);

Status checkFrameFitsDevice(const rhi::Capabilities& caps, uint32_t width, uint32_t height,
                            const CausticsSettings& settings);

}  // namespace caustics::sample
