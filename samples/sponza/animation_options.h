#pragma once
// Command-line options of the animation (scene_animation.h): which things move, how fast, and the
// headless run of N animated frames. Parsing never throws; errors name the option and the range.
#include <cstdint>
#include <string>

#include "caustics/rhi/result.h"
#include "scene_animation.h"

namespace caustics::sample {

struct AnimationOptions {
    AnimationToggles toggles;        // --animate objects,light:N  --animate-speed X
    bool togglesGiven = false;
    uint32_t frames = 0;             // --animate-frames N: headless, N frames of the animation
};

inline constexpr uint32_t kMaxAnimationFrames = 100000;
// --out FILE with this token writes every animated frame, the token replaced by the frame number.
inline constexpr const char* kFrameToken = "{frame}";

// If `option` is an animation option, parses `value` into `options` and returns true; false for any
// other option, an error for a bad value.
Result<bool> parseAnimationOption(const std::string& option, const std::string& value, AnimationOptions& options);

// Checks across options: --animate-frames is headless and replaces --frames and --accumulate;
// without --animate it moves the glass objects. Fills the default toggles.
Status finishAnimationOptions(AnimationOptions& options, bool window, bool framesGiven, uint32_t accumulate);

// After the scene is loaded: every orbiting light exists (the error names the index and the count).
Status checkAnimatedLights(const AnimationToggles& toggles, size_t lightCount, const std::string& where);

// `pattern` with every kFrameToken replaced by the zero-padded frame number (unchanged without the token).
std::string framePath(const std::string& pattern, uint32_t frame);

const char* animationUsage();

}  // namespace caustics::sample
