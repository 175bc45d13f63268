#pragma once
// Binding layouts (VkDescriptorSetLayout), binding sets (VkDescriptorSet) and the growing descriptor
// pool allocator behind them.
#include <vulkan/vulkan.h>

#include <mutex>
#include <vector>

#include "caustics/rhi/binding.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

VkDescriptorType toVkDescriptorType(BindingType type);
VkShaderStageFlags toVkShaderStages(ShaderStage stages);

// Pools of fixed capacity; a new pool is made when the current ones are full, so allocation never
// fails for lack of room. Sets are freed individually (VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT).
class DescriptorAllocator {
public:
    explicit DescriptorAllocator(VulkanContext& context) : context_(context) {}
    ~DescriptorAllocator();
    Result<VkDescriptorSet> allocate(VkDescriptorSetLayout layout, VkDescriptorPool& poolOut);
    void free(VkDescriptorPool pool, VkDescriptorSet set);

private:
    Result<VkDescriptorPool> newPool();
    VulkanContext& context_;
    std::mutex mutex_;
    std::vector<VkDescriptorPool> pools_;
};

class VulkanBindingLayout final : public IBindingLayout {
public:
    static Result<std::shared_ptr<VulkanBindingLayout>> create(const ContextPtr& context, const BindingLayoutDesc& desc);
    ~VulkanBindingLayout() override;
    const BindingLayoutDesc& desc() const override { return desc_; }
    VkDescriptorSetLayout handle() const { return layout_; }

private:
    VulkanBindingLayout(ContextPtr context, const BindingLayoutDesc& desc) : context_(std::move(context)), desc_(desc) {}
    ContextPtr context_;
    BindingLayoutDesc desc_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
};

inline VulkanBindingLayout* toVk(const BindingLayoutHandle& layout) {
    return static_cast<VulkanBindingLayout*>(layout.get());
}

class VulkanBindingSet final : public IBindingSet {
public:
    static Result<std::shared_ptr<VulkanBindingSet>> create(const ContextPtr& context, const BindingSetDesc& desc,
                                                            const BindingLayoutHandle& layout);
    ~VulkanBindingSet() override;
    const BindingSetDesc& desc() const override { return desc_; }
    const BindingLayoutHandle& layout() const override { return layout_; }
    VkDescriptorSet handle() const { return set_; }

private:
    VulkanBindingSet(ContextPtr context, const BindingSetDesc& desc, BindingLayoutHandle layout)
        : context_(std::move(context)), desc_(desc), layout_(std::move(layout)) {}
    ContextPtr context_;
    BindingSetDesc desc_;          // holds the referenced resources alive with the set
    BindingLayoutHandle layout_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

inline VulkanBindingSet* toVk(const BindingSetHandle& set) { return static_cast<VulkanBindingSet*>(set.get()); }

}  // namespace caustics::rhi::vulkan
