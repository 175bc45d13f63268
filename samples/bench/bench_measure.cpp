#include "bench_measure.h"

#include <algorithm>
#include <cmath>

#include "caustics/caustic_passes.h"
#include "caustics/scene/gpu_scene.h"

namespace caustics::bench {

CausticsSettings benchSettings(const BenchOptions& o) {
    CausticsSettings s;
    s.mapResolution = o.mapResolution;
    s.raysPerTexel = o.raysPerTexel;
    s.maxSpecularDepth = o.maxDepth;
    s.filter = o.filter;
    s.filterSecondTypeApart = o.filterSecondTypeApart;
    s.secondTypeSplitLobes = o.secondTypeSplitLobes;
    s.sphereRadiusScale = o.sphereRadiusScale;
    s.mapOccluders = o.mapOccluders;
    s.photonsPerFrame = o.photons;
    s.causticTimeTargetMs = o.timeTargetMs;
    return s;
}

Result<std::unique_ptr<BenchSession>> BenchSession::create(const rhi::DeviceHandle& device, scene::Scene scene,
                                                            const CausticsSettings& settings) {
    auto s = std::make_unique<BenchSession>();
    s->scene = std::move(scene);
    CAUSTICS_TRY(scene::GpuScene gpu, scene::GpuScene::create(*device, s->scene));
    s->gpu = std::make_unique<scene::GpuScene>(std::move(gpu));
    CAUSTICS_TRY(s->module, CausticsModule::create(device, s->scene, *s->gpu, settings));
    return s;
}

uint32_t warmupFrames(const BenchOptions& o, const CausticsSettings& settings) {
    if (o.warmupGiven || !settings.filter) return o.warmupFrames;
    return std::max(o.warmupFrames, settings.filterMaxHistory + settings.framesInFlight + 8);
}

Result<Measurement> measure(const rhi::DeviceHandle& device, BenchSession& session, const CausticsSettings& settings,
                            uint32_t width, uint32_t height, BenchView view, const BenchOptions& o, bool readCaustics) {
    const scene::Scene& scene = session.scene;
    CAUSTICS_CHECK(session.module->setSettings(settings));
    CAUSTICS_TRY(auto frames, BenchFrames::create(device, *session.module, width, height));
    frames->graph().setTimingWindow(o.frames);
    const scene::Camera camera = benchCamera(scene, view);
    const uint32_t total = warmupFrames(o, settings) + o.frames;
    for (uint32_t f = 0; f < total; ++f) CAUSTICS_CHECK(frames->render(camera, f, readCaustics && f + 1 == total));

    Measurement m;
    for (const auto& pass : frames->graph().desc().passes) {
        auto ms = frames->graph().passTimeMs(pass.name);
        if (!ms) continue;
        m.passMs.push_back({pass.name, *ms});
        m.frameMs += *ms;
        if (pass.name.rfind("caustics.", 0) == 0) m.causticsMs += *ms;
    }
    const std::vector<uint32_t>& s = frames->stats();
    for (uint32_t l = 0; l < kMaxCausticLights; ++l) m.photons += s[kStatRaysPerLight + l];
    m.emitterTexels = s[kStatEmitterTexels];
    m.dispatchedTexels = s[kStatDispatchedTexels];
    m.segments = s[kStatForwardSegments];
    m.specularPixels = s[kStatSpecularPixels];
    m.backwardLaunches = s[kStatBackwardLaunches];
    m.spheres = s[kStatSpheres];
    m.sphereCapacity = s[kStatSphereCapacity];
    m.spheresDropped = s[kStatSpheresDropped];
    m.hitAttempts = s[kStatStoredHitAttempts];
    m.storedHits = std::min<uint64_t>(m.hitAttempts, settings.maxStoredHits);
    m.gatherPairs = s[kStatGatherHits];
    m.maps = uint32_t(planCausticMaps(scene, computeSpecularBounds(scene)).maps.size());
    m.transients = frames->transients();
    m.transientHeapBytes = frames->transientHeapBytes();
    m.persistent = session.module->memoryReport();
    if (readCaustics) m.caustics = frames->caustics();
    return m;
}

Result<std::vector<float>> causticReference(const rhi::DeviceHandle& device, BenchSession& session,
                                            CausticsSettings settings, uint32_t width, uint32_t height, uint32_t frames) {
    settings.raysPerTexel = 16.0f;
    settings.filter = false;
    CAUSTICS_CHECK(session.module->setSettings(settings));
    CAUSTICS_TRY(auto runner, BenchFrames::create(device, *session.module, width, height));
    const scene::Camera camera = benchCamera(session.scene, BenchView::Visible);
    std::vector<double> sum(size_t(width) * height * 4, 0.0);
    for (uint32_t f = 0; f < frames; ++f) {
        // Frame indices far from the measured ones: independent seeds.
        CAUSTICS_CHECK(runner->render(camera, 100000 + f, true));
        const std::vector<float>& img = runner->caustics();
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += img[i];
    }
    std::vector<float> mean(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) mean[i] = float(sum[i] / frames);
    return mean;
}

double Measurement::passTime(const std::string& prefix) const {
    double sum = 0.0;
    for (const auto& [name, ms] : passMs)
        if (name.rfind(prefix, 0) == 0) sum += ms;
    return sum;
}

double relativeL1(const std::vector<float>& image, const std::vector<float>& reference) {
    double diff = 0.0, norm = 0.0;
    for (size_t i = 0; i < reference.size() && i < image.size(); ++i) {
        if (i % 4 == 3) continue;   // alpha
        diff += std::abs(double(image[i]) - reference[i]);
        norm += std::abs(double(reference[i]));
    }
    return norm > 0.0 ? diff / norm : 0.0;
}

}  // namespace caustics::bench
