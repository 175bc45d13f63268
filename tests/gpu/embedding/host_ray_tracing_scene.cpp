#include "host_ray_tracing_scene.h"

#include <algorithm>
#include <cstring>

#include "caustics/scene/gpu_scene.h"

namespace caustics::test {
namespace {

template <typename T>
RawBuffer uploadTable(RawVulkanHost& host, const std::vector<T>& rows, size_t count, VkDeviceSize& bytes) {
    bytes = std::max<VkDeviceSize>(count * sizeof(T), 16);
    RawBuffer b = host.createHostBuffer(bytes, HostRayTracingScene::kTableUsage);
    if (b.mapped && count > 0) std::memcpy(b.mapped, rows.data(), count * sizeof(T));
    return b;
}

}  // namespace

VkDeviceAddress HostRayTracingScene::address(const RawBuffer& buffer) const {
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = buffer.buffer;
    return vkGetBufferDeviceAddress(host_->device, &info);
}

bool HostRayTracingScene::create(RawVulkanHost& host, const scene::Scene& scene, size_t instanceRows,
                                 float diffuseAlbedoScale, bool materialsOnTheGpu) {
    host_ = &host;
    auto load = [&](auto& fn, const char* name) {
        fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(host.device, name));
        return fn != nullptr;
    };
    if (!load(getBuildSizes_, "vkGetAccelerationStructureBuildSizesKHR") ||
        !load(createAs_, "vkCreateAccelerationStructureKHR") || !load(destroyAs_, "vkDestroyAccelerationStructureKHR") ||
        !load(asAddress_, "vkGetAccelerationStructureDeviceAddressKHR") ||
        !load(cmdBuild_, "vkCmdBuildAccelerationStructuresKHR"))
        return false;

    // The documented layouts (caustics/scene/gpu_types.h); packScene writes exactly those rows.
    scene::PackedScene packed = scene::packScene(scene);
    for (scene::GpuMaterial& m : packed.materials)
        if (!(m.flags & scene::kMaterialSpecular)) m.baseColor *= diffuseAlbedoScale;
    positions = uploadTable(host, packed.positions, packed.positions.size(), positionBytes);
    vertices = uploadTable(host, packed.vertices, packed.vertices.size(), vertexBytes);
    indices = uploadTable(host, packed.indices, packed.indices.size(), indexBytes);
    materialRows = packed.materials;
    const std::vector<scene::GpuMaterial> zeros(packed.materials.size(), scene::GpuMaterial{});
    materials = uploadTable(host, materialsOnTheGpu ? zeros : packed.materials, packed.materials.size(), materialBytes);
    instances = uploadTable(host, packed.instances, std::min(instanceRows, packed.instances.size()), instanceBytes);
    this->instanceRows.assign(packed.instances.begin(), packed.instances.begin() + std::min(instanceRows, packed.instances.size()));
    if (!positions.mapped || !vertices.mapped || !indices.mapped || !materials.mapped || !instances.mapped) return false;

    blases_.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::GpuMeshRange& r = packed.meshRanges[m];
        AccelStruct& blas = blases_[m];
        blas.geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        // Opaque triangles; specular ones once per primitive in any-hit (docs/embedding.md table).
        const scene::Material& material = scene.materials[scene.meshes[m].material];
        blas.geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR |
                              (material.isSpecular() ? VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR : 0);
        auto& tri = blas.geometry.geometry.triangles;
        tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
        tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
        tri.vertexData.deviceAddress = address(positions) + VkDeviceAddress(r.firstVertex) * sizeof(glm::vec3);
        tri.vertexStride = sizeof(glm::vec3);
        tri.maxVertex = r.vertexCount - 1;
        tri.indexType = VK_INDEX_TYPE_UINT32;
        tri.indexData.deviceAddress = address(indices) + VkDeviceAddress(r.firstIndex) * sizeof(uint32_t);
        if (!createAccelStruct(blas, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, r.indexCount / 3)) return false;
    }

    // TLAS instance i: custom index i, mask by specularity, hit group 0 (docs/embedding.md table).
    std::vector<VkAccelerationStructureInstanceKHR> rows(scene.instances.size());
    for (uint32_t i = 0; i < rows.size(); ++i) {
        const rhi::InstanceDesc d = scene::makeInstanceDesc(scene, i);
        std::memcpy(&rows[i].transform, d.transform, sizeof(rows[i].transform));
        rows[i].instanceCustomIndex = i;
        rows[i].mask = d.instanceMask;
        rows[i].instanceShaderBindingTableRecordOffset = 0;
        VkAccelerationStructureDeviceAddressInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
        info.accelerationStructure = blases_[scene.instances[i].mesh].handle;
        rows[i].accelerationStructureReference = asAddress_(host.device, &info);
    }
    VkDeviceSize instanceBufferBytes = 0;
    tlasInstances_ = uploadTable(host, rows, rows.size(), instanceBufferBytes);
    tlas_.geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    tlas_.geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    tlas_.geometry.geometry.instances.data.deviceAddress = address(tlasInstances_);
    if (!tlasInstances_.mapped || !createAccelStruct(tlas_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, uint32_t(rows.size())))
        return false;
    tlas = tlas_.handle;
    return true;
}

bool HostRayTracingScene::createAccelStruct(AccelStruct& as, VkAccelerationStructureTypeKHR type, uint32_t primitiveCount) {
    as.build.type = type;
    as.build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    as.build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    as.build.geometryCount = 1;
    as.build.pGeometries = &as.geometry;
    as.range.primitiveCount = primitiveCount;
    VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    getBuildSizes_(host_->device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &as.build, &primitiveCount, &sizes);
    as.storage = host_->createHostBuffer(sizes.accelerationStructureSize,
                                         VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                             VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
    as.scratch = host_->createHostBuffer(std::max<VkDeviceSize>(sizes.buildScratchSize, 16),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
    if (!as.storage.buffer || !as.scratch.buffer) return false;
    VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = as.storage.buffer;
    info.size = sizes.accelerationStructureSize;
    info.type = type;
    if (createAs_(host_->device, &info, nullptr, &as.handle) != VK_SUCCESS) return false;
    as.build.dstAccelerationStructure = as.handle;
    as.build.scratchData.deviceAddress = address(as.scratch);
    return true;
}

void HostRayTracingScene::recordBuilds() {
    constexpr VkPipelineStageFlags2 kBuild = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;
    for (AccelStruct& blas : blases_) {
        blas.build.pGeometries = &blas.geometry;   // the vector may have moved since create()
        const VkAccelerationStructureBuildRangeInfoKHR* range = &blas.range;
        cmdBuild_(host_->commandBuffer, 1, &blas.build, &range);
    }
    host_->memoryBarrier(kBuild, VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR, kBuild,
                         VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    tlas_.build.pGeometries = &tlas_.geometry;
    const VkAccelerationStructureBuildRangeInfoKHR* range = &tlas_.range;
    cmdBuild_(host_->commandBuffer, 1, &tlas_.build, &range);
    host_->memoryBarrier(kBuild, VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                         VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
}

void HostRayTracingScene::recordMaterialUpload() {
    // vkCmdUpdateBuffer: at most 65536 bytes, a multiple of 4 (the rows are 96 bytes each).
    vkCmdUpdateBuffer(host_->commandBuffer, materials.buffer, 0, materialRows.size() * sizeof(scene::GpuMaterial),
                      materialRows.data());
}

void HostRayTracingScene::destroy() {
    if (!host_) return;
    auto destroyAccelStruct = [&](AccelStruct& as) {
        if (as.handle) destroyAs_(host_->device, as.handle, nullptr);
        host_->destroy(as.storage);
        host_->destroy(as.scratch);
    };
    destroyAccelStruct(tlas_);
    for (AccelStruct& blas : blases_) destroyAccelStruct(blas);
    for (RawBuffer* b : {&positions, &vertices, &indices, &materials, &instances, &tlasInstances_}) host_->destroy(*b);
    blases_.clear();
    host_ = nullptr;
}

}  // namespace caustics::test
