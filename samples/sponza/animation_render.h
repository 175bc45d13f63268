#pragma once
// Headless --animate-frames N: N frames of the animation (scene_animation.h), the clocks advanced by
// kFixedFrameSeconds per frame so the run is deterministic; each frame rewrites the module's live
// scene (instances and lights), nothing is rebuilt. With kFrameToken in --out every frame is written.
#include "cli_options.h"
#include "frame_renderer.h"
#include "caustics/scene/scene.h"

namespace caustics::sample {

// `scene` is the one the renderer's module reads; it is left in the last frame's pose.
Result<FrameImages> renderAnimation(FrameRenderer& renderer, scene::Scene& scene, const scene::Camera& camera,
                                    const CliOptions& options);

}  // namespace caustics::sample
