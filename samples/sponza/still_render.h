#pragma once
// Headless rendering of the sample's output image: --frames N frames (the temporal filter sees them
// all, the last is kept), or with --accumulate N the mean of N unfiltered frames, each with its own
// random key (frame index f, CausticsSettings::seed): a reference-quality still.
#include "cli_options.h"
#include "frame_renderer.h"

namespace caustics::sample {

Result<FrameImages> renderStill(FrameRenderer& renderer, const scene::Camera& camera, const CliOptions& options);

}  // namespace caustics::sample
