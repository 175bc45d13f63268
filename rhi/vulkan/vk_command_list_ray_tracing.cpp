// Ray-tracing commands of VulkanCommandList: binding a state object + shader table, vkCmdTraceRaysKHR,
// and acceleration-structure builds/updates. Each build gets its own scratch buffer (aligned to
// minAccelerationStructureScratchOffsetAlignment) owned by the list until its submission completes,
// so builds in one list never share scratch memory and need no scratch barriers between them.
#include <cstring>

#include "vk_accel_struct.h"
#include "vk_buffer.h"
#include "vk_command_list.h"
#include "vk_shader_table.h"
#include "vk_state_object.h"

namespace caustics::rhi::vulkan {
namespace {

// Records one build (or update) of `as` from `geometry`; scratch comes from the list's transients.
void recordBuild(VulkanCommandList& list, VulkanAccelStruct& as, AccelGeometryInfo& geometry, bool update,
                 const char* what) {
    const std::string name = std::string(what) + (as.desc().debugName.empty() ? "" : " '" + as.desc().debugName + "'");
    if (update && !hasAny(as.desc().flags, AccelBuildFlags::AllowUpdate)) {
        list.recordError(name + ": update requested, but the structure was created without AllowUpdate");
        return;
    }
    if (update && !as.built) {
        list.recordError(name + ": update requested before any build");
        return;
    }
    const VulkanContext& ctx = list.context();
    const uint64_t alignment = std::max<uint64_t>(1, ctx.accelStructProperties.minAccelerationStructureScratchOffsetAlignment);
    const uint64_t scratchBytes = std::max<uint64_t>(1, update ? as.updateScratchBytes() : as.buildScratchBytes());
    BufferHandle scratch = list.allocateTransient(BufferDesc()
                                                      .setByteSize(scratchBytes + alignment)
                                                      .setUsage(BufferUsage::Storage)
                                                      .setMemory(MemoryType::DeviceLocal)
                                                      .setDebugName("AS build scratch"));
    if (!scratch) return;

    VkAccelerationStructureBuildGeometryInfoKHR build{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    build.type = as.type();
    build.flags = toVkBuildFlags(as.desc().flags);
    build.mode = update ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    build.srcAccelerationStructure = update ? as.handle() : VK_NULL_HANDLE;   // in-place refit
    build.dstAccelerationStructure = as.handle();
    build.geometryCount = uint32_t(geometry.geometries.size());
    build.pGeometries = geometry.geometries.data();
    build.scratchData.deviceAddress = alignUp(scratch->deviceAddress(), alignment);
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = geometry.ranges.data();
    ctx.fn.vkCmdBuildAccelerationStructuresKHR(list.commandBuffer(), 1, &build, &ranges);
    as.built = true;
}

}  // namespace

void VulkanCommandList::setRayTracingState(const StateObjectHandle& stateObject, const ShaderTableHandle& table) {
    if (!stateObject || !table) {
        recordError("setRayTracingState: null state object or shader table");
        return;
    }
    if (table->desc().stateObject != stateObject) {
        recordError("setRayTracingState: shader table '" + table->desc().debugName +
                    "' was built for another state object than '" + stateObject->desc().debugName + "'");
        return;
    }
    VulkanStateObject& so = *toVk(stateObject);
    context().fn.vkCmdBindPipeline(commandBuffer(), VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, so.pipeline());
    bindPipelineLayout(so.layout(), VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR);
    rayTracingState() = {stateObject, table};
    retain(stateObject);
    retain(table);
}

void VulkanCommandList::dispatchRays(uint32_t width, uint32_t height, uint32_t depth) {
    const RayTracingState& state = rayTracingState();
    if (!state.shaderTable) {
        recordError("dispatchRays: no setRayTracingState before it");
        return;
    }
    const VulkanShaderTable& table = *toVk(state.shaderTable);
    context().fn.vkCmdTraceRaysKHR(commandBuffer(), &table.rayGen(), &table.miss(), &table.hitGroup(), &table.callable(),
                                   width, height, depth);
}

void VulkanCommandList::dispatchRaysIndirect(const BufferHandle& args, uint64_t offset) {
    const RayTracingState& state = rayTracingState();
    if (!state.shaderTable) {
        recordError("dispatchRaysIndirect: no setRayTracingState before it");
        return;
    }
    if (!context().capabilities.rayTracingIndirect) {
        recordError("dispatchRaysIndirect: the device has no rayTracingPipelineTraceRaysIndirect");
        return;
    }
    if (!args || !hasAny(args->desc().usage, BufferUsage::Indirect) || offset % 4 != 0 ||
        offset + 12 > args->desc().byteSize) {
        recordError("dispatchRaysIndirect: the argument buffer needs BufferUsage::Indirect and 12 bytes at a "
                    "4-aligned offset");
        return;
    }
    retain(args);
    const VulkanShaderTable& table = *toVk(state.shaderTable);
    context().fn.vkCmdTraceRaysIndirectKHR(commandBuffer(), &table.rayGen(), &table.miss(), &table.hitGroup(),
                                           &table.callable(), args->deviceAddress() + offset);
}

void VulkanCommandList::buildBottomLevel(const AccelStructHandle& blas, bool update) {
    if (!blas || blas->desc().isTopLevel) {
        recordError("buildBottomLevel: null or top-level acceleration structure");
        return;
    }
    auto geometry = describeBottomLevel(blas->desc());
    if (!geometry) {
        recordError("buildBottomLevel: " + geometry.message());
        return;
    }
    // Input buffers and the structure itself must live until the build has run.
    for (const GeometryDesc& g : blas->desc().geometries) {
        retain(g.triangles.vertexBuffer);
        retain(g.triangles.indexBuffer);
        retain(g.aabbs.buffer);
    }
    retain(blas);
    recordBuild(*this, *toVk(blas), geometry.value(), update, "buildBottomLevel");
}

void VulkanCommandList::buildTopLevel(const AccelStructHandle& tlas, std::span<const InstanceDesc> instances,
                                      bool update) {
    // Host instances go to an upload buffer owned by the list (VkAccelerationStructureInstanceKHR
    // needs 16-byte alignment, which every buffer start satisfies).
    BufferHandle upload = allocateTransient(BufferDesc()
                                                .setByteSize(std::max<uint64_t>(1, instances.size_bytes()))
                                                .setUsage(BufferUsage::AccelStructInput)
                                                .setMemory(MemoryType::Upload)
                                                .setDebugName("TLAS instances"));
    if (!upload) return;
    if (!upload->mappedData()) {
        recordError("buildTopLevel: the instance upload buffer has no host mapping");
        return;
    }
    if (!instances.empty()) std::memcpy(upload->mappedData(), instances.data(), instances.size_bytes());
    buildTopLevelFromBuffer(tlas, upload, 0, uint32_t(instances.size()), update);
}

void VulkanCommandList::buildTopLevelFromBuffer(const AccelStructHandle& tlas, const BufferHandle& instances,
                                                uint64_t offset, uint32_t count, bool update) {
    if (!tlas || !tlas->desc().isTopLevel || !instances) {
        recordError("buildTopLevel: null instance buffer, or null or bottom-level acceleration structure");
        return;
    }
    if (count > tlas->desc().maxInstances) {
        recordError("buildTopLevel '" + tlas->desc().debugName + "': " + std::to_string(count) +
                    " instances exceed maxInstances " + std::to_string(tlas->desc().maxInstances));
        return;
    }
    if (offset % 16 != 0) {
        recordError("buildTopLevelFromBuffer: instance offset must be a multiple of 16 (VUID-vkCmdBuildAccelerationStructuresKHR-pInfos-03715)");
        return;
    }
    retain(instances);
    retain(tlas);
    AccelGeometryInfo geometry = describeTopLevel(toVk(instances)->deviceAddress() + offset, count);
    recordBuild(*this, *toVk(tlas), geometry, update, "buildTopLevel");
}

}  // namespace caustics::rhi::vulkan
