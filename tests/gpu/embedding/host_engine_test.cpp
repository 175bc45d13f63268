// Issue 9, "Tests", first bullet: a host engine written in plain Vulkan (host_engine.h: its own
// instance, device, queue, command buffer, compute G-buffer, output image and, in the second test, its
// own BLASes, TLAS and scene tables) runs the module in caustics-only mode inside its own command buffer
// and submits on its own queue. Its caustic image must equal the standalone module's (the fixture's
// device, the module's own G-buffer pass, TLAS and tables) for the same scene, camera and seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test.h"
#include "host_engine.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = kHostImageSize;

std::string joined(const std::vector<std::string>& messages) {
    std::string all;
    for (const std::string& m : messages) all += "\n  " + m;
    return all;
}

class HostEngine : public GpuTest {
protected:
    Result<FrameImage> standaloneFrame(const scene::Scene& scene, const CameraView& camera, uint32_t seed) {
        CAUSTICS_TRY(scene::GpuScene gpuScene, scene::GpuScene::create(*device, scene));
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene, hostEngineSettings(seed, false)));
        CAUSTICS_TRY(auto frames, runModuleFrames(*device, *module, 1, 1, [&](uint32_t) {
            ViewRequest v;
            v.inputs = {.camera = camera, .width = kSize, .height = kSize};
            return std::vector<ViewRequest>{v};
        }));
        return frames[0][0];
    }

    // The module's own G-buffer pass for the same camera: its objectId and linearDepth.
    Result<IdDepth> standaloneGBuffer(const scene::Scene& scene, const CameraView& camera) {
        CAUSTICS_TRY(scene::GpuScene gpuScene, scene::GpuScene::create(*device, scene));
        CAUSTICS_TRY(auto module, CausticsModule::create(device, scene, gpuScene, hostEngineSettings(1, false)));
        rg::RenderGraph graph;
        const FrameInputs inputs{.camera = camera, .width = kSize, .height = kSize};
        CAUSTICS_TRY(FrameOutputs out, module->addPasses(graph, inputs));
        const uint64_t bytes = uint64_t(kSize) * kSize * 4;
        rhi::BufferHandle ids = createReadback(bytes, "module object ids"), depths = createReadback(bytes, "module depths");
        for (auto [texture, buffer] : {std::pair{out.gbuffer.objectId, ids}, std::pair{out.gbuffer.linearDepth, depths}})
            graph.addPass("test.gbuffer_readback", [&](rg::PassBuilder& b) {
                rg::RgTexture src = b.read(texture, rg::Access::CopySource);
                b.setSideEffects();
                return [src, buffer](rg::PassContext& ctx) { ctx.cmd().copyTextureToBuffer(buffer, 0, ctx.texture(src)); };
            });
        Status executed = okStatus();
        runCommands([&](rhi::ICommandList& cmd) { executed = graph.execute(*device, cmd); });
        CAUSTICS_CHECK(executed);
        IdDepth g{std::vector<uint32_t>(size_t(kSize) * kSize), std::vector<float>(size_t(kSize) * kSize)};
        CAUSTICS_CHECK(device->readBuffer(ids, g.objectId.data(), bytes));
        CAUSTICS_CHECK(device->readBuffer(depths, g.linearDepth.data(), bytes));
        return g;
    }
};

// Measured (lavapipe llvmpipe, 96x96, map 64, 4 rays/texel; the "[ measured ]" line of 5 runs of
// `build/bin/embedding_gpu_tests --gtest_filter='HostEngine*' --gtest_repeat=5`), relative L1:
//   host engine vs standalone, seed 1:      1.197e-5 .. 1.210e-5 (total luminance equal to 5 digits)
//   standalone vs standalone, seed 1:       3.2e-8 .. 1.2e-7 (order of the fixed-point accumulation)
//   standalone seed 1 vs standalone seed 2: 0.4672
// The host's G-buffer (ray/triangle intersection at pixel centres) differs from the rasterized one only
// in float rounding of depth and normals and in edge-rule ties at triangle edges. Bound 1.5e-4: about
// 12x the largest host-vs-standalone value, and 3000x below what another seed gives (asserted too).
constexpr double kHostBound = 1.5e-4;
// The G-buffers themselves (3 runs, identical): 0 of 9216 pixels differ in objectId, max relative
// linearDepth error 5.64e-5 (ray/triangle intersection vs interpolated raster depth, float rounding).
// Bounds: 10 id mismatches (0.1% of the pixels: edge-rule ties of another driver; a camera off by one
// pixel changes hundreds along the sphere's silhouette) and 5e-4 relative depth (9x the measurement).
constexpr uint32_t kMaxIdMismatches = 10;
constexpr double kMaxDepthError = 5e-4;

TEST_F(HostEngine, PlainVulkanEngineGetsTheStandaloneModulesCausticImage) {
    const scene::Scene scene = spotSphereScene();
    const CameraView camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
    std::vector<std::string> hostMessages;
    auto host = hostEngineFrame(scene, camera, 1, {}, hostMessages);
    ASSERT_TRUE(host) << host.message();
    EXPECT_TRUE(hostMessages.empty()) << hostMessages.size() << " validation message(s) on the host's device:"
                                      << joined(hostMessages);
    auto standalone = standaloneFrame(scene, camera, 1);
    ASSERT_TRUE(standalone) << standalone.message();
    auto again = standaloneFrame(scene, camera, 1);
    ASSERT_TRUE(again) << again.message();
    auto otherSeed = standaloneFrame(scene, camera, 2);
    ASSERT_TRUE(otherSeed) << otherSeed.message();

    // The host's compute G-buffer against the module's raster G-buffer, pixel by pixel.
    auto moduleGBuffer = standaloneGBuffer(scene, camera);
    ASSERT_TRUE(moduleGBuffer) << moduleGBuffer.message();
    const IdDepth& ours = host.value().gbuffer;
    const IdDepth& theirs = moduleGBuffer.value();
    uint32_t idMismatches = 0, covered = 0;
    double maxDepthError = 0.0;
    for (size_t i = 0; i < theirs.objectId.size(); ++i) {
        if (ours.objectId[i] != theirs.objectId[i]) { ++idMismatches; continue; }
        if (theirs.objectId[i] == 0) continue;
        ++covered;
        maxDepthError = std::max(maxDepthError, double(std::abs(ours.linearDepth[i] - theirs.linearDepth[i])) /
                                                    theirs.linearDepth[i]);
    }
    std::printf("[ measured ] G-buffer: %u of %u pixels differ in objectId; max relative linearDepth error %.3g "
                "over %u covered pixels\n", idMismatches, kSize * kSize, maxDepthError, covered);
    EXPECT_GT(covered, kSize * kSize / 2) << "the scene should cover most of the image";
    EXPECT_LE(idMismatches, kMaxIdMismatches);
    EXPECT_LT(maxDepthError, kMaxDepthError);

    const double hostL1 = relativeL1(host.value().caustics, standalone.value());
    const double sameL1 = relativeL1(again.value(), standalone.value());
    const double seedL1 = relativeL1(otherSeed.value(), standalone.value());
    std::printf("[ measured ] relative L1: host vs standalone %.4g, standalone repeat %.4g, other seed %.4g; "
                "energy host %.5g standalone %.5g\n", hostL1, sameL1, seedL1, totalLuminance(host.value().caustics),
                totalLuminance(standalone.value()));
    EXPECT_GT(totalLuminance(standalone.value()), 0.0) << "no caustic in the standalone image: nothing is compared";
    EXPECT_LT(hostL1, kHostBound);
    // The bound separates "same frame" from "another frame": a different seed alone exceeds it.
    EXPECT_GT(seedL1, kHostBound);
}

// The host's own acceleration structures and tables (raw Vulkan builds, host_ray_tracing_scene.*)
// replace the module's. The BLASes hold the same triangles in the same order and the TLAS the same
// instances, so the traced image differs from the module-built one only where a different build could
// split a tie differently. Measured (5 runs, as above): host tables vs standalone 1.197e-5 .. 1.210e-5,
// the same as with the module's own TLAS (the host G-buffer dominates the difference); kHostBound holds.
TEST_F(HostEngine, OwnTlasAndSceneTablesGetTheStandaloneModulesCausticImage) {
    const scene::Scene scene = spotSphereScene();
    const CameraView camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
    std::vector<std::string> hostMessages;
    auto host = hostEngineFrame(scene, camera, 1, {.ownSceneTables = true}, hostMessages);
    ASSERT_TRUE(host) << host.message();
    EXPECT_TRUE(hostMessages.empty()) << hostMessages.size() << " validation message(s) on the host's device:"
                                      << joined(hostMessages);
    auto standalone = standaloneFrame(scene, camera, 1);
    ASSERT_TRUE(standalone) << standalone.message();
    const double hostL1 = relativeL1(host.value().caustics, standalone.value());
    std::printf("[ measured ] host TLAS and tables: relative L1 vs standalone %.4g; energy host %.5g standalone %.5g\n",
                hostL1, totalLuminance(host.value().caustics), totalLuminance(standalone.value()));
    EXPECT_GT(totalLuminance(standalone.value()), 0.0) << "no caustic in the standalone image: nothing is compared";
    EXPECT_LT(hostL1, kHostBound);
}

// docs/embedding.md "Hand-over states": the host writes its material table in the same command buffer
// (vkCmdUpdateBuffer after zeros from the CPU) with no barrier of its own and declares the tables
// CopyDest; the module's barrier orders its traces after the write. Synchronization validation is on:
// without that barrier (scene.host_tables) it reports the read-after-write hazard (checked once by
// removing the pass: 1 message). The image must equal the host whose table was written from the CPU:
// measured relative L1 0 (same rows, same seed); bound kHostBound as above.
TEST_F(HostEngine, HostTablesWrittenInItsCommandBufferAreMadeVisibleByTheModulesBarrier) {
    const scene::Scene scene = spotSphereScene();
    const CameraView camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
    std::vector<std::string> cpuMessages, gpuMessages;
    auto cpuWritten = hostEngineFrame(scene, camera, 1, {.ownSceneTables = true}, cpuMessages);
    ASSERT_TRUE(cpuWritten) << cpuWritten.message();
    auto gpuWritten =
        hostEngineFrame(scene, camera, 1, {.ownSceneTables = true, .materialsWrittenInCommandBuffer = true}, gpuMessages);
    ASSERT_TRUE(gpuWritten) << gpuWritten.message();
    EXPECT_TRUE(gpuMessages.empty()) << gpuMessages.size() << " validation message(s) on the host's device:"
                                     << joined(gpuMessages);
    const double l1 = relativeL1(gpuWritten.value().caustics, cpuWritten.value().caustics);
    std::printf("[ measured ] material table written in the host's command buffer: relative L1 vs CPU-written %.4g\n", l1);
    EXPECT_GT(totalLuminance(cpuWritten.value().caustics), 0.0);
    EXPECT_LT(l1, kHostBound);
}

// The module reads the host's material table, not its own copy: halving the diffuse albedo there
// (and nowhere else) halves the caustic, whose receiver BRDF is albedo / pi (paper formula (2)).
// Measured: energy ratio 0.5000 (caustics-only output; the sphere's glass is unchanged). Bound: 0.5 +- 0.01,
// far below the 1.0 that the module's own table would give.
TEST_F(HostEngine, HostMaterialTableIsTheOneTheCausticsRead) {
    const scene::Scene scene = spotSphereScene();
    const CameraView camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
    std::vector<std::string> messages, halfMessages;
    auto full = hostEngineFrame(scene, camera, 1, {.ownSceneTables = true}, messages);
    ASSERT_TRUE(full) << full.message();
    auto half = hostEngineFrame(scene, camera, 1, {.ownSceneTables = true, .diffuseAlbedoScale = 0.5f}, halfMessages);
    ASSERT_TRUE(half) << half.message();
    EXPECT_TRUE(messages.empty() && halfMessages.empty()) << joined(messages) << joined(halfMessages);
    const double fullEnergy = totalLuminance(full.value().caustics);
    const double ratio = totalLuminance(half.value().caustics) / fullEnergy;
    std::printf("[ measured ] caustic energy with the host's diffuse albedo halved: ratio %.4f\n", ratio);
    ASSERT_GT(fullEnergy, 0.0);
    EXPECT_NEAR(ratio, 0.5, 0.01);
}

// "A host's own instance ids map to the module's": the host's G-buffer writes sparse ids 1000 + 7k for
// instance row k and hands the module its (hostId, moduleId) map; the module maps them on the GPU
// (pass gbuffer.object_ids) and renders the standalone image. Without the map the same G-buffer's ids
// match no object of the module: the first-type splat's visibility test (paper Fig. 4b, same object)
// rejects every photon, and only the second type (whose gather compares traced ids) is left. That
// control must exceed the bound. Measured: with the map 1.2e-5 (as with the module's own ids), without
// it 0.9275.
TEST_F(HostEngine, SparseHostObjectIdsMapToTheModulesThroughTheHostsMap) {
    const scene::Scene scene = spotSphereScene();
    const CameraView camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
    std::vector<std::string> messages, unmappedMessages;
    auto mapped = hostEngineFrame(scene, camera, 1, {.sparseObjectIds = true, .objectIdMap = true}, messages);
    ASSERT_TRUE(mapped) << mapped.message();
    auto unmapped = hostEngineFrame(scene, camera, 1, {.sparseObjectIds = true}, unmappedMessages);
    ASSERT_TRUE(unmapped) << unmapped.message();
    EXPECT_TRUE(messages.empty() && unmappedMessages.empty()) << joined(messages) << joined(unmappedMessages);
    // The host's own image holds its own ids, and only those.
    for (uint32_t id : mapped.value().gbuffer.objectId) {
        const bool hostId = id >= kSparseIdBase && (id - kSparseIdBase) % kSparseIdStride == 0 &&
                            (id - kSparseIdBase) / kSparseIdStride < scene.instances.size();
        ASSERT_TRUE(id == 0 || hostId) << "object id " << id << " is not one of the host's";
    }
    auto standalone = standaloneFrame(scene, camera, 1);
    ASSERT_TRUE(standalone) << standalone.message();
    const double mappedL1 = relativeL1(mapped.value().caustics, standalone.value());
    const double unmappedL1 = relativeL1(unmapped.value().caustics, standalone.value());
    std::printf("[ measured ] host ids 1000 + 7k: relative L1 vs standalone %.4g with the map, %.4g without\n",
                mappedL1, unmappedL1);
    EXPECT_GT(totalLuminance(standalone.value()), 0.0);
    EXPECT_LT(mappedL1, kHostBound);
    EXPECT_GT(unmappedL1, kHostBound);
}

// An instance table with fewer rows than the CPU scene has instances would let the hit shaders read
// past its end: refused at addPasses, naming the table, its debug name and both counts.
TEST_F(HostEngine, ShortHostInstanceTableIsRefusedNamingTheTableAndTheCount) {
    const scene::Scene scene = spotSphereScene();
    const size_t rows = scene.instances.size() - 1;
    std::vector<std::string> hostMessages;
    auto host = hostEngineFrame(scene, cameraViewMatrices(spotSphereCamera(), kSize, kSize), 1,
                                {.ownSceneTables = true, .instanceRows = rows}, hostMessages);
    ASSERT_FALSE(host) << "a host instance table of " << rows << " rows was accepted for " << scene.instances.size()
                       << " instances";
    const std::string& why = host.message();
    std::printf("[ refused ] %s\n", why.c_str());
    EXPECT_NE(why.find("HostSceneTables::instances"), std::string::npos) << why;
    EXPECT_NE(why.find("'host instances'"), std::string::npos) << why;
    EXPECT_NE(why.find(std::to_string(rows) + " GpuInstance rows"), std::string::npos) << why;
    EXPECT_NE(why.find(std::to_string(scene.instances.size()) + " instances"), std::string::npos) << why;
    EXPECT_TRUE(hostMessages.empty()) << joined(hostMessages);
}

}  // namespace
}  // namespace caustics::test
