#include "vk_accel_struct.h"

#include <cstddef>

#include "vk_buffer.h"
#include "vk_device.h"

namespace caustics::rhi::vulkan {

// InstanceDesc is handed to Vulkan byte for byte (VkAccelerationStructureInstanceKHR, spec 12.6.1
// "Instances"), and InstanceFlags are the VkGeometryInstanceFlagBitsKHR values.
static_assert(sizeof(InstanceDesc) == sizeof(VkAccelerationStructureInstanceKHR));
static_assert(offsetof(InstanceDesc, blasAddress) == offsetof(VkAccelerationStructureInstanceKHR, accelerationStructureReference));
static_assert(uint32_t(InstanceFlags::TriangleCullDisable) == VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR);
static_assert(uint32_t(InstanceFlags::TriangleFrontCounterClockwise) == VK_GEOMETRY_INSTANCE_TRIANGLE_FRONT_COUNTERCLOCKWISE_BIT_KHR);
static_assert(uint32_t(InstanceFlags::ForceOpaque) == VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR);
static_assert(uint32_t(InstanceFlags::ForceNonOpaque) == VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR);

namespace {

VkGeometryFlagsKHR toVkGeometryFlags(GeometryFlags flags) {
    VkGeometryFlagsKHR out = 0;
    if (hasAny(flags, GeometryFlags::Opaque)) out |= VK_GEOMETRY_OPAQUE_BIT_KHR;
    if (hasAny(flags, GeometryFlags::NoDuplicateAnyHit)) out |= VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
    return out;
}

uint64_t addressOf(const BufferHandle& buffer, uint64_t offset) {
    return buffer ? toVk(buffer)->deviceAddress() + offset : 0;
}

std::string nameOf(const AccelStructDesc& desc) {
    return desc.debugName.empty() ? std::string(desc.isTopLevel ? "TLAS" : "BLAS") : "'" + desc.debugName + "'";
}

}  // namespace

VkBuildAccelerationStructureFlagsKHR toVkBuildFlags(AccelBuildFlags flags) {
    VkBuildAccelerationStructureFlagsKHR out = 0;
    if (hasAny(flags, AccelBuildFlags::AllowUpdate)) out |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
    if (hasAny(flags, AccelBuildFlags::AllowCompaction)) out |= VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
    if (hasAny(flags, AccelBuildFlags::PreferFastTrace)) out |= VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    else if (hasAny(flags, AccelBuildFlags::PreferFastBuild)) out |= VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR;
    return out;
}

Result<AccelGeometryInfo> describeBottomLevel(const AccelStructDesc& desc) {
    AccelGeometryInfo info;
    for (size_t i = 0; i < desc.geometries.size(); ++i) {
        const GeometryDesc& g = desc.geometries[i];
        VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
        geometry.flags = toVkGeometryFlags(g.flags);
        uint32_t primitives = 0;
        if (g.type == GeometryDesc::Type::Triangles) {
            const TriangleGeometry& t = g.triangles;
            const uint32_t corners = t.indexBuffer ? t.indexCount : t.vertexCount;
            if (corners % 3 != 0 || t.vertexCount == 0)
                return makeError("acceleration structure " + nameOf(desc) + ": geometry " + std::to_string(i) +
                                 " has " + std::to_string(corners) + " triangle corners (need a non-zero multiple of 3)");
            geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
            VkAccelerationStructureGeometryTrianglesDataKHR& tri = geometry.geometry.triangles;
            tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
            tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
            tri.vertexData.deviceAddress = addressOf(t.vertexBuffer, t.vertexOffset);
            tri.vertexStride = t.vertexStride;
            tri.maxVertex = t.vertexCount - 1;
            tri.indexType = t.indexBuffer ? VK_INDEX_TYPE_UINT32 : VK_INDEX_TYPE_NONE_KHR;
            tri.indexData.deviceAddress = addressOf(t.indexBuffer, t.indexOffset);
            primitives = corners / 3;
        } else {
            geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
            VkAccelerationStructureGeometryAabbsDataKHR& aabbs = geometry.geometry.aabbs;
            aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
            aabbs.data.deviceAddress = addressOf(g.aabbs.buffer, g.aabbs.offset);
            aabbs.stride = g.aabbs.stride;
            primitives = g.aabbs.count;
        }
        info.geometries.push_back(geometry);
        info.ranges.push_back({primitives, 0, 0, 0});
        info.primitiveCounts.push_back(primitives);
    }
    if (info.geometries.empty())
        return makeError("acceleration structure " + nameOf(desc) + ": a bottom level needs at least one geometry");
    return info;
}

AccelGeometryInfo describeTopLevel(uint64_t instancesAddress, uint32_t count) {
    AccelGeometryInfo info;
    VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    geometry.geometry.instances.arrayOfPointers = VK_FALSE;
    geometry.geometry.instances.data.deviceAddress = instancesAddress;
    info.geometries.push_back(geometry);
    info.ranges.push_back({count, 0, 0, 0});
    info.primitiveCounts.push_back(count);
    return info;
}

Result<std::shared_ptr<VulkanAccelStruct>> VulkanAccelStruct::create(const ContextPtr& context,
                                                                     const AccelStructDesc& desc, uint64_t storageBytes) {
    if (!context->fn.vkCreateAccelerationStructureKHR)
        return makeError("acceleration structure " + nameOf(desc) +
                         ": the device has no VK_KHR_acceleration_structure");
    std::shared_ptr<VulkanAccelStruct> as(new VulkanAccelStruct(context, desc));
    AccelGeometryInfo geometry;
    if (desc.isTopLevel) {
        if (desc.maxInstances == 0) return makeError("acceleration structure " + nameOf(desc) + ": maxInstances is 0");
        geometry = describeTopLevel(0, desc.maxInstances);
    } else {
        CAUSTICS_TRY(geometry, describeBottomLevel(desc));
    }
    VkAccelerationStructureBuildGeometryInfoKHR build{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    build.type = as->type();
    build.flags = toVkBuildFlags(desc.flags);
    build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    build.geometryCount = uint32_t(geometry.geometries.size());
    build.pGeometries = geometry.geometries.data();
    VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    context->fn.vkGetAccelerationStructureBuildSizesKHR(context->device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                        &build, geometry.primitiveCounts.data(), &sizes);
    as->buildScratchBytes_ = sizes.buildScratchSize;
    as->updateScratchBytes_ = sizes.updateScratchSize;
    as->storageBytes_ = storageBytes ? storageBytes : sizes.accelerationStructureSize;

    auto buffer = VulkanBuffer::create(context, BufferDesc()
                                                    .setByteSize(as->storageBytes_)
                                                    .setUsage(BufferUsage::AccelStructStorage)
                                                    .setMemory(MemoryType::DeviceLocal)
                                                    .setDebugName(desc.debugName + " storage"));
    if (!buffer) return buffer.error();
    as->storage_ = buffer.value();

    VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = buffer.value()->handle();
    info.offset = 0;
    info.size = as->storageBytes_;
    info.type = as->type();
    VkResult r = context->fn.vkCreateAccelerationStructureKHR(context->device, &info, nullptr, &as->handle_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateAccelerationStructureKHR", desc.debugName);
    if (!desc.debugName.empty())
        context->setName(VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, as->handle_, desc.debugName);
    VkAccelerationStructureDeviceAddressInfoKHR addressInfo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
    addressInfo.accelerationStructure = as->handle_;
    as->deviceAddress_ = context->fn.vkGetAccelerationStructureDeviceAddressKHR(context->device, &addressInfo);
    return as;
}

std::shared_ptr<VulkanAccelStruct> VulkanAccelStruct::wrap(const ContextPtr& context, const AccelStructDesc& desc,
                                                           VkAccelerationStructureKHR handle, uint64_t deviceAddress) {
    std::shared_ptr<VulkanAccelStruct> wrapped(new VulkanAccelStruct(context, desc));
    wrapped->handle_ = handle;
    wrapped->deviceAddress_ = deviceAddress;
    wrapped->ownsHandle_ = false;
    wrapped->built = true;
    return wrapped;
}

NativeObject VulkanAccelStruct::getNativeObject(NativeObjectType type) const {
    if (type == NativeObjectType::VkAccelerationStructureKHR) return NativeObject::from(handle_);
    if (type == NativeObjectType::VkBuffer && storage_) return storage_->getNativeObject(type);
    return {};
}

VulkanAccelStruct::~VulkanAccelStruct() {
    if (handle_ == VK_NULL_HANDLE || !ownsHandle_) return;
    // The storage buffer travels with the deferred destruction so it outlives the handle.
    context_->deferDestroy([context = context_.get(), handle = handle_, storage = storage_]() {
        context->fn.vkDestroyAccelerationStructureKHR(context->device, handle, nullptr);
    });
}

VkAccelerationStructureKHR vulkanAccelStructHandle(const IAccelStruct& accelStruct) {
    return static_cast<const VulkanAccelStruct&>(accelStruct).handle();
}

Result<AccelStructHandle> VulkanDevice::createAccelStruct(const AccelStructDesc& desc) {
    auto as = VulkanAccelStruct::create(contextPtr(), desc);
    if (!as) return as.error();
    return AccelStructHandle(as.value());
}

}  // namespace caustics::rhi::vulkan
