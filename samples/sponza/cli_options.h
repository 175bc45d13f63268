#pragma once
// Command-line options of the Sponza sample (headless and windowed). Parsing never exits or throws:
// a bad option yields an error naming the option and the accepted range.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/caustics_settings.h"
#include "caustics/rhi/result.h"
#include "animation_options.h"
#include "sample_controls.h"

namespace caustics::sample {

enum class Aov { Final, Albedo, Normal, Depth, Direct, Caustics };

struct CameraOverride {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f};
    float verticalFovDegrees = 45.0f;
    std::optional<glm::vec3> up;          // unit; absent: +Y, or a robust choice when looking along Y
};

struct CliOptions {
    std::string scene = "builtin";        // glTF path, "builtin", "builtin:table" or "builtin:atrium"
    std::string assetRoot;                // --asset-root: scene::LoadOptions::assetRoot (empty: the model's folder)
    std::string sponzaPath;               // modified Sponza: a glTF to which the caustic objects are added
    std::string backend = "vulkan";
    uint32_t width = 512;
    uint32_t height = 384;
    std::optional<CameraOverride> camera;
    std::string outPath;                  // .png or .exr; empty in windowed mode = none
    Aov aov = Aov::Final;
    uint32_t frames = 1;
    bool framesGiven = false;             // --window: close after --frames frames (scripted runs)
    std::string graphDotPath;
    bool window = false;
    std::string scriptPath;               // --window --script FILE: per-frame commands (script.h)
    bool reference = false;               // also render the CPU reference light tracer
    uint32_t referencePhotons = 2'000'000;
    // Caustic settings (see CausticsSettings for meaning and defaults).
    uint32_t mapResolution = 512;
    float raysPerTexel = 1.0f;
    uint32_t maxDepth = 4;
    uint32_t maxStoredHits = 1u << 20;
    bool filter = true;
    bool filterSecondTypeApart = CausticsSettings{}.filterSecondTypeApart;
    bool secondType = true;
    bool mapOccluders = false;
    float exposure = 1.0f;
    SampleControls controls;              // --seed, --accumulate, --sphere-* (sample_controls.h)
    AnimationOptions animation;           // --animate, --animate-speed, --animate-frames (animation_options.h)
    // --set FIELD=VALUE (repeatable): any CausticsSettings field by its C++ name (settings_fields.h), applied
    // after the options above, in order; the viewer's `set` command takes the same names and values.
    std::vector<std::pair<std::string, std::string>> settingFields;
    bool validation = false;
    bool help = false;
};

// argv[0] is skipped.
Result<CliOptions> parseCliOptions(const std::vector<std::string>& args);
const char* cliUsage();
const char* aovName(Aov aov);

}  // namespace caustics::sample
