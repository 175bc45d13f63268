#include "animation_options.h"

#include <cstdio>
#include <sstream>

#include "cli_numbers.h"

namespace caustics::sample {
namespace {

// "objects", "light:N", comma-separated.
Status parseAnimateList(const std::string& text, AnimationToggles& toggles) {
    std::stringstream stream(text);
    std::string item;
    bool any = false;
    while (std::getline(stream, item, ',')) {
        any = true;
        if (item == "objects") {
            toggles.objects = true;
        } else if (item.rfind("light:", 0) == 0) {
            CAUSTICS_TRY(uint32_t light, parseWholeNumber("--animate " + item, item.substr(6), 0, 1u << 20));
            toggles.orbitingLights.insert(light);
        } else {
            return makeError("--animate: '" + item + "' is not objects or light:N (comma-separated)");
        }
    }
    if (!any) return makeError("--animate: the list is empty (objects, light:N)");
    return okStatus();
}

}  // namespace

Result<bool> parseAnimationOption(const std::string& option, const std::string& value, AnimationOptions& o) {
    if (option == "--animate") {
        CAUSTICS_CHECK(parseAnimateList(value, o.toggles));
        o.togglesGiven = true;
    } else if (option == "--animate-speed") {
        CAUSTICS_TRY(o.toggles.speed, parsePositiveNumber(option, value, kMaxAnimationSpeed));
    } else if (option == "--animate-frames") {
        CAUSTICS_TRY(o.frames, parseWholeNumber(option, value, 1, kMaxAnimationFrames));
    } else {
        return false;
    }
    return true;
}

Status finishAnimationOptions(AnimationOptions& o, bool window, bool framesGiven, uint32_t accumulate) {
    if (o.frames == 0) return okStatus();
    if (window) return makeError("--animate-frames: renders headless; with --window use --animate (and --frames to stop)");
    if (framesGiven) return makeError("--animate-frames N renders N frames itself; leave out --frames");
    if (accumulate > 0) return makeError("--animate-frames: a moving scene cannot be accumulated; leave out --accumulate");
    if (!o.togglesGiven) o.toggles.objects = true;
    return okStatus();
}

Status checkAnimatedLights(const AnimationToggles& toggles, size_t lightCount, const std::string& where) {
    for (uint32_t light : toggles.orbitingLights)
        if (light >= lightCount)
            return makeError(where + ": light " + std::to_string(light) + " does not exist (the scene has " +
                             std::to_string(lightCount) + " lights)");
    return okStatus();
}

std::string framePath(const std::string& pattern, uint32_t frame) {
    char number[16];
    std::snprintf(number, sizeof(number), "%04u", frame);
    const size_t token = std::char_traits<char>::length(kFrameToken);
    std::string path = pattern;
    for (size_t at = path.find(kFrameToken); at != std::string::npos; at = path.find(kFrameToken, at))
        path.replace(at, token, number);   // every {frame}: the name written is the name reported
    return path;
}

const char* animationUsage() {
    return "  --animate LIST          animate: objects (the glass moves along a path), light:N (light N orbits\n"
           "                          the glass); comma-separated. In the viewer: the start toggles\n"
           "  --animate-speed X       animation clock rate (default 1: one loop in 8 s; at most 100)\n"
           "  --animate-frames N      headless: render N frames of the animation, 1/30 s apart; --out FILE\n"
           "                          gets the last one, or every one when FILE contains {frame}\n";
}

}  // namespace caustics::sample
