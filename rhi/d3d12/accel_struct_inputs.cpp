#include "accel_struct_inputs.h"

namespace caustics::rhi::d3d12 {

D3D12_RAYTRACING_GEOMETRY_FLAGS toD3D12GeometryFlags(GeometryFlags flags) {
    uint32_t out = D3D12_RAYTRACING_GEOMETRY_FLAG_NONE;
    if (hasAny(flags, GeometryFlags::Opaque)) out |= D3D12_RAYTRACING_GEOMETRY_FLAG_OPAQUE;
    // Accumulating any-hit shaders (backward caustic gathering) must run once per primitive.
    if (hasAny(flags, GeometryFlags::NoDuplicateAnyHit))
        out |= D3D12_RAYTRACING_GEOMETRY_FLAG_NO_DUPLICATE_ANYHIT_INVOCATION;
    return D3D12_RAYTRACING_GEOMETRY_FLAGS(out);
}

D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAGS toD3D12BuildFlags(AccelBuildFlags flags, bool update) {
    uint32_t out = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_NONE;
    if (hasAny(flags, AccelBuildFlags::AllowUpdate)) out |= D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_ALLOW_UPDATE;
    if (hasAny(flags, AccelBuildFlags::AllowCompaction))
        out |= D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_ALLOW_COMPACTION;
    if (hasAny(flags, AccelBuildFlags::PreferFastTrace))
        out |= D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_TRACE;
    if (hasAny(flags, AccelBuildFlags::PreferFastBuild))
        out |= D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PREFER_FAST_BUILD;
    if (update) out |= D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAG_PERFORM_UPDATE;
    return D3D12_RAYTRACING_ACCELERATION_STRUCTURE_BUILD_FLAGS(out);
}

D3D12_RAYTRACING_GEOMETRY_DESC toD3D12Geometry(const GeometryDesc& g) {
    D3D12_RAYTRACING_GEOMETRY_DESC d{};
    d.Flags = toD3D12GeometryFlags(g.flags);
    if (g.type == GeometryDesc::Type::Aabbs) {
        d.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_PROCEDURAL_PRIMITIVE_AABBS;
        d.AABBs.AABBCount = g.aabbs.count;
        d.AABBs.AABBs.StartAddress = (g.aabbs.buffer ? g.aabbs.buffer->deviceAddress() : 0) + g.aabbs.offset;
        d.AABBs.AABBs.StrideInBytes = g.aabbs.stride;
        return d;
    }
    const TriangleGeometry& t = g.triangles;
    d.Type = D3D12_RAYTRACING_GEOMETRY_TYPE_TRIANGLES;
    d.Triangles.VertexFormat = DXGI_FORMAT_R32G32B32_FLOAT;
    d.Triangles.VertexCount = t.vertexCount;
    d.Triangles.VertexBuffer.StartAddress = (t.vertexBuffer ? t.vertexBuffer->deviceAddress() : 0) + t.vertexOffset;
    d.Triangles.VertexBuffer.StrideInBytes = t.vertexStride;
    if (t.indexBuffer) {
        d.Triangles.IndexFormat = DXGI_FORMAT_R32_UINT;
        d.Triangles.IndexCount = t.indexCount;
        d.Triangles.IndexBuffer = t.indexBuffer->deviceAddress() + t.indexOffset;
    } else {
        d.Triangles.IndexFormat = DXGI_FORMAT_UNKNOWN;
    }
    return d;
}

void makeBottomLevelInputs(const AccelStructDesc& desc, bool update, BottomLevelInputs& out) {
    out.geometries.clear();
    for (const GeometryDesc& g : desc.geometries) out.geometries.push_back(toD3D12Geometry(g));
    out.inputs = {};
    out.inputs.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL;
    out.inputs.Flags = toD3D12BuildFlags(desc.flags, update);
    out.inputs.NumDescs = UINT(out.geometries.size());
    out.inputs.DescsLayout = D3D12_ELEMENTS_LAYOUT_ARRAY;
    out.inputs.pGeometryDescs = out.geometries.data();
}

D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS makeTopLevelInputs(const AccelStructDesc& desc,
                                                                        uint64_t instanceAddress,
                                                                        uint32_t instanceCount, bool update) {
    D3D12_BUILD_RAYTRACING_ACCELERATION_STRUCTURE_INPUTS in{};
    in.Type = D3D12_RAYTRACING_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL;
    in.Flags = toD3D12BuildFlags(desc.flags, update);
    in.NumDescs = instanceCount;
    in.DescsLayout = D3D12_ELEMENTS_LAYOUT_ARRAY;
    in.InstanceDescs = instanceAddress;
    return in;
}

}  // namespace caustics::rhi::d3d12
