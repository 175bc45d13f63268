#pragma once
// VulkanDevice: IDevice over one VkDevice (see vk_context.h for the shared state).
//
// Ownership split between the two helpers writing this backend:
//  - core (vk_device*.cpp, vk_buffer/texture/binding/pipeline/memory/command_list*.cpp): everything
//    declared here and in the other vk_*.h headers, EXCEPT
//  - ray tracing (vk_accel_struct*.cpp, vk_state_object*.cpp, vk_shader_table*.cpp,
//    vk_command_list_ray_tracing.cpp): VulkanDevice::createAccelStruct, compactAccelStruct,
//    createStateObject, createShaderTable; the five ray-tracing methods of VulkanCommandList; and
//    vulkanAccelStructHandle() below, which binding sets use to write acceleration-structure
//    descriptors.
// Internal headers (vk_context.h, vk_buffer.h, vk_texture.h, vk_binding.h, vk_pipeline.h,
// vk_command_list.h, vk_device.h) only grow; existing declarations stay compatible.
#include <vulkan/vulkan.h>

#include <functional>
#include <memory>

#include "caustics/rhi/device.h"
#include "vk_command_list.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

class VulkanDevice final : public IDevice, public std::enable_shared_from_this<VulkanDevice> {
public:
    static Result<std::shared_ptr<VulkanDevice>> create(const DeviceDesc& desc);
    // Over a context whose device already exists (a host engine's, vk_device_wrap.cpp).
    static std::shared_ptr<VulkanDevice> adopt(ContextPtr context) {
        return std::shared_ptr<VulkanDevice>(new VulkanDevice(std::move(context)));
    }
    ~VulkanDevice() override;

    Backend backend() const override { return Backend::Vulkan; }
    const Capabilities& capabilities() const override { return context_->capabilities; }
    NativeObject getNativeObject(NativeObjectType type) const override;

    Result<BufferHandle> createBuffer(const BufferDesc& desc) override;
    Result<TextureHandle> createTexture(const TextureDesc& desc) override;
    Result<SamplerHandle> createSampler(const SamplerDesc& desc) override;
    Result<HeapHandle> createHeap(const HeapDesc& desc) override;
    MemoryRequirements memoryRequirements(const TextureDesc& desc) override;
    MemoryRequirements memoryRequirements(const BufferDesc& desc) override;
    Status bindMemory(const TextureHandle& texture, const HeapHandle& heap, uint64_t offset) override;
    Status bindMemory(const BufferHandle& buffer, const HeapHandle& heap, uint64_t offset) override;

    Result<BindingLayoutHandle> createBindingLayout(const BindingLayoutDesc& desc) override;
    Result<BindingSetHandle> createBindingSet(const BindingSetDesc& desc, const BindingLayoutHandle& layout) override;

    Result<ComputePipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override;
    Result<GraphicsPipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override;

    // --- defined by the ray-tracing helper (vk_accel_struct.cpp, vk_state_object.cpp, vk_shader_table.cpp) ---
    Result<AccelStructHandle> createAccelStruct(const AccelStructDesc& desc) override;
    Result<AccelStructHandle> compactAccelStruct(const AccelStructHandle& built) override;
    Result<StateObjectHandle> createStateObject(const StateObjectDesc& desc) override;
    Result<ShaderTableHandle> createShaderTable(const ShaderTableDesc& desc) override;
    // ---

    Result<TimestampPoolHandle> createTimestampPool(uint32_t count) override;
    std::vector<std::optional<double>> readTimestamps(const TimestampPoolHandle& pool, uint32_t first,
                                                      uint32_t count) override;

    Result<CommandListHandle> createCommandList() override;
    Result<uint64_t> submit(std::span<const CommandListHandle> lists) override;
    using IDevice::submit;
    Status waitForFence(uint64_t value) override;
    Status waitIdle() override;
    Status readBuffer(const BufferHandle& buffer, void* dst, uint64_t bytes, uint64_t offset = 0) override;

    // ---- Internal ----
    VulkanContext& context() const { return *context_; }
    const ContextPtr& contextPtr() const { return context_; }
    // Records with `record` into a fresh command list (already begun), submits and waits for it.
    Status executeImmediate(const std::function<void(VulkanCommandList&)>& record);

private:
    explicit VulkanDevice(ContextPtr context) : context_(std::move(context)) {}
    ContextPtr context_;
};

// The VkAccelerationStructureKHR of an acceleration structure made by this backend (ray-tracing helper).
VkAccelerationStructureKHR vulkanAccelStructHandle(const IAccelStruct& accelStruct);

}  // namespace caustics::rhi::vulkan
