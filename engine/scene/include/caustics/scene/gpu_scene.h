#pragma once
// The scene on the GPU through the public RHI only: one positions buffer (float3, BLAS input), one
// vertex-attribute buffer (GpuVertex), one index buffer (uint32, relative to each mesh's first
// vertex), the material and instance tables (gpu_types.h), the textures (RGBA8_SRGB, for a
// bindless array; never empty: a 1x1 white one when the scene has none), one BLAS per mesh and a
// TLAS with instanceId = instance index and mask kMaskDiffuse / kMaskSpecular.
#include <cstdint>
#include <vector>

#include "caustics/rhi/device.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/gpu_types.h"
#include "caustics/scene/scene.h"

namespace caustics::scene {

// TLAS instance masks: passes trace only specular objects with kMaskSpecular (e.g. caustic maps).
constexpr uint8_t kMaskDiffuse = 0x1;
constexpr uint8_t kMaskSpecular = 0x2;

struct GpuMeshRange {
    uint32_t firstVertex = 0, vertexCount = 0;
    uint32_t firstIndex = 0, indexCount = 0;
};

struct GpuSceneDesc {
    // The meshes' triangles are uploaded in their stored order; loaders and the built-in scenes
    // already Morton-sort them. Set this to sort copies here (for scenes built elsewhere).
    bool sortTriangles = false;
    bool buildAccelStructs = true;
    // False: positions, vertices and indices are not uploaded (the three handles stay null). For a host
    // that hands the module its own TLAS and geometry tables (FrameInputs::hostScene; docs/embedding.md
    // "Host scene tables"): every pass then reads the host's. Needs buildAccelStructs = false.
    bool uploadGeometry = true;
};

class GpuScene {
public:
    // Uploads everything and builds the acceleration structures; waits for the GPU.
    static Result<GpuScene> create(rhi::IDevice& device, const Scene& scene, const GpuSceneDesc& desc = {});

    rhi::BufferHandle positions;    // float3 per vertex, stride 12
    rhi::BufferHandle vertices;     // GpuVertex per vertex
    rhi::BufferHandle indices;      // uint32
    rhi::BufferHandle materials;    // GpuMaterial[]
    rhi::BufferHandle instances;    // GpuInstance[]
    std::vector<rhi::TextureHandle> textures;   // RGBA8_SRGB, index = Material::baseColorTexture
    std::vector<rhi::AccelStructHandle> blases; // one per mesh
    rhi::AccelStructHandle tlas;
    std::vector<GpuMeshRange> meshRanges;
    std::vector<rhi::InstanceDesc> tlasInstances;   // as built (blasAddress filled)
    uint32_t instanceCount = 0;
    uint32_t materialCount = 0;
};

// The CPU half of create(): the packed arrays and tables, testable without a device.
struct PackedScene {
    std::vector<glm::vec3> positions;
    std::vector<GpuVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<GpuMaterial> materials;
    std::vector<GpuInstance> instances;
    std::vector<GpuMeshRange> meshRanges;
};
PackedScene packScene(const Scene& scene);
// Row-major 3x4 object->world transform, mask and id for TLAS instance `index` (blasAddress = 0).
rhi::InstanceDesc makeInstanceDesc(const Scene& scene, uint32_t index);

}  // namespace caustics::scene
