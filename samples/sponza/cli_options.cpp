#include "cli_options.h"

#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <sstream>

#include "cli_numbers.h"
#include "settings_fields.h"

namespace caustics::sample {
namespace {

// Limits that keep a run finite and the GPU allocations sane; beyond them the option is refused.
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint32_t kMaxMapResolution = 8192;
constexpr uint32_t kMaxSpecularDepth = 31;    // Vulkan guarantees maxRayRecursionDepth >= 1 only; we loop, but bound it
constexpr float kMaxRaysPerTexel = 256.0f;
constexpr uint32_t kMaxFrames = 100000;

Result<uint32_t> parseUint(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi) {
    return parseWholeNumber(option, text, lo, hi);
}

Result<float> parseFloat(const std::string& option, const std::string& text, float lo, float hi) {
    return parseNumberIn(option, text, lo, hi);
}

// "ex,ey,ez,tx,ty,tz,fov[,ux,uy,uz]" (fov in degrees; the optional up vector must not be parallel to
// the view direction).
Result<CameraOverride> parseCamera(const std::string& text) {
    std::vector<float> values;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, ',')) {
        auto v = parseFloat("--camera", part, -1e6f, 1e6f);
        if (!v) return v.error();
        values.push_back(*v);
    }
    if (values.size() != 7 && values.size() != 10)
        return makeError("--camera: expected 7 or 10 comma-separated numbers "
                         "eye_x,eye_y,eye_z,target_x,target_y,target_z,fov_degrees[,up_x,up_y,up_z]");
    CameraOverride camera;
    camera.eye = {values[0], values[1], values[2]};
    camera.target = {values[3], values[4], values[5]};
    camera.verticalFovDegrees = values[6];
    if (!(camera.verticalFovDegrees > 1.0f && camera.verticalFovDegrees < 179.0f))
        return makeError("--camera: the field of view must be within (1, 179) degrees");
    if (glm::length(camera.target - camera.eye) < 1e-6f) return makeError("--camera: eye and target coincide");
    if (values.size() == 10) {
        glm::vec3 up{values[7], values[8], values[9]};
        glm::vec3 forward = glm::normalize(camera.target - camera.eye);
        if (glm::length(up) < 1e-6f || glm::length(glm::cross(forward, glm::normalize(up))) < 1e-3f)
            return makeError("--camera: the up vector is zero or parallel to the view direction");
        camera.up = glm::normalize(up);
    }
    return camera;
}

Result<Aov> parseAov(const std::string& text) {
    for (Aov aov : {Aov::Final, Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Direct, Aov::Caustics})
        if (text == aovName(aov)) return aov;
    return makeError("--aov: '" + text + "' is not one of final, albedo, normal, depth, direct, caustics");
}

}  // namespace

const char* aovName(Aov aov) {
    switch (aov) {
        case Aov::Final: return "final";
        case Aov::Albedo: return "albedo";
        case Aov::Normal: return "normal";
        case Aov::Depth: return "depth";
        case Aov::Direct: return "direct";
        case Aov::Caustics: return "caustics";
    }
    return "?";
}

const char* cliUsage() {
    static const std::string usage = std::string("usage: caustics-sponza [options]\n"
           "  --scene PATH|builtin|builtin:atrium   scene to render (glTF .gltf/.glb or a built-in one)\n"
           "  --asset-root DIR        folder the glTF's buffer and image URIs must stay inside (default:\n"
           "                          the model's folder; widen it for textures in a sibling folder)\n"
           "  --sponza PATH           modified Sponza: load PATH and add the caustic objects to its atrium\n"
           "  --backend vulkan|d3d12  RHI backend (default vulkan)\n"
           "  --width N --height N    image size (default 512x384)\n"
           "  --camera ex,ey,ez,tx,ty,tz,fov[,ux,uy,uz]   eye, target, vertical field of view in degrees\n"
           "                          and optional up vector (default +Y, or +Z when looking straight down/up)\n"
           "  --out FILE.png|FILE.exr output image (EXR keeps linear radiance)\n"
           "  --aov final|albedo|normal|depth|direct|caustics\n"
           "  --frames N              frames to render (temporal filter accumulates); with --window, close after N\n"
           "  --graph-dot FILE        write the render graph as Graphviz dot\n"
           "  --map-resolution N      caustic visibility map size (default 512)\n"
           "  --rays-per-texel X      rays per map texel in (0, 256], fractional allowed (default 1)\n"
           "  --max-depth N           max specular events per caustic path (default 4)\n"
           "  --max-stored-hits N     forward hits kept for the second type (default 1048576)\n"
           "  --no-filter             switch the caustic filter off (the paper measured with it off)\n"
           "  --no-second-type        skip caustics seen through glass (the backward sphere pass)\n"
           "  --filter-second-type apart|merged  filter the caustics seen through glass on the surface they lie\n"
           "                          on (apart, the default: own guides and history, docs/caustics.md\n"
           "                          \"Second-type guides\") or with the first type on the camera G-buffer (merged)\n"
           "  --map-occluders         caustic maps also draw occluders (default: specular objects only)\n"
           "  --exposure X            linear exposure before tone mapping (default 1)\n"
           ) + sampleControlsUsage() + animationUsage() + std::string(
           "  --reference             also render the CPU reference light tracer (to FILE.reference.exr)\n"
           "  --reference-photons N   photons per light for --reference\n"
           "  --set FIELD=VALUE       any CausticsSettings field by name (repeatable; e.g. atrousIterations=0,\n"
           "                          filterPoolTiles=4096): the viewer's `set` names and values, applied last\n"
           "  --validation            enable Vulkan validation layers\n"
           "  --window                interactive viewer (GLFW + Dear ImGui; README lists its controls)\n"
           "  --script FILE           drive the viewer from FILE, one command per line (docs/viewer.md)\n");
    return usage.c_str();
}

namespace {

// Options that take a value (here and in sample_controls.h); anything else that is not a flag is
// unknown (checked before the value, so `--bogus` as the last argument is "unknown option", not
// "missing value").
bool takesValue(const std::string& a) {
    SampleControls probe;
    auto control = parseSampleControl(a, "", probe);   // an error or true: one of the sample controls
    if (!control || *control) return true;
    AnimationOptions animationProbe;
    auto animation = parseAnimationOption(a, "", animationProbe);
    if (!animation || *animation) return true;
    static const char* const kValueOptions[] = {
        "--scene", "--asset-root", "--sponza", "--backend", "--out", "--graph-dot", "--aov", "--camera", "--width", "--height",
        "--frames", "--map-resolution", "--max-stored-hits", "--max-depth", "--rays-per-texel", "--exposure",
        "--reference-photons", "--script", "--filter-second-type", "--set"};
    for (const char* known : kValueOptions)
        if (a == known) return true;
    return false;
}

Status checkOutputExtension(const char* option, const std::string& path, std::initializer_list<const char*> exts) {
    if (path.empty()) return makeError(std::string(option) + ": the path is empty");
    auto dot = path.rfind('.');
    std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    for (const char* e : exts)
        if (ext == e) return okStatus();
    std::string list;
    for (const char* e : exts) list += (list.empty() ? "" : " or ") + std::string(e);
    return makeError(std::string(option) + ": '" + path + "' must end in " + list);
}

}  // namespace

Result<CliOptions> parseCliOptions(const std::vector<std::string>& args) {
    CliOptions o;
    bool outGiven = false, dotGiven = false;
    for (size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto next = [&]() -> Result<std::string> {
            if (!takesValue(a)) return makeError("unknown option '" + a + "' (see --help)");
            if (i + 1 >= args.size()) return makeError(a + ": missing value");
            return args[++i];
        };
#define CLI_VALUE(var)              \
    auto var##Result = next();      \
    if (!var##Result) return var##Result.error(); \
    const std::string& var = *var##Result
        if (a == "--help" || a == "-h") { o.help = true; continue; }
        if (a == "--window") { o.window = true; continue; }
        if (a == "--no-filter") { o.filter = false; continue; }
        if (a == "--no-second-type") { o.secondType = false; continue; }
        if (a == "--filter-second-type-apart") { o.filterSecondTypeApart = true; continue; }   // the earlier spelling
        if (a == "--map-occluders") { o.mapOccluders = true; continue; }
        if (a == "--reference") { o.reference = true; continue; }
        if (a == "--validation") { o.validation = true; continue; }
        CLI_VALUE(value);
        if (a == "--scene") o.scene = value;
        else if (a == "--asset-root") {
            if (value.empty()) return makeError("--asset-root: the path is empty");
            o.assetRoot = value;
        }
        else if (a == "--sponza") o.sponzaPath = value;
        else if (a == "--backend") {
            if (value != "vulkan" && value != "d3d12") return makeError("--backend: '" + value + "' is not vulkan or d3d12");
            o.backend = value;
        } else if (a == "--out") { o.outPath = value; outGiven = true; }
        else if (a == "--graph-dot") { o.graphDotPath = value; dotGiven = true; }
        else if (a == "--script") o.scriptPath = value;
        else if (a == "--filter-second-type") {
            if (value != "apart" && value != "merged")
                return makeError("--filter-second-type: expected apart or merged, got '" + value + "'");
            o.filterSecondTypeApart = value == "apart";
        }
        else if (a == "--set") {
            const size_t eq = value.find('=');
            if (eq == std::string::npos || eq == 0)
                return makeError("--set: expected FIELD=VALUE (a CausticsSettings field, e.g. atrousIterations=0), got '" + value + "'");
            std::string field = value.substr(0, eq), fieldValue = value.substr(eq + 1);
            CausticsSettings probe;   // the name and the value's form checked now; ranges by validate()
            CAUSTICS_CHECK(setSettingsField(probe, field, fieldValue));
            o.settingFields.emplace_back(std::move(field), std::move(fieldValue));
        }
        else if (a == "--aov") { CAUSTICS_TRY(o.aov, parseAov(value)); }
        else if (a == "--camera") { CAUSTICS_TRY(o.camera, parseCamera(value)); }
        else if (a == "--width") { CAUSTICS_TRY(o.width, parseUint(a, value, 1, kMaxImageSide)); }
        else if (a == "--height") { CAUSTICS_TRY(o.height, parseUint(a, value, 1, kMaxImageSide)); }
        else if (a == "--frames") {
            CAUSTICS_TRY(o.frames, parseUint(a, value, 1, kMaxFrames));
            o.framesGiven = true;
        }
        else if (a == "--map-resolution") { CAUSTICS_TRY(o.mapResolution, parseUint(a, value, 1, kMaxMapResolution)); }
        else if (a == "--max-stored-hits") { CAUSTICS_TRY(o.maxStoredHits, parseUint(a, value, 1, 1u << 26)); }
        else if (a == "--max-depth") { CAUSTICS_TRY(o.maxDepth, parseUint(a, value, 1, kMaxSpecularDepth)); }
        else if (a == "--rays-per-texel") {
            // The range shown is the one applied: 0 is refused, so it is open at 0.
            auto rays = parsePositiveNumber(a, value, kMaxRaysPerTexel);   // "X is outside (0, 256]"
            if (!rays && std::strtod(value.c_str(), nullptr) <= 0.0 && rays.message().find("outside") != std::string::npos)
                return makeError("--rays-per-texel: must be greater than 0 (got " + value + "); the range is (0, 256]");
            CAUSTICS_TRY(o.raysPerTexel, std::move(rays));
        } else if (a == "--exposure") { CAUSTICS_TRY(o.exposure, parseFloat(a, value, 1e-6f, 1e6f)); }
        else if (a == "--reference-photons") { CAUSTICS_TRY(o.referencePhotons, parseUint(a, value, 1, 1'000'000'000u)); }
        else {
            CAUSTICS_TRY(bool known, parseSampleControl(a, value, o.controls));
            if (!known) {
                CAUSTICS_TRY(known, parseAnimationOption(a, value, o.animation));
            }
            if (!known) return makeError("unknown option '" + a + "' (see --help)");
        }
#undef CLI_VALUE
    }
    CAUSTICS_CHECK(validateSampleControls(o.controls, o.window, o.framesGiven));
    CAUSTICS_CHECK(finishAnimationOptions(o.animation, o.window, o.framesGiven, o.controls.accumulate));
    if (outGiven) CAUSTICS_CHECK(checkOutputExtension("--out", o.outPath, {".png", ".exr"}));
    if (dotGiven && o.graphDotPath.empty()) return makeError("--graph-dot: the path is empty");
    if (!o.scriptPath.empty() && !o.window) return makeError("--script: needs --window (it drives the viewer)");
    return o;
}

}  // namespace caustics::sample
