#pragma once
// The plain-Vulkan host engine's own ray-tracing scene (host_engine_test.cpp): its geometry, material
// and instance tables in the layout docs/embedding.md "Host scene tables" documents, one BLAS per mesh
// and a TLAS, all created and built with raw Vulkan calls (VK_KHR_acceleration_structure) on a
// RawVulkanHost. The module only sees them through importVulkanBuffer / importVulkanAccelStruct.
#include <vulkan/vulkan.h>

#include <vector>

#include "caustics/scene/gpu_types.h"
#include "caustics/scene/scene.h"
#include "raw_vulkan_host.h"

namespace caustics::test {

class HostRayTracingScene {
public:
    // The tables' usage: bound as storage buffers by the module, read by the host's AS builds, written
    // by vkCmdUpdateBuffer (recordMaterialUpload).
    static constexpr VkBufferUsageFlags kTableUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                      VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                                      VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

    // Writes the tables (host-visible) and creates the acceleration structures; `instanceRows` < the
    // scene's instance count leaves the instance table short (the refusal test); `diffuseAlbedoScale`
    // scales the base colour of the non-specular materials in the host's material table. False on failure.
    // `materialsOnTheGpu`: the CPU writes zeros into the material table; recordMaterialUpload() writes the
    // rows in the host's command buffer instead.
    bool create(RawVulkanHost& host, const scene::Scene& scene, size_t instanceRows, float diffuseAlbedoScale = 1.0f,
                bool materialsOnTheGpu = false);
    // Records vkCmdUpdateBuffer of the material rows into host.commandBuffer, with no barrier after it:
    // the host hands the tables over in CopyDest and the module's barrier makes the write visible.
    void recordMaterialUpload();
    // Records the BLAS builds, then the TLAS build, into host.commandBuffer; the TLAS is left readable
    // by ray-tracing shaders (a barrier AS write -> AS read at the ray-tracing stage).
    void recordBuilds();
    void destroy();

    RawBuffer positions, vertices, indices, materials, instances;
    VkDeviceSize positionBytes = 0, vertexBytes = 0, indexBytes = 0, materialBytes = 0, instanceBytes = 0;
    VkAccelerationStructureKHR tlas = VK_NULL_HANDLE;
    // The host's CPU copy of what it wrote into `instances` (and placed in its TLAS): handed to the module
    // as HostSceneTables::instanceRows, which checks the CPU scene against it every frame.
    std::vector<scene::GpuInstance> instanceRows;
    std::vector<scene::GpuMaterial> materialRows;   // what the material table holds once written

private:
    struct AccelStruct {
        VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
        RawBuffer storage, scratch;
        VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
        VkAccelerationStructureBuildGeometryInfoKHR build{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
        VkAccelerationStructureBuildRangeInfoKHR range{};
    };
    bool createAccelStruct(AccelStruct& as, VkAccelerationStructureTypeKHR type, uint32_t primitiveCount);
    VkDeviceAddress address(const RawBuffer& buffer) const;

    RawVulkanHost* host_ = nullptr;
    std::vector<AccelStruct> blases_;
    AccelStruct tlas_;
    RawBuffer tlasInstances_;
    PFN_vkGetAccelerationStructureBuildSizesKHR getBuildSizes_ = nullptr;
    PFN_vkCreateAccelerationStructureKHR createAs_ = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroyAs_ = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR asAddress_ = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmdBuild_ = nullptr;
};

}  // namespace caustics::test
