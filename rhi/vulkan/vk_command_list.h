#pragma once
// Command list: one VkCommandPool + VkCommandBuffer. Everything the list allocates for itself
// (staging/upload/scratch buffers) or is asked to retain stays alive until the submission that
// executed it has completed: begin() waits for the previous submission before releasing them.
//
// The ray-tracing methods (setRayTracingState, dispatchRays, buildBottomLevel, buildTopLevel,
// buildTopLevelFromBuffer) are defined in vk_command_list_ray_tracing.cpp (ray-tracing helper); the
// rest in vk_command_list*.cpp of the core.
#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "caustics/rhi/command_list.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

class VulkanDevice;

class VulkanCommandList final : public ICommandList {
public:
    static Result<std::shared_ptr<VulkanCommandList>> create(VulkanDevice& device);
    // Records into a host engine's command buffer, already begun (vk_interop_command_list.cpp):
    // begin()/end() then record nothing and the buffer is never reset, ended, submitted or freed.
    static std::shared_ptr<VulkanCommandList> wrap(VulkanDevice& device, VkCommandBuffer commandBuffer,
                                                   bool allowTimestamps);
    ~VulkanCommandList() override;

    void begin() override;
    void end() override;

    void barriers(std::span<const TextureBarrier> textures, std::span<const BufferBarrier> buffers,
                  std::span<const AccelStructBarrier> accelStructs = {}) override;

    void writeBuffer(const BufferHandle& dst, const void* data, uint64_t bytes, uint64_t dstOffset = 0) override;
    void copyBuffer(const BufferHandle& dst, uint64_t dstOffset, const BufferHandle& src, uint64_t srcOffset,
                    uint64_t bytes) override;
    void fillBuffer(const BufferHandle& dst, uint32_t value, uint64_t offset = 0, uint64_t bytes = ~0ull) override;
    void writeTexture(const TextureHandle& dst, uint32_t layer, uint32_t mip, const void* data,
                      uint64_t bytes) override;
    void copyTexture(const TextureHandle& dst, const TextureRegion& dstRegion, const TextureHandle& src,
                     const TextureRegion& srcRegion) override;
    void copyTextureToBuffer(const BufferHandle& dst, uint64_t dstOffset, const TextureHandle& src,
                             uint32_t layer = 0, uint32_t mip = 0) override;
    void clearTextureFloat(const TextureHandle& texture, const float value[4]) override;
    void clearTextureUint(const TextureHandle& texture, const uint32_t value[4]) override;

    void setComputePipeline(const ComputePipelineHandle& pipeline) override;
    void dispatch(uint32_t x, uint32_t y = 1, uint32_t z = 1) override;
    void dispatchIndirect(const BufferHandle& args, uint64_t offset = 0) override;

    void beginRendering(const RenderingDesc& desc) override;
    void endRendering() override;
    void setGraphicsPipeline(const GraphicsPipelineHandle& pipeline) override;
    void setViewport(float x, float y, float width, float height) override;
    void setVertexBuffer(uint32_t slot, const BufferHandle& buffer, uint64_t offset = 0) override;
    void setIndexBuffer(const BufferHandle& buffer, uint64_t offset = 0) override;
    void draw(uint32_t vertexCount, uint32_t instanceCount = 1, uint32_t firstVertex = 0,
              uint32_t firstInstance = 0) override;
    void drawIndexed(uint32_t indexCount, uint32_t instanceCount = 1, uint32_t firstIndex = 0,
                     int32_t vertexOffset = 0, uint32_t firstInstance = 0) override;

    // --- defined in vk_command_list_ray_tracing.cpp (ray-tracing helper) ---
    void setRayTracingState(const StateObjectHandle& stateObject, const ShaderTableHandle& table) override;
    void dispatchRays(uint32_t width, uint32_t height = 1, uint32_t depth = 1) override;
    void dispatchRaysIndirect(const BufferHandle& args, uint64_t offset = 0) override;
    void buildBottomLevel(const AccelStructHandle& blas, bool update = false) override;
    void buildTopLevel(const AccelStructHandle& tlas, std::span<const InstanceDesc> instances,
                       bool update = false) override;
    void buildTopLevelFromBuffer(const AccelStructHandle& tlas, const BufferHandle& instances, uint64_t offset,
                                 uint32_t count, bool update = false) override;
    // ---

    // Work for whichever pipeline was bound last, including VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR.
    void setBindingSet(uint32_t index, const BindingSetHandle& set) override;
    void setPushConstants(const void* data, uint32_t bytes) override;

    bool recordsTimestamps() const override { return timestampsAllowed_; }
    void resetTimestamps(const TimestampPoolHandle& pool, uint32_t first, uint32_t count) override;
    void writeTimestamp(const TimestampPoolHandle& pool, uint32_t index) override;
    void beginMarker(std::string_view name) override;
    void endMarker() override;

    NativeObject getNativeObject(NativeObjectType type) const override {
        return type == NativeObjectType::VkCommandBuffer ? NativeObject::from(commandBuffer_) : NativeObject();
    }

    // ---- For the device and the ray-tracing file ----
    VkCommandBuffer commandBuffer() const { return commandBuffer_; }
    const VulkanContext& context() const { return *context_; }
    const ContextPtr& contextPtr() const { return context_; }
    VulkanDevice& device() const { return device_; }

    // A buffer owned by this list until its submission completes (upload staging, AS scratch, instance
    // uploads). Upload/Readback memory is persistently mapped. Null (and recordError) on failure.
    BufferHandle allocateTransient(const BufferDesc& desc);
    // Keeps any object alive until this list's submission completes (state objects, shader tables, ...).
    void retain(std::shared_ptr<const void> object);

    // The layout/bind point setBindingSet and setPushConstants use; setComputePipeline,
    // setGraphicsPipeline and setRayTracingState set them.
    void bindPipelineLayout(VkPipelineLayout layout, VkPipelineBindPoint bindPoint) {
        boundLayout_ = layout;
        boundBindPoint_ = bindPoint;
    }
    VkPipelineLayout boundLayout() const { return boundLayout_; }
    VkPipelineBindPoint boundBindPoint() const { return boundBindPoint_; }

    // The ray-tracing state set by setRayTracingState, read by dispatchRays.
    struct RayTracingState {
        StateObjectHandle stateObject;
        ShaderTableHandle shaderTable;
    };
    RayTracingState& rayTracingState() { return rayTracing_; }

    // Recording errors are reported by IDevice::submit (ICommandList methods return void).
    void recordError(std::string message);
    const std::optional<Error>& recordingError() const { return error_; }

    // Called by VulkanDevice::submit with the fence value that will signal when the list completes.
    void markSubmitted(uint64_t fenceValue) { submittedFence_ = fenceValue; }
    bool isRecording() const { return recording_; }
    bool isWrapped() const { return wrapped_; }

private:
    VulkanCommandList(std::shared_ptr<VulkanDevice> device, ContextPtr context)
        : deviceRef_(std::move(device)), device_(*deviceRef_), context_(std::move(context)) {}
    void releaseResources();   // waits for the last submission, then drops transients/retained

    std::shared_ptr<VulkanDevice> deviceRef_;   // a list keeps its device alive
    VulkanDevice& device_;
    ContextPtr context_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    bool recording_ = false;
    bool wrapped_ = false;             // the host's command buffer
    bool timestampsAllowed_ = true;    // false: timestamp calls record nothing
    uint64_t submittedFence_ = 0;
    VkPipelineLayout boundLayout_ = VK_NULL_HANDLE;
    VkPipelineBindPoint boundBindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    RayTracingState rayTracing_;
    std::vector<BufferHandle> transients_;
    std::vector<std::shared_ptr<const void>> retained_;
    std::optional<Error> error_;
};

inline VulkanCommandList* toVk(const CommandListHandle& c) { return static_cast<VulkanCommandList*>(c.get()); }

}  // namespace caustics::rhi::vulkan
