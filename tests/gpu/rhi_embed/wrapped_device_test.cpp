// A host engine written in raw Vulkan wraps its device with the RHI, imports its own image and buffer
// with their current layouts, and lets a render graph record a compute pass into the host's command
// buffer, which the host submits on its own queue. Results are checked byte for byte (integer
// arithmetic: no tolerance); the declared final layout is checked by the validation layer, which sees
// the host's own copy from that layout, and every layer message fails the test.
#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/vulkan_interop.h"
#include "counting_proc_addr.h"
#include "gpu_test.h"
#include "raw_vulkan_host.h"

namespace caustics::test {
namespace {
using namespace rhi;

constexpr uint32_t kWidth = 19, kHeight = 11;   // odd sizes exercise the shader's bounds check
constexpr uint32_t kCleared = 0xdeadbeefu;

uint32_t inputValue(uint32_t i) { return i * 7u + 5u; }

class WrappedVulkanDevice : public ::testing::Test {
protected:
    void TearDown() override {
        device.reset();
        host.destroyAll();   // the layer reports anything the wrapped device left on the host's device
        std::vector<std::string> seen = host.messages();
        std::string all;
        for (const std::string& m : seen) all += "\n  " + m;
        EXPECT_TRUE(seen.empty()) << seen.size() << " validation message(s):" << all;
    }

    // Creates the raw host (with ray tracing) and wraps its device into `device`, handing the module
    // `getInstanceProcAddr` (the loader's when null); false on failure.
    ::testing::AssertionResult wrapHost(PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr) {
        if (!host.create(/*withRayTracing=*/true)) return ::testing::AssertionFailure() << host.why();
        VulkanDeviceImport import = host.deviceImport();
        if (getInstanceProcAddr) import.getInstanceProcAddr = getInstanceProcAddr;
        auto wrapped = wrapVulkanDevice(import);
        if (!wrapped) return ::testing::AssertionFailure() << wrapped.message();
        device = wrapped.value();
        return ::testing::AssertionSuccess();
    }

    RawVulkanHost host;
    DeviceHandle device;
};

struct ScalePass {
    BindingLayoutHandle layout;
    ComputePipelineHandle pipeline;
};

ScalePass makeScalePass(IDevice& device) {
    ScalePass pass;
    auto layout = device.createBindingLayout(BindingLayoutDesc()
                                                 .setVisibility(ShaderStage::Compute)
                                                 .add(0, BindingType::StorageBufferRO)
                                                 .add(1, BindingType::StorageTexture));
    EXPECT_TRUE(layout.ok()) << (layout.ok() ? "" : layout.message());
    if (!layout) return pass;
    pass.layout = layout.value();
    ComputePipelineDesc pd;
    pd.shader.code = testShader("rhi_embed/scale.comp");
    pd.bindings.layouts = {pass.layout};
    pd.bindings.pushConstantBytes = 8;
    pd.debugName = "scale";
    auto pipeline = device.createComputePipeline(pd);
    EXPECT_TRUE(pipeline.ok()) << (pipeline.ok() ? "" : pipeline.message());
    if (pipeline) pass.pipeline = pipeline.value();
    return pass;
}

// Runs one host frame: the host clears its image (leaving it in TRANSFER_DST_OPTIMAL), the graph
// scales the host's buffer into it and must leave it in TRANSFER_SRC_OPTIMAL, where the host copies
// it to its readback buffer. Returns the readback values; `timed` receives the pass's GPU time.
std::vector<uint32_t> runHostFrame(RawVulkanHost& host, IDevice& device, bool allowTimestamps,
                                   std::optional<double>& timed) {
    RawImage image = host.createImage(kWidth, kHeight, VK_FORMAT_R32_UINT,
                                      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    RawBuffer input = host.createHostBuffer(kWidth * kHeight * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    RawBuffer readback = host.createHostBuffer(kWidth * kHeight * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    for (uint32_t i = 0; i < kWidth * kHeight; ++i) static_cast<uint32_t*>(input.mapped)[i] = inputValue(i);

    std::vector<uint32_t> result;
    {
        auto texture = importVulkanTexture(device, {.image = image.image, .format = VK_FORMAT_R32_UINT,
                                                    .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                             VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                    .width = kWidth, .height = kHeight,
                                                    .uses = TextureUsage::Storage, .debugName = "host image"});
        auto buffer = importVulkanBuffer(device, {.buffer = input.buffer, .byteSize = kWidth * kHeight * 4,
                                                  .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                  .uses = BufferUsage::Storage, .debugName = "host input"});
        auto cmd = wrapVulkanCommandBuffer(device, {.commandBuffer = host.commandBuffer,
                                                    .allowTimestamps = allowTimestamps});
        auto current = resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        auto final = resourceStateFromVkImageLayout(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        EXPECT_TRUE(texture.ok()) << (texture.ok() ? "" : texture.message());
        EXPECT_TRUE(buffer.ok()) << (buffer.ok() ? "" : buffer.message());
        EXPECT_TRUE(cmd.ok() && current.ok() && final.ok());
        if (!texture || !buffer || !cmd || !current || !final) return result;

        // Each RHI object hands back the native object it wraps, and nothing for another type.
        EXPECT_EQ(texture.value()->getNativeObject(NativeObjectType::VkImage).as<VkImage>(), image.image);
        EXPECT_EQ(buffer.value()->getNativeObject(NativeObjectType::VkBuffer).as<VkBuffer>(), input.buffer);
        EXPECT_EQ(cmd.value()->getNativeObject(NativeObjectType::VkCommandBuffer).as<VkCommandBuffer>(),
                  host.commandBuffer);
        EXPECT_FALSE(texture.value()->getNativeObject(NativeObjectType::VkBuffer).valid());

        ScalePass scale = makeScalePass(device);
        auto set = device.createBindingSet(BindingSetDesc()
                                               .add(BindingSetItem::storageBuffer(0, buffer.value()))
                                               .add(BindingSetItem::storageTexture(1, texture.value())),
                                           scale.layout);
        EXPECT_TRUE(set.ok()) << (set.ok() ? "" : set.message());
        if (!scale.pipeline || !set) return result;

        host.begin();
        host.imageBarrier(image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkClearColorValue clear{};
        clear.uint32[0] = kCleared;
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(host.commandBuffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);

        rg::RenderGraph graph;
        rg::RgTexture target = graph.importTexture("host image", texture.value(), current.value(), final.value());
        rg::RgBuffer source = graph.importBuffer("host input", buffer.value(), ResourceState::ShaderResource,
                                                 ResourceState::ShaderResource);
        graph.addPass("scale", [&](rg::PassBuilder& b) {
            b.read(source, rg::Access::StorageRead);
            b.write(target, rg::Access::StorageWrite);
            return [&](rg::PassContext& ctx) {
                ctx.cmd().setComputePipeline(scale.pipeline);
                ctx.cmd().setBindingSet(0, set.value());
                const uint32_t push[2] = {kWidth, kHeight};
                ctx.cmd().setPushConstants(push, sizeof(push));
                ctx.cmd().dispatch((kWidth + 7) / 8, (kHeight + 7) / 8);
            };
        });
        graph.markOutput(target);
        Status executed = graph.execute(device, *cmd.value());
        EXPECT_TRUE(executed.ok()) << (executed.ok() ? "" : executed.message());

        // The host's own work after the graph, in the layout it declared: the layer checks the layout
        // (core validation) and that the graph made the compute writes visible (sync validation).
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kWidth, kHeight, 1};
        vkCmdCopyImageToBuffer(host.commandBuffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1,
                               &region);
        host.memoryBarrier(VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                           VK_ACCESS_2_HOST_READ_BIT);

        auto signal = vulkanSubmitSignal(device, *cmd.value());
        EXPECT_TRUE(signal.ok()) << (signal.ok() ? "" : signal.message());
        EXPECT_TRUE(host.endSubmitAndWait(signal.ok() ? &signal.value() : nullptr));
        // The host's submission signalled the device fence, so the device sees the work as done.
        if (signal) {
            EXPECT_TRUE(device.waitForFence(signal->value).ok());
        }
        graph.collectTimings(device);
        timed = graph.passTimeMs("scale");
        result.resize(kWidth * kHeight);
        std::memcpy(result.data(), readback.mapped, result.size() * 4);
    }
    host.destroy(image);
    host.destroy(input);
    host.destroy(readback);
    return result;
}

TEST_F(WrappedVulkanDevice, GraphRecordsIntoHostCommandBufferAndLeavesHostImageInDeclaredLayout) {
    ASSERT_TRUE(wrapHost());
    EXPECT_EQ(device->getNativeObject(NativeObjectType::VkDevice).as<VkDevice>(), host.device);
    EXPECT_EQ(device->getNativeObject(NativeObjectType::VkQueue).as<VkQueue>(), host.queue);
    EXPECT_TRUE(device->capabilities().rayTracingPipeline);

    std::optional<double> passTime;
    std::vector<uint32_t> values = runHostFrame(host, *device, /*allowTimestamps=*/true, passTime);
    ASSERT_EQ(values.size(), kWidth * kHeight);
    uint32_t mismatches = 0;
    for (uint32_t i = 0; i < kWidth * kHeight; ++i)
        if (values[i] != inputValue(i) * 3u + 1u && ++mismatches <= 5)
            ADD_FAILURE() << "texel " << i << ": got " << values[i] << ", expected " << inputValue(i) * 3u + 1u;
    EXPECT_EQ(mismatches, 0u);
    // Timestamps work on a wrapped command buffer (the module's own query pool, reset inside it).
    EXPECT_TRUE(passTime.has_value());
}

// Every call of the module goes through the pointers the host hands it (vk_dispatch.h): the host's
// vkGetInstanceProcAddr resolves the core entry points too, and the module's vkCreateBuffer and
// vkCmdDispatch calls land in the host's wrappers. The frame still gives the exact result.
TEST_F(WrappedVulkanDevice, EveryCallGoesThroughTheHostsGetInstanceProcAddr) {
    ASSERT_TRUE(wrapHost(countingGetInstanceProcAddr()));
    const ProcAddrLog& log = procAddrLog();
    for (const char* name : {"vkGetPhysicalDeviceProperties", "vkGetPhysicalDeviceMemoryProperties",
                             "vkGetPhysicalDeviceFormatProperties", "vkGetDeviceProcAddr"})
        EXPECT_TRUE(log.instanceNames.count(name)) << name << " was not resolved through the host's vkGetInstanceProcAddr";
    for (const char* name : {"vkCreateBuffer", "vkAllocateMemory", "vkCmdPipelineBarrier2", "vkCmdDispatch",
                             "vkQueueSubmit2", "vkCreateSemaphore", "vkCreateAccelerationStructureKHR"})
        EXPECT_TRUE(log.deviceNames.count(name)) << name << " was not resolved through the host's vkGetDeviceProcAddr";

    auto buffer = device->createBuffer(BufferDesc().setByteSize(256).setUsage(BufferUsage::Storage).setDebugName("counted"));
    ASSERT_TRUE(buffer) << buffer.message();
    EXPECT_GE(log.createBufferCalls, 1) << "vkCreateBuffer bypassed the host's pointer";
    std::optional<double> passTime;
    std::vector<uint32_t> values = runHostFrame(host, *device, /*allowTimestamps=*/false, passTime);
    ASSERT_EQ(values.size(), kWidth * kHeight);
    uint32_t mismatches = 0;
    for (uint32_t i = 0; i < kWidth * kHeight; ++i) mismatches += values[i] != inputValue(i) * 3u + 1u;
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(log.dispatchCalls, 1) << "the graph's one dispatch did not go through the host's vkCmdDispatch";
}

TEST_F(WrappedVulkanDevice, TimestampsSwitchedOffRecordNoQueriesIntoHostCommandBuffer) {
    ASSERT_TRUE(wrapHost());
    std::optional<double> passTime;
    std::vector<uint32_t> values = runHostFrame(host, *device, /*allowTimestamps=*/false, passTime);
    ASSERT_EQ(values.size(), kWidth * kHeight);
    EXPECT_EQ(values[kWidth * kHeight - 1], inputValue(kWidth * kHeight - 1) * 3u + 1u);
    EXPECT_FALSE(passTime.has_value());
}

TEST_F(WrappedVulkanDevice, DeviceWithoutRayTracingIsRefusedNamingEveryMissingExtensionAndFeature) {
    ASSERT_TRUE(host.create(/*withRayTracing=*/false)) << host.why();
    auto wrapped = wrapVulkanDevice(host.deviceImport());
    ASSERT_FALSE(wrapped.ok());
    const std::string& m = wrapped.message();
    for (const char* name : {"VK_KHR_ray_tracing_pipeline", "VK_KHR_acceleration_structure",
                             "VK_KHR_deferred_host_operations", "rayTracingPipeline", "accelerationStructure"})
        EXPECT_NE(m.find(name), std::string::npos) << "missing '" << name << "' in: " << m;
    // Only ray tracing is missing: the same device serves compute/raster work when RT is not required.
    VulkanDeviceImport computeOnly = host.deviceImport();
    computeOnly.requireRayTracing = false;
    auto plain = wrapVulkanDevice(computeOnly);
    ASSERT_TRUE(plain.ok()) << plain.message();
    EXPECT_FALSE(plain.value()->capabilities().rayTracingPipeline);
}

TEST_F(WrappedVulkanDevice, ImportWithoutStorageUsageForStorageUseIsRefusedNamingTheTexture) {
    ASSERT_TRUE(wrapHost());
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    RawImage image = host.createImage(8, 8, VK_FORMAT_R8G8B8A8_UNORM, usage);
    auto refused = importVulkanTexture(*device, {.image = image.image, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                                 .usage = usage, .width = 8, .height = 8,
                                                 .uses = TextureUsage::Sampled | TextureUsage::Storage,
                                                 .debugName = "host colour target"});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.message().find("'host colour target'"), std::string::npos) << refused.message();
    EXPECT_NE(refused.message().find("VK_IMAGE_USAGE_STORAGE_BIT"), std::string::npos) << refused.message();
    EXPECT_EQ(refused.message().find("Sampled"), std::string::npos) << "Sampled is allowed: " << refused.message();
    // The uses the image allows import fine.
    auto sampled = importVulkanTexture(*device, {.image = image.image, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                                 .usage = usage, .width = 8, .height = 8,
                                                 .uses = TextureUsage::Sampled | TextureUsage::RenderTarget,
                                                 .debugName = "host colour target"});
    EXPECT_TRUE(sampled.ok()) << sampled.message();
    sampled = Error{};   // release the import before the host destroys its image
    host.destroy(image);
}

TEST_F(WrappedVulkanDevice, ImportOfBufferWithoutStorageUsageForStorageUseIsRefusedNamingTheBuffer) {
    ASSERT_TRUE(wrapHost());
    RawBuffer buffer = host.createHostBuffer(256, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    auto refused = importVulkanBuffer(*device, {.buffer = buffer.buffer, .byteSize = 256,
                                                .usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                                .uses = BufferUsage::Storage | BufferUsage::Constant,
                                                .debugName = "host constants"});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.message().find("'host constants'"), std::string::npos) << refused.message();
    EXPECT_NE(refused.message().find("VK_BUFFER_USAGE_STORAGE_BUFFER_BIT"), std::string::npos) << refused.message();
    EXPECT_EQ(refused.message().find("Constant"), std::string::npos) << "Constant is allowed: " << refused.message();
    host.destroy(buffer);
}

// The render graph places buffers and optimal images in one heap: each virtual resource's requirements
// start and end on the device's bufferImageGranularity page (Vulkan spec 12.7), read from the device,
// not a fixed 1024 bytes.
TEST_F(WrappedVulkanDevice, VirtualResourceRequirementsFollowTheDevicesBufferImageGranularity) {
    ASSERT_TRUE(wrapHost());
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(host.physicalDevice, &props);
    const uint64_t page = std::max<uint64_t>(1, props.limits.bufferImageGranularity);
    const MemoryRequirements buffer = device->memoryRequirements(BufferDesc().setByteSize(100).setVirtual(true));
    const MemoryRequirements texture = device->memoryRequirements(
        TextureDesc().setSize(3, 3).setFormat(Format::R32_FLOAT).setUsage(TextureUsage::Storage).setVirtual(true));
    for (const MemoryRequirements& r : {buffer, texture}) {
        EXPECT_EQ(r.alignment % page, 0u) << "granularity " << page;
        EXPECT_EQ(r.size % page, 0u) << "granularity " << page << ", size " << r.size;
    }
    std::printf("[ measured ] bufferImageGranularity %llu: 100-byte buffer -> %llu bytes, 3x3 R32F image -> %llu\n",
                (unsigned long long)page, (unsigned long long)buffer.size, (unsigned long long)texture.size);
}

TEST_F(WrappedVulkanDevice, HostCommandBufferIsNeverSubmittedByTheDevice) {
    ASSERT_TRUE(wrapHost());
    host.begin();
    auto cmd = wrapVulkanCommandBuffer(*device, {.commandBuffer = host.commandBuffer});
    ASSERT_TRUE(cmd.ok()) << cmd.message();
    cmd.value()->end();   // records nothing: the host still ends the buffer itself below
    auto submitted = device->submit(cmd.value());
    ASSERT_FALSE(submitted.ok());
    EXPECT_NE(submitted.message().find("the host submits it"), std::string::npos) << submitted.message();
    // The buffer is still the host's to end and submit (the layer would report ending it twice).
    EXPECT_TRUE(host.endSubmitAndWait());
}

}  // namespace
}  // namespace caustics::test
