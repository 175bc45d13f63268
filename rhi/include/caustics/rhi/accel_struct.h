#pragma once
// Acceleration structures in the DXR shape: bottom levels from indexed triangles or AABBs
// (procedural), top levels from instances with a 3x4 transform, id, mask, hit-group offset and flags.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/rhi/resources.h"

namespace caustics::rhi {

enum class GeometryFlags : uint32_t {
    None = 0,
    Opaque = 1u << 0,
    // Any-hit runs exactly once per primitive; needed by any-hit shaders that accumulate (docs/caustics.md, "Second type").
    NoDuplicateAnyHit = 1u << 1,
};
constexpr GeometryFlags operator|(GeometryFlags a, GeometryFlags b) { return GeometryFlags(uint32_t(a) | uint32_t(b)); }
constexpr bool hasAny(GeometryFlags set, GeometryFlags bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

struct TriangleGeometry {
    BufferHandle vertexBuffer;    // RGB32_FLOAT positions
    uint64_t vertexOffset = 0;
    uint32_t vertexCount = 0;
    uint32_t vertexStride = 12;
    BufferHandle indexBuffer;     // uint32 indices; null = non-indexed
    uint64_t indexOffset = 0;
    uint32_t indexCount = 0;
};

// AABBs as 6 floats (minX, minY, minZ, maxX, maxY, maxZ), D3D12_RAYTRACING_AABB layout.
struct AabbGeometry {
    BufferHandle buffer;
    uint64_t offset = 0;
    uint32_t count = 0;
    uint32_t stride = 24;
};

struct GeometryDesc {
    enum class Type : uint8_t { Triangles, Aabbs } type = Type::Triangles;
    TriangleGeometry triangles;
    AabbGeometry aabbs;
    GeometryFlags flags = GeometryFlags::Opaque;

    static GeometryDesc fromTriangles(TriangleGeometry t, GeometryFlags f = GeometryFlags::Opaque) {
        GeometryDesc g; g.type = Type::Triangles; g.triangles = std::move(t); g.flags = f; return g;
    }
    static GeometryDesc fromAabbs(AabbGeometry a, GeometryFlags f = GeometryFlags::None) {
        GeometryDesc g; g.type = Type::Aabbs; g.aabbs = std::move(a); g.flags = f; return g;
    }
};

enum class AccelBuildFlags : uint32_t {
    None = 0,
    AllowUpdate = 1u << 0,
    AllowCompaction = 1u << 1,
    PreferFastTrace = 1u << 2,
    PreferFastBuild = 1u << 3,
};
constexpr AccelBuildFlags operator|(AccelBuildFlags a, AccelBuildFlags b) { return AccelBuildFlags(uint32_t(a) | uint32_t(b)); }
constexpr bool hasAny(AccelBuildFlags set, AccelBuildFlags bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

struct AccelStructDesc {
    bool isTopLevel = false;
    std::vector<GeometryDesc> geometries;  // bottom level: sizes are taken from these
    uint32_t maxInstances = 0;             // top level: capacity
    AccelBuildFlags flags = AccelBuildFlags::PreferFastTrace;
    std::string debugName;
};

class IAccelStruct {
public:
    virtual ~IAccelStruct() = default;
    virtual const AccelStructDesc& desc() const = 0;
    virtual uint64_t deviceAddress() const = 0;   // what an instance refers to
    virtual uint64_t storageBytes() const = 0;    // size of the backing buffer
    // VkAccelerationStructureKHR / VkBuffer of its storage / ID3D12Resource of its storage.
    virtual NativeObject getNativeObject(NativeObjectType) const { return {}; }
};
using AccelStructHandle = std::shared_ptr<IAccelStruct>;

enum class InstanceFlags : uint8_t {
    None = 0,
    TriangleCullDisable = 1u << 0,
    TriangleFrontCounterClockwise = 1u << 1,
    ForceOpaque = 1u << 2,
    ForceNonOpaque = 1u << 3,
};
constexpr InstanceFlags operator|(InstanceFlags a, InstanceFlags b) { return InstanceFlags(uint8_t(a) | uint8_t(b)); }

// Exactly D3D12_RAYTRACING_INSTANCE_DESC == VkAccelerationStructureInstanceKHR (64 bytes), so a
// shader may also write instances into a buffer for buildTopLevelFromBuffer.
struct InstanceDesc {
    float transform[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};  // row-major 3x4
    uint32_t instanceId : 24 = 0;
    uint32_t instanceMask : 8 = 0xFF;
    uint32_t hitGroupOffset : 24 = 0;
    uint32_t flags : 8 = 0;   // InstanceFlags
    uint64_t blasAddress = 0; // IAccelStruct::deviceAddress() of the bottom level
};
static_assert(sizeof(InstanceDesc) == 64, "instance layout must match D3D12 and Vulkan");

}  // namespace caustics::rhi
