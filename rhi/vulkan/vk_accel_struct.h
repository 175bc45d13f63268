#pragma once
// Acceleration structures (VK_KHR_acceleration_structure): a VkAccelerationStructureKHR over its own
// device-local buffer, sized with vkGetAccelerationStructureBuildSizesKHR for the geometries (bottom
// level) or the instance capacity (top level) of its desc.
#include <vulkan/vulkan.h>

#include <vector>

#include "caustics/rhi/accel_struct.h"
#include "vk_context.h"

namespace caustics::rhi::vulkan {

// The geometry arrays one vkCmdBuildAccelerationStructuresKHR (or size query) needs.
struct AccelGeometryInfo {
    std::vector<VkAccelerationStructureGeometryKHR> geometries;
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
    std::vector<uint32_t> primitiveCounts;   // per geometry, for size queries
};

// Bottom level: triangles/AABBs of `desc` with their current buffer addresses (zero is fine for size
// queries). An error names the AS and the geometry (e.g. a triangle count not divisible by three).
Result<AccelGeometryInfo> describeBottomLevel(const AccelStructDesc& desc);
// Top level: `count` VkAccelerationStructureInstanceKHR at `instancesAddress`.
AccelGeometryInfo describeTopLevel(uint64_t instancesAddress, uint32_t count);
VkBuildAccelerationStructureFlagsKHR toVkBuildFlags(AccelBuildFlags flags);

class VulkanAccelStruct final : public IAccelStruct {
public:
    // `storageBytes` 0: size from the desc via vkGetAccelerationStructureBuildSizesKHR; otherwise a
    // structure of exactly that size (compaction target, whose size comes from a query).
    static Result<std::shared_ptr<VulkanAccelStruct>> create(const ContextPtr& context, const AccelStructDesc& desc,
                                                             uint64_t storageBytes = 0);
    // A host engine's structure (vk_interop_resources.cpp): never destroyed here; it counts as built.
    static std::shared_ptr<VulkanAccelStruct> wrap(const ContextPtr& context, const AccelStructDesc& desc,
                                                   VkAccelerationStructureKHR handle, uint64_t deviceAddress);
    ~VulkanAccelStruct() override;

    const AccelStructDesc& desc() const override { return desc_; }
    NativeObject getNativeObject(NativeObjectType type) const override;
    uint64_t deviceAddress() const override { return deviceAddress_; }
    uint64_t storageBytes() const override { return storageBytes_; }

    VkAccelerationStructureKHR handle() const { return handle_; }
    VkAccelerationStructureTypeKHR type() const {
        return desc_.isTopLevel ? VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR
                                : VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    }
    uint64_t buildScratchBytes() const { return buildScratchBytes_; }
    uint64_t updateScratchBytes() const { return updateScratchBytes_; }
    // True once built at least once: an update needs a previous build (VUID-...-04630).
    bool built = false;

private:
    VulkanAccelStruct(ContextPtr context, const AccelStructDesc& desc) : context_(std::move(context)), desc_(desc) {}
    ContextPtr context_;
    AccelStructDesc desc_;
    BufferHandle storage_;
    VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
    bool ownsHandle_ = true;
    uint64_t deviceAddress_ = 0;
    uint64_t storageBytes_ = 0;
    uint64_t buildScratchBytes_ = 0;
    uint64_t updateScratchBytes_ = 0;
};

inline VulkanAccelStruct* toVk(const AccelStructHandle& a) { return static_cast<VulkanAccelStruct*>(a.get()); }

}  // namespace caustics::rhi::vulkan
