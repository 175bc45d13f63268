// `figures` mode: the caustic images of the paper's Figures 10 and 12 without the sample (so without
// OpenImageIO or GLFW on a headless GPU machine): one frame, filter off, of the caustic radiance at each
// rays-per-texel setting (depth 4) and each depth (1 ray per texel), written as linear RGB PFM files
// (Portable Float Map: a text header and little-endian float32 rows, bottom row first) under --out:
// rays_<r>.pfm and depth_<d>.pfm. scripts/render_figure_rows.py --bench crops and tiles them.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench_gpu.h"
#include "bench_measure.h"
#include "bench_modes.h"

namespace caustics::bench {
namespace {

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench figures: %s\n", what.c_str());
    return 1;
}

// `rgba`: RGBA32F, row 0 = top (BenchFrames::caustics()).
bool writePfm(const std::string& path, const std::vector<float>& rgba, uint32_t width, uint32_t height) {
    std::ofstream f(path, std::ios::binary);
    f << "PF\n" << width << ' ' << height << "\n-1.0\n";   // negative scale: little endian
    std::vector<float> row(size_t(width) * 3);
    for (uint32_t y = 0; y < height; ++y) {
        const float* src = rgba.data() + size_t(height - 1 - y) * width * 4;
        for (uint32_t x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) row[size_t(x) * 3 + c] = src[size_t(x) * 4 + c];
        f.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    return f.good();
}

}  // namespace

int runFiguresMode(const BenchOptions& o) {
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) return fail("--out " + o.outDir + ": " + ec.message());
    auto device = createBenchDevice(o);
    if (!device) return fail(device.message());
    const std::string sceneName = o.scenes.substr(0, o.scenes.find(','));
    auto sc = loadBenchScene(sceneName, o.extraLights);
    if (!sc) return fail(sc.message());
    auto session = BenchSession::create(device.value(), std::move(sc.value()), benchSettings(o));
    if (!session) return fail(session.message());

    struct Image { std::string name; float rays; uint32_t depth; };
    std::vector<Image> images;
    for (const char* r : {"0.25", "0.5", "0.75", "1", "2", "4", "8", "25"}) images.push_back({std::string("rays_") + r, std::stof(r), 4});
    for (uint32_t d : {1u, 2u, 3u, 4u, 8u, 16u}) images.push_back({"depth_" + std::to_string(d), 1.0f, d});
    BenchOptions one = o;   // one frame per image, no warm-up: the paper's rows are single frames
    one.frames = 1;
    one.warmupFrames = 0;
    for (const Image& image : images) {
        CausticsSettings s = benchSettings(o);
        s.raysPerTexel = image.rays;
        s.maxSpecularDepth = image.depth;
        s.filter = false;
        auto m = measure(device.value(), *session.value(), s, o.width, o.height, BenchView::Visible, one, true);
        if (!m) return fail(image.name + ": " + m.message());
        const std::string path = o.outDir + "/" + image.name + ".pfm";
        if (!writePfm(path, m->caustics, o.width, o.height)) return fail(path + ": cannot write it");
        std::printf("%s\n", path.c_str());
    }
    return 0;
}

}  // namespace caustics::bench
