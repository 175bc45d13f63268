#include "bench_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "bench_modes.h"
#include "caustics/caustics_settings.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics::bench {
namespace {

Result<uint32_t> parseCount(std::string_view flag, std::string_view text, uint32_t lo, uint32_t hi) {
    uint64_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        return makeError(std::string(flag) + ": expected a whole number, got '" + std::string(text) + "'");
    if (value < lo || value > hi)
        return makeError(std::string(flag) + ": " + std::string(text) + " is outside [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]");
    return uint32_t(value);
}

Result<float> parsePositive(std::string_view flag, std::string_view text, float hi) {
    std::string s(text);
    char* end = nullptr;
    double value = std::strtod(s.c_str(), &end);   // double: 1e39 is "outside", not "not a number"
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value))
        return makeError(std::string(flag) + ": expected a number, got '" + s + "'");
    if (!(value > 0.0) || value > double(hi))
        return makeError(std::string(flag) + ": " + s + " is outside (0, " + std::to_string(int(hi)) + "]");
    return float(value);
}

Status setOption(BenchOptions& o, std::string_view flag, std::string_view value) {
    if (flag == "--backend") {
        auto backend = rhi::parseBackend(value);
        if (!backend) return makeError("--backend: expected vulkan or d3d12, got '" + std::string(value) + "'");
        o.backend = *backend;
    } else if (flag == "--width") {
        CAUSTICS_TRY(o.width, parseCount(flag, value, 1, kMaxBenchImageSide));
    } else if (flag == "--height") {
        CAUSTICS_TRY(o.height, parseCount(flag, value, 1, kMaxBenchImageSide));
    } else if (flag == "--frames") {
        CAUSTICS_TRY(o.frames, parseCount(flag, value, 1, kMaxBenchFrames));
    } else if (flag == "--warmup") {
        CAUSTICS_TRY(o.warmupFrames, parseCount(flag, value, 0, kMaxBenchFrames));
        o.warmupGiven = true;
    } else if (flag == "--triangles") {
        CAUSTICS_TRY(o.triangles, parseCount(flag, value, 12, kMaxBenchTriangles));
    } else if (flag == "--scene" || flag == "--scenes") {
        if (value.empty()) return makeError(std::string(flag) + ": empty scene list");
        // Every name checked before anything runs: a bad second name must not cost a benchmark of the first.
        const std::vector<std::string> known = scene::builtinSceneNames();
        const std::string list(value);
        for (size_t start = 0; start <= list.size();) {
            size_t end = std::min(list.find(',', start), list.size());
            const std::string item = list.substr(start, end - start);
            if (std::find(known.begin(), known.end(), item) == known.end()) {
                std::string names;
                for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
                return makeError(std::string(flag) + ": '" + item + "' is not a built-in scene (known: " + names + ")");
            }
            start = end + 1;
        }
        o.scenes = list;
    } else if (flag == "--extra-lights") {
        CAUSTICS_TRY(o.extraLights, parseCount(flag, value, 0, kMaxBenchExtraLights));
    } else if (flag == "--rays-per-texel") {
        CAUSTICS_TRY(o.raysPerTexel, parsePositive(flag, value, CausticsSettings::kMaxRaysPerTexel));
    } else if (flag == "--depth") {
        CAUSTICS_TRY(o.maxDepth, parseCount(flag, value, 1, CausticsSettings::kMaxSpecularDepth));
    } else if (flag == "--map-size") {
        CAUSTICS_TRY(o.mapResolution, parseCount(flag, value, 1, CausticsSettings::kMaxMapResolution));
    } else if (flag == "--map-occluders") {
        if (value != "on" && value != "off")
            return makeError("--map-occluders: expected on or off, got '" + std::string(value) + "'");
        o.mapOccluders = value == "on";
    } else if (flag == "--filter") {
        if (value != "on" && value != "off") return makeError("--filter: expected on or off, got '" + std::string(value) + "'");
        o.filter = value == "on";
    } else if (flag == "--filter-second-type") {
        if (value != "apart" && value != "merged")
            return makeError("--filter-second-type: expected apart or merged, got '" + std::string(value) + "'");
        o.filterSecondTypeApart = value == "apart";
    } else if (flag == "--second-type-lobes") {
        if (value != "split" && value != "sampled")
            return makeError("--second-type-lobes: expected split or sampled, got '" + std::string(value) + "'");
        o.secondTypeSplitLobes = value == "split";
    } else if (flag == "--sphere-radius-scale") {
        CAUSTICS_TRY(o.sphereRadiusScale, parsePositive(flag, value, 64.0f));
    } else if (flag == "--view") {
        if (value != "visible" && value != "away")
            return makeError("--view: expected visible or away, got '" + std::string(value) + "'");
        o.viewAway = value == "away";
    } else if (flag == "--out") {
        if (value.empty()) return makeError("--out: empty folder name");
        o.outDir = std::string(value);
    } else if (flag == "--sweeps") {
        std::string list(value);
        for (size_t start = 0; start <= list.size();) {
            size_t end = std::min(list.find(',', start), list.size());
            const std::string item = list.substr(start, end - start);
            if (item != "lights" && item != "rays" && item != "depth" && item != "map" && item != "image")
                return makeError("--sweeps: '" + item + "' is not one of lights, rays, depth, map, image");
            start = end + 1;
        }
        o.sweeps = list;
    } else if (flag == "--photons") {
        CAUSTICS_TRY(o.photons, parseCount(flag, value, 0, CausticsSettings::kMaxPhotonsPerFrame));
    } else if (flag == "--time-target") {
        CAUSTICS_TRY(o.timeTargetMs, parsePositive(flag, value, CausticsSettings::kMaxCausticTimeTargetMs));
    } else if (flag == "--reference-frames") {
        CAUSTICS_TRY(o.referenceFrames, parseCount(flag, value, 1, 4096));
    } else {
        return makeError("unknown option '" + std::string(flag) + "'");
    }
    return okStatus();
}

}  // namespace

std::string benchUsage() {
    std::string text =
        "usage: caustics-bench <mode> [options]\n"
        "  --width W --height H        image size (default 1920x1080, at most 16384)\n"
        "  --frames N --warmup N       timed frames (median reported) and warm-up frames (default 2; with\n"
        "                              the filter on, its history cap + frames in flight + 8)\n"
        "  --backend vulkan|d3d12      --validation: Vulkan validation layers on\n"
        "  --triangles T               rays mode: mesh size (12 .. 67108864)\n"
        "  --scene LIST                comma list of built-in scenes (default builtin,builtin:atrium)\n"
        "  --extra-lights N            caustic spot lights added around the specular objects (0 .. 32)\n"
        "  --rays-per-texel R          (0, 256], fractional allowed (default 1)\n"
        "  --depth D                   specular events per caustic path, 1 .. 31 (default 4)\n"
        "  --map-size N                caustic map side, 1 .. 8192 (default 512)\n"
        "  --filter on|off             caustic filter (default off, as the paper measured)\n"
        "  --filter-second-type apart|merged  second type filtered on its own guides or with the first\n"
        "                              (default apart, CausticsSettings::filterSecondTypeApart)\n"
        "  --second-type-lobes split|sampled  camera paths through glass split off their likely lobe\n"
        "                              (default split) or pick one lobe per event (the paper)\n"
        "  --sphere-radius-scale X     second-type gather radius in pixel footprint widths (0, 64] (default 0.75)\n"
        "  --view visible|away         caustics, frame: the scene's camera, or turned away from every caustic\n"
        "  --map-occluders on|off      caustic maps also draw occluders (default off: specular objects only)\n"
        "  --out DIR                   sweep, figures, memory: folder for the CSV / PFM files (created)\n"
        "  --reference-frames N        sweep: frames of 16 rays per texel in the quality reference (default 16)\n"
        "  --sweeps LIST               sweep: any of lights,rays,depth,map,image (default all)\n"
        "  --photons N                 photons per frame split over the layers in view (0 .. 2^28; 0: per texel)\n"
        "  --time-target MS            steer the photons so the caustic passes take MS milliseconds (level mode: 1)\n"
        "modes:\n";
    for (const BenchMode& mode : benchModes()) text += "  " + std::string(mode.name) + "  " + mode.summary + "\n";
    return text;
}

Result<BenchOptions> parseBenchOptions(int argc, char** argv) {
    BenchOptions options;
    if (argc < 2) return makeError("no mode given");
    options.mode = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string_view flag = argv[i];
        if (flag == "--validation") {
            options.validation = true;
            continue;
        }
        if (i + 1 >= argc) return makeError(std::string(flag) + ": missing value");
        CAUSTICS_CHECK(setOption(options, flag, argv[++i]));
    }
    if (options.mode == "sweep" && options.outDir.empty()) return makeError("sweep: --out DIR is required");
    if (options.mode == "figures" && options.outDir.empty()) return makeError("figures: --out DIR is required");
    if (options.mode == "level" && options.outDir.empty()) return makeError("level: --out DIR is required");
    return options;
}

}  // namespace caustics::bench
