#include "sample_controls.h"

#include "cli_numbers.h"

namespace caustics::sample {
namespace {

Result<uint32_t> parseWhole(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi) {
    return parseWholeNumber(option, text, lo, hi);
}

}  // namespace

Result<bool> parseSampleControl(const std::string& option, const std::string& value, SampleControls& c) {
    if (option == "--seed") {
        CAUSTICS_TRY(c.seed, parseWhole(option, value, 0, 0xFFFFFFFFu));
    } else if (option == "--accumulate") {
        CAUSTICS_TRY(c.accumulate, parseWhole(option, value, 1, kMaxAccumulatedFrames));
    } else if (option == "--sphere-radius-scale") {
        CAUSTICS_TRY(c.sphereRadiusScale, parsePositiveNumber(option, value, kMaxSphereRadiusScale));
    } else if (option == "--sphere-world-radius") {
        CAUSTICS_TRY(c.sphereWorldRadius, parsePositiveNumber(option, value, kMaxSphereWorldRadius));
        c.sphereWorldRadiusGiven = true;
    } else if (option == "--sphere-radius-policy") {
        if (value == "pixel") c.sphereRadiusPolicy = SphereRadiusChoice::Pixel;
        else if (value == "world") c.sphereRadiusPolicy = SphereRadiusChoice::World;
        else return makeError("--sphere-radius-policy: '" + value + "' is not pixel or world");
    } else {
        return false;
    }
    return true;
}

Status validateSampleControls(const SampleControls& c, bool window, bool framesGiven) {
    if (c.accumulate > 0 && window) return makeError("--accumulate: writes a still image; it cannot be used with --window");
    if (c.accumulate > 0 && framesGiven)
        return makeError("--accumulate N renders N frames itself; leave out --frames");
    if (c.sphereWorldRadiusGiven && c.sphereRadiusPolicy != SphereRadiusChoice::World)
        return makeError("--sphere-world-radius: only used with --sphere-radius-policy world");
    return okStatus();
}

const char* sampleControlsUsage() {
    return "  --seed N                random seed of the caustic passes (default 1)\n"
           "  --accumulate N          average N unfiltered frames with different random keys: a\n"
           "                          reference-quality still (switches the filter off; 1..4096)\n"
           "  --sphere-radius-policy pixel|world   second-type gather radius: pixel footprint (default) or fixed\n"
           "  --sphere-radius-scale X radius in pixel footprint widths for the pixel policy (default 0.75, at most 64)\n"
           "  --sphere-world-radius X radius in metres for the world policy (default 0.01, at most 1000)\n";
}

}  // namespace caustics::sample
