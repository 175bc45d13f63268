#include "vk_timestamp_pool.h"

namespace caustics::rhi::vulkan {

Result<std::shared_ptr<VulkanTimestampPool>> VulkanTimestampPool::create(const ContextPtr& context, uint32_t count) {
    if (count == 0) return makeError("vulkan: timestamp pool of 0 queries");
    std::shared_ptr<VulkanTimestampPool> pool(new VulkanTimestampPool(context, count));
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    VkResult r = context->fn.vkCreateQueryPool(context->device, &info, nullptr, &pool->pool_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateQueryPool");
    // Queries start in an undefined state; reset them on the host so a read before any write
    // reports "not available" rather than being invalid (hostQueryReset, core 1.2).
    context->fn.vkResetQueryPool(context->device, pool->pool_, 0, count);
    return pool;
}

VulkanTimestampPool::~VulkanTimestampPool() {
    ContextPtr ctx = context_;
    VkQueryPool p = pool_;
    ctx->deferDestroy([ctx, p] { ctx->fn.vkDestroyQueryPool(ctx->device, p, nullptr); });
}

}  // namespace caustics::rhi::vulkan
