#include <gtest/gtest.h>

#include "accel_struct_inputs.h"

namespace caustics::rhi::d3d12 {
namespace {

class FakeBuffer final : public IBuffer {
public:
    explicit FakeBuffer(uint64_t address) : address_(address) {}
    const BufferDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return address_; }
    void* mappedData() override { return nullptr; }

private:
    BufferDesc desc_;
    uint64_t address_;
};

TEST(D3D12AccelStruct, NoDuplicateAnyHitMapsToTheDxrGeometryFlag) {
    EXPECT_EQ(toD3D12GeometryFlags(GeometryFlags::NoDuplicateAnyHit),
              D3D12_RAYTRACING_GEOMETRY_FLAG_NO_DUPLICATE_ANYHIT_INVOCATION);
    EXPECT_EQ(toD3D12GeometryFlags(GeometryFlags::Opaque), D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE);
    EXPECT_EQ(toD3D12GeometryFlags(GeometryFlags::None), D3D12_RAYTRACING_GEOMETRY_FLAG_NONE);
}

TEST(D3D12AccelStruct, UpdateAddsPerformUpdateToTheBuildFlags) {
    auto flags = toD3D12BuildFlags(AccelBuildFlags::AllowUpdate | AccelBuildFlags::PreferFastTrace, true);
    EXPECT_TRUE(flags & D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PERFORM_UPDATE);
    EXPECT_TRUE(flags & D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_ALLOW_UPDATE);
    EXPECT_TRUE(flags & D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_TRACE);
    EXPECT_FALSE(toD3D12BuildFlags(AccelBuildFlags::AllowCompaction, false) &
                 D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PERFORM_UPDATE);
}

TEST(D3D12AccelStruct, IndexedTrianglesUseBufferAddressesPlusOffsets) {
    TriangleGeometry t;
    t.vertexBuffer = std::make_shared<FakeBuffer>(0x1000);
    t.vertexOffset = 0x40;
    t.vertexCount = 3;
    t.indexBuffer = std::make_shared<FakeBuffer>(0x2000);
    t.indexOffset = 12;
    t.indexCount = 3;
    D3D12_RAYTRACING_GEOMETRY_DESC d = toD3D12Geometry(GeometryDesc::fromTriangles(t));
    EXPECT_EQ(d.Type, D3D12_RAYTRACING_GEOMETRY_TYPE_TRIANGLES);
    EXPECT_EQ(d.Triangles.VertexBuffer.StartAddress, 0x1040u);
    EXPECT_EQ(d.Triangles.VertexBuffer.StrideInBytes, 12u);
    EXPECT_EQ(d.Triangles.VertexFormat, DXGI_FORMAT_R32G32B32_FLOAT);
    EXPECT_EQ(d.Triangles.IndexBuffer, 0x200Cu);
    EXPECT_EQ(d.Triangles.IndexFormat, DXGI_FORMAT_R32_UINT);
    EXPECT_EQ(d.Flags, D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE);
}

TEST(D3D12AccelStruct, UnitSphereAabbIsAProceduralGeometry) {
    AabbGeometry a;
    a.buffer = std::make_shared<FakeBuffer>(0x3000);
    a.count = 1;
    AccelStructDesc desc;
    desc.geometries.push_back(GeometryDesc::fromAabbs(a, GeometryFlags::NoDuplicateAnyHit));
    BottomLevelInputs in;
    makeBottomLevelInputs(desc, false, in);
    ASSERT_EQ(in.inputs.NumDescs, 1u);
    EXPECT_EQ(in.inputs.Type, D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL);
    EXPECT_EQ(in.inputs.pGeometryDescs, in.geometries.data());
    EXPECT_EQ(in.geometries[0].Type, D3D12_RAYTRACING_GEOMETRY_TYPE_PROCEDURAL_PRIMITIVE_AABBS);
    EXPECT_EQ(in.geometries[0].AABBs.AABBs.StartAddress, 0x3000u);
    EXPECT_EQ(in.geometries[0].AABBs.AABBs.StrideInBytes, sizeof(D3D12_RAYTRACING_AABB));
    EXPECT_EQ(in.geometries[0].Flags, D3D12_RAYTRACING_GEOMETRY_FLAG_NO_DUPLICATE_ANYHIT_INVOCATION);
}

TEST(D3D12AccelStruct, TopLevelInputsReadInstancesFromTheGivenAddress) {
    AccelStructDesc desc;
    desc.isTopLevel = true;
    auto in = makeTopLevelInputs(desc, 0x8000, 7, false);
    EXPECT_EQ(in.Type, D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL);
    EXPECT_EQ(in.InstanceDescs, 0x8000u);
    EXPECT_EQ(in.NumDescs, 7u);
}

TEST(D3D12AccelStruct, RhiInstanceMatchesD3D12InstanceLayout) {
    EXPECT_EQ(sizeof(InstanceDesc), sizeof(D3D12_RAYTRACING_INSTANCE_DESC));
    EXPECT_EQ(offsetof(InstanceDesc, blasAddress), offsetof(D3D12_RAYTRACING_INSTANCE_DESC, AccelerationStructure));
}

}  // namespace
}  // namespace caustics::rhi::d3d12
