// Compaction of a built bottom level (Vulkan spec, vkCmdWriteAccelerationStructuresPropertiesKHR and
// vkCmdCopyAccelerationStructureKHR):
// query the compacted size after the build, create a structure of that size, copy with
// VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR. Both steps wait for the GPU (the size must reach
// the host before the target can be created).
#include "vk_accel_struct.h"
#include "vk_device.h"

namespace caustics::rhi::vulkan {
namespace {

// Orders earlier AS builds/copies (any submission on the queue) before the next AS command.
void accelStructBuildBarrier(const VulkanContext& ctx, VkCommandBuffer cb, VkPipelineStageFlags dstStages,
                             VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = dstAccess;
    ctx.fn.vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, dstStages, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
}

}  // namespace

Result<AccelStructHandle> VulkanDevice::compactAccelStruct(const AccelStructHandle& built) {
    if (!built) return makeError("compactAccelStruct: null acceleration structure");
    VulkanAccelStruct& source = *toVk(built);
    const std::string name = source.desc().debugName.empty() ? "BLAS" : "'" + source.desc().debugName + "'";
    if (!hasAny(source.desc().flags, AccelBuildFlags::AllowCompaction))
        return makeError("compactAccelStruct: " + name + " was not created with AccelBuildFlags::AllowCompaction");
    if (!source.built) return makeError("compactAccelStruct: " + name + " has not been built yet");

    VulkanContext& ctx = context();
    VkQueryPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    poolInfo.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
    poolInfo.queryCount = 1;
    VkQueryPool pool = VK_NULL_HANDLE;
    VkResult r = ctx.fn.vkCreateQueryPool(ctx.device, &poolInfo, nullptr, &pool);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateQueryPool (compacted size)", source.desc().debugName);

    VkAccelerationStructureKHR sourceHandle = source.handle();
    Status queried = executeImmediate([&](VulkanCommandList& list) {
        VkCommandBuffer cb = list.commandBuffer();
        ctx.fn.vkCmdResetQueryPool(cb, pool, 0, 1);
        accelStructBuildBarrier(ctx, cb, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                                VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
        ctx.fn.vkCmdWriteAccelerationStructuresPropertiesKHR(
            cb, 1, &sourceHandle, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
    });
    VkDeviceSize compactedBytes = 0;
    if (queried) {
        r = ctx.fn.vkGetQueryPoolResults(ctx.device, pool, 0, 1, sizeof(compactedBytes), &compactedBytes,
                                  sizeof(compactedBytes), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
    }
    ctx.fn.vkDestroyQueryPool(ctx.device, pool, nullptr);
    if (!queried) return queried.error();
    if (r != VK_SUCCESS) return vkError(r, "vkGetQueryPoolResults (compacted size)", source.desc().debugName);
    if (compactedBytes == 0) return makeError("compactAccelStruct: " + name + " reported a compacted size of 0");

    AccelStructDesc desc = source.desc();
    desc.debugName = source.desc().debugName + " (compacted)";
    auto target = VulkanAccelStruct::create(contextPtr(), desc, compactedBytes);
    if (!target) return target.error();
    VkAccelerationStructureKHR targetHandle = target.value()->handle();
    Status copied = executeImmediate([&](VulkanCommandList& list) {
        VkCommandBuffer cb = list.commandBuffer();
        VkCopyAccelerationStructureInfoKHR copy{VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
        copy.src = sourceHandle;
        copy.dst = targetHandle;
        copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
        ctx.fn.vkCmdCopyAccelerationStructureKHR(cb, &copy);
        // Makes the copy visible to whatever uses the new structure next (TLAS builds, traces).
        accelStructBuildBarrier(ctx, cb, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    });
    if (!copied) return copied.error();
    target.value()->built = true;
    return AccelStructHandle(target.value());
}

}  // namespace caustics::rhi::vulkan
