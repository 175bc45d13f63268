#pragma once
// Timestamp queries: a VkQueryPool of TIMESTAMP queries, reset on the host at creation (hostQueryReset).
#include <vulkan/vulkan.h>

#include "caustics/rhi/command_list.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

class VulkanTimestampPool final : public ITimestampPool {
public:
    static Result<std::shared_ptr<VulkanTimestampPool>> create(const ContextPtr& context, uint32_t count);
    ~VulkanTimestampPool() override;
    uint32_t capacity() const override { return capacity_; }
    VkQueryPool handle() const { return pool_; }

private:
    VulkanTimestampPool(ContextPtr context, uint32_t count) : context_(std::move(context)), capacity_(count) {}
    ContextPtr context_;
    uint32_t capacity_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

inline VulkanTimestampPool* toVk(const TimestampPoolHandle& p) { return static_cast<VulkanTimestampPool*>(p.get()); }

}  // namespace caustics::rhi::vulkan
