// docs/embedding.md "Threading and submissions": the module submits to the host's queue only in
// GpuScene::create, CausticsModule::create, prepare() and setSettings() (when it switches something
// on), as many times as the table there says, and never in addPasses or the render graph's execute().
// Counted through the host's vkGetInstanceProcAddr (every Vulkan call of the wrapped RHI device goes
// through it; counting_proc_addr.*), so the host's own vkQueueSubmit2 of its frames is not counted.
#include <gtest/gtest.h>

#include <cstdio>

#include "caustics/rhi/vulkan_interop.h"
#include "caustics/scene/gpu_scene.h"
#include "counting_proc_addr.h"
#include "host_engine.h"
#include "raw_vulkan_host.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kFrames = 4;

// The counts docs/embedding.md states, per call.
constexpr int kGpuSceneCreateSubmits = 1;      // geometry, textures and BLAS builds in one submission
constexpr int kModuleCreateSubmits = 1;        // caustics off: direct lighting's shader table
constexpr int kCausticsSwitchOnSubmits = 3;    // setSettings(causticsEnabled): forward, backward, gather tables (the sphere BLAS is built per frame)

int submits() { return procAddrLog().queueSubmitCalls; }

// One host frame: the host begins its command buffer, the module records into it, the host submits.
Status hostFrame(RawVulkanHost& host, rhi::IDevice& device, CausticsModule& module, const scene::Scene& scene,
                 uint64_t frameIndex, int& submitsInAddPassesAndExecute) {
    rg::RenderGraph graph;
    host.begin();
    CAUSTICS_TRY(rhi::CommandListHandle list, rhi::wrapVulkanCommandBuffer(device, {.commandBuffer = host.commandBuffer}));
    const int before = submits();
    FrameInputs inputs = viewOf(scene.cameras.front(), kSize).inputs;
    inputs.frameIndex = frameIndex;
    CAUSTICS_TRY(FrameOutputs out, module.addPasses(graph, inputs));
    graph.markOutput(out.display);
    CAUSTICS_CHECK(graph.execute(device, *list));
    CAUSTICS_TRY(rhi::VulkanSubmitSignal signal, rhi::vulkanSubmitSignal(device, *list));
    submitsInAddPassesAndExecute += submits() - before;
    if (!host.endSubmitAndWait(&signal)) return makeError("raw host: submit failed");
    return okStatus();
}

TEST(SubmitCount, ModuleSubmitsOnTheHostsQueueOnlyInCreatePrepareAndSetSettings) {
    RawVulkanHost host;
    ASSERT_TRUE(host.create(true)) << host.why();
    rhi::VulkanDeviceImport import = host.deviceImport();
    import.getInstanceProcAddr = countingGetInstanceProcAddr();
    const scene::Scene scene = spotSphereScene();
    ASSERT_FALSE(scene.cameras.empty());
    {
        auto device = rhi::wrapVulkanDevice(import);
        ASSERT_TRUE(device.ok()) << device.message();
        EXPECT_EQ(submits(), 0) << "wrapVulkanDevice";

        auto gpuScene = scene::GpuScene::create(*device.value(), scene);
        ASSERT_TRUE(gpuScene.ok()) << gpuScene.message();
        const int sceneSubmits = submits();
        EXPECT_EQ(sceneSubmits, kGpuSceneCreateSubmits) << "GpuScene::create";

        CausticsSettings settings = hostEngineSettings(1, false);
        settings.causticsEnabled = false;
        int counted = submits();
        auto module = CausticsModule::create(device.value(), scene, gpuScene.value(), settings);
        ASSERT_TRUE(module.ok()) << module.message();
        const int createSubmits = submits() - counted;
        EXPECT_EQ(createSubmits, kModuleCreateSubmits) << "CausticsModule::create";

        counted = submits();
        ASSERT_TRUE(module.value()->prepare().ok());
        EXPECT_EQ(submits() - counted, 0) << "prepare() with everything made";

        int inFrames = 0;
        for (uint64_t n = 0; n < kFrames; ++n) {
            Status frame = hostFrame(host, *device.value(), *module.value(), scene, n, inFrames);
            ASSERT_TRUE(frame.ok()) << frame.message();
        }
        EXPECT_EQ(inFrames, 0) << "addPasses and execute over " << kFrames << " frames";

        settings.causticsEnabled = true;
        counted = submits();
        ASSERT_TRUE(module.value()->setSettings(settings).ok());
        const int switchOn = submits() - counted;
        EXPECT_EQ(switchOn, kCausticsSwitchOnSubmits) << "setSettings switching the caustics on";
        counted = submits();
        ASSERT_TRUE(module.value()->setSettings(settings).ok());
        EXPECT_EQ(submits() - counted, 0) << "setSettings with nothing new";

        for (uint64_t n = kFrames; n < 2 * kFrames; ++n) {
            Status frame = hostFrame(host, *device.value(), *module.value(), scene, n, inFrames);
            ASSERT_TRUE(frame.ok()) << frame.message();
        }
        EXPECT_EQ(inFrames, 0) << "addPasses and execute with the caustics on";
        std::printf("[ measured ] submits: GpuScene::create %d, CausticsModule::create %d, setSettings (caustics on) "
                    "%d, %u frames %d\n",
                    sceneSubmits, createSubmits, switchOn, 2 * kFrames, inFrames);
    }   // the module and the wrapped device go before the host's device
    host.destroyAll();
    const std::vector<std::string> messages = host.messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation messages, first: "
                                  << (messages.empty() ? "" : messages.front());
}

// docs/embedding.md "Host scene tables": with the host's TLAS and geometry tables the GpuScene is made
// with uploadGeometry = false and writes only the material and instance tables into buffers, no byte
// of the vertices and indices the host already has. Counted as the bytes of the module's
// vkCmdUpdateBuffer and vkCmdCopyBuffer calls through the host's vkGetInstanceProcAddr.
TEST(HostSceneUpload, GpuSceneUploadsNoGeometryTheHostHandsIn) {
    RawVulkanHost host;
    ASSERT_TRUE(host.create(true)) << host.why();
    rhi::VulkanDeviceImport import = host.deviceImport();
    import.getInstanceProcAddr = countingGetInstanceProcAddr();
    const scene::Scene scene = spotSphereScene();
    const scene::PackedScene packed = scene::packScene(scene);
    const uint64_t geometryBytes = packed.positions.size() * sizeof(glm::vec3) +
                                   packed.vertices.size() * sizeof(scene::GpuVertex) +
                                   packed.indices.size() * sizeof(uint32_t);
    const uint64_t tableBytes = packed.materials.size() * sizeof(scene::GpuMaterial) +
                                packed.instances.size() * sizeof(scene::GpuInstance);
    {
        auto device = rhi::wrapVulkanDevice(import);
        ASSERT_TRUE(device.ok()) << device.message();
        auto uploaded = [&](const scene::GpuSceneDesc& desc) -> uint64_t {
            const uint64_t before = procAddrLog().bufferUploadBytes;
            auto gpuScene = scene::GpuScene::create(*device.value(), scene, desc);
            EXPECT_TRUE(gpuScene.ok()) << gpuScene.message();
            if (gpuScene.ok()) {
                EXPECT_EQ(bool(gpuScene.value().positions), desc.uploadGeometry);
                EXPECT_EQ(bool(gpuScene.value().indices), desc.uploadGeometry);
            }
            return procAddrLog().bufferUploadBytes - before;
        };
        const uint64_t withGeometry = uploaded({.buildAccelStructs = false});
        const uint64_t hostGeometry = uploaded({.buildAccelStructs = false, .uploadGeometry = false});
        std::printf("[ measured ] GpuScene::create buffer uploads: own geometry %llu bytes, host geometry %llu bytes "
                    "(materials + instances %llu, geometry %llu)\n",
                    (unsigned long long)withGeometry, (unsigned long long)hostGeometry, (unsigned long long)tableBytes,
                    (unsigned long long)geometryBytes);
        EXPECT_EQ(hostGeometry, tableBytes) << "only the material and instance tables";
        EXPECT_EQ(withGeometry - hostGeometry, geometryBytes);
        EXPECT_FALSE(scene::GpuScene::create(*device.value(), scene, {.uploadGeometry = false}).ok())
            << "BLAS builds without geometry are refused";
    }
    host.destroyAll();
    EXPECT_TRUE(host.messages().empty()) << host.messages().size() << " validation messages";
}

}  // namespace
}  // namespace caustics::test
