#pragma once
// Sample controls of caustics-sponza (issue 10 item 5): the random seed, reference-quality stills by
// averaging frames, and the second-type sphere radius. Kept apart from cli_options.cpp so that the
// option list stays readable; parsing never throws and names the option and its range on error.
#include <cstdint>
#include <string>

#include "caustics/rhi/result.h"

namespace caustics::sample {

enum class SphereRadiusChoice : uint8_t { Pixel, World };

struct SampleControls {
    uint32_t seed = 1;               // CausticsSettings::seed: the RNG key of frame 0
    uint32_t accumulate = 0;         // 0: off; N: average N unfiltered frames (frame f uses key f)
    float sphereRadiusScale = 0.75f; // CausticsSettings::sphereRadiusScale (pixel policy), footprint widths
    SphereRadiusChoice sphereRadiusPolicy = SphereRadiusChoice::Pixel;
    float sphereWorldRadius = 0.01f; // CausticsSettings::sphereWorldRadius (world policy), metres
    bool sphereWorldRadiusGiven = false;
};

// Limits beyond which an option is refused (they match CausticsSettings::validate()).
inline constexpr uint32_t kMaxAccumulatedFrames = 4096;
inline constexpr float kMaxSphereRadiusScale = 64.0f;
inline constexpr float kMaxSphereWorldRadius = 1000.0f;

// If `option` is one of the sample controls, parses `value` into `controls` and returns true; returns
// false for any other option (the caller tries its own), an error for a bad value.
Result<bool> parseSampleControl(const std::string& option, const std::string& value, SampleControls& controls);

// Checks that hold across options (call after every option is parsed).
Status validateSampleControls(const SampleControls& controls, bool window, bool framesGiven);

// The usage lines of these options.
const char* sampleControlsUsage();

}  // namespace caustics::sample
