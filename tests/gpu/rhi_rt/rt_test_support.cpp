#include "rt_test_support.h"

#include <gtest/gtest.h>

namespace caustics::test {

using namespace caustics::rhi;

BufferHandle makeUploadBuffer(IDevice& device, const void* data, uint64_t bytes, BufferUsage usage, std::string name) {
    auto buffer = device.createBuffer(
        BufferDesc().setByteSize(bytes).setUsage(usage).setMemory(MemoryType::Upload).setDebugName(std::move(name)));
    if (!buffer) {
        ADD_FAILURE() << buffer.message();
        return nullptr;
    }
    if (!buffer.value()->mappedData()) {
        ADD_FAILURE() << "upload buffer '" << buffer.value()->desc().debugName << "' has no host mapping";
        return nullptr;
    }
    std::memcpy(buffer.value()->mappedData(), data, bytes);
    return buffer.value();
}

BufferHandle makeOutputBuffer(IDevice& device, uint64_t bytes, std::string name) {
    auto buffer = device.createBuffer(BufferDesc()
                                          .setByteSize(bytes)
                                          .setUsage(BufferUsage::Storage | BufferUsage::CopySource | BufferUsage::CopyDest)
                                          .setDebugName(std::move(name)));
    if (!buffer) {
        ADD_FAILURE() << buffer.message();
        return nullptr;
    }
    return buffer.value();
}

void recordClear(ICommandList& cmd, const BufferHandle& buffer) {
    cmd.barrier(BufferBarrier{buffer, ResourceState::Undefined, ResourceState::CopyDest});
    cmd.fillBuffer(buffer, 0);
    cmd.barrier(BufferBarrier{buffer, ResourceState::CopyDest, ResourceState::UnorderedAccess});
}

BufferHandle makeReadbackBuffer(IDevice& device, uint64_t bytes) {
    auto readback = device.createBuffer(BufferDesc()
                                            .setByteSize(bytes)
                                            .setUsage(BufferUsage::CopyDest)
                                            .setMemory(MemoryType::Readback)
                                            .setDebugName("readback"));
    if (!readback) {
        ADD_FAILURE() << readback.message();
        return nullptr;
    }
    return readback.value();
}

void recordReadback(ICommandList& cmd, const BufferHandle& src, const BufferHandle& readback, uint64_t bytes) {
    cmd.barrier(BufferBarrier{src, ResourceState::UnorderedAccess, ResourceState::CopySource});
    cmd.barrier(BufferBarrier{readback, ResourceState::Undefined, ResourceState::CopyDest});
    cmd.copyBuffer(readback, 0, src, 0, bytes);
}

bool runAndWait(IDevice& device, const std::function<void(ICommandList&)>& record) {
    auto cmd = device.createCommandList();
    if (!cmd) {
        ADD_FAILURE() << cmd.message();
        return false;
    }
    cmd.value()->begin();
    record(*cmd.value());
    cmd.value()->end();
    auto fence = device.submit(cmd.value());
    if (!fence) {
        ADD_FAILURE() << fence.message();
        return false;
    }
    auto waited = device.waitForFence(fence.value());
    if (!waited) {
        ADD_FAILURE() << waited.message();
        return false;
    }
    return true;
}

ShaderLibraryDesc shaderLibrary(std::string_view path, std::string exportName, ShaderStage stage) {
    std::span<const uint32_t> words = test_shaders::spirv(path);
    EXPECT_FALSE(words.empty()) << "no embedded shader " << path;
    ShaderLibraryDesc lib;
    lib.code.kind = ShaderCodeKind::SPIRV;
    lib.code.bytes.resize(words.size_bytes());
    std::memcpy(lib.code.bytes.data(), words.data(), words.size_bytes());
    lib.code.debugName = std::string(path);
    lib.exports.push_back({std::move(exportName), "main", stage});
    return lib;
}

AccelStructHandle makeTriangleBlas(IDevice& device, const CpuMesh& mesh, AccelBuildFlags flags,
                                   std::vector<BufferHandle>& keepAlive) {
    BufferHandle vertices = makeUploadBuffer(device, mesh.positions, BufferUsage::AccelStructInput, "vertices");
    BufferHandle indices = makeUploadBuffer(device, mesh.indices, BufferUsage::AccelStructInput, "indices");
    keepAlive.push_back(vertices);
    keepAlive.push_back(indices);
    TriangleGeometry tri;
    tri.vertexBuffer = vertices;
    tri.vertexCount = uint32_t(mesh.positions.size() / 3);
    tri.indexBuffer = indices;
    tri.indexCount = uint32_t(mesh.indices.size());
    AccelStructDesc desc;
    desc.geometries.push_back(GeometryDesc::fromTriangles(tri));
    desc.flags = flags;
    desc.debugName = "test BLAS";
    auto blas = device.createAccelStruct(desc);
    if (!blas) {
        ADD_FAILURE() << blas.message();
        return nullptr;
    }
    return blas.value();
}

BindingLayoutHandle makeLayout(IDevice& device, uint32_t extraReadOnlyBuffers) {
    BindingLayoutDesc desc;
    desc.setVisibility(ShaderStage::AllRayTracing).add(0, BindingType::AccelStruct).add(1, BindingType::StorageBufferRW);
    for (uint32_t i = 0; i < extraReadOnlyBuffers; ++i) desc.add(2 + i, BindingType::StorageBufferRO);
    auto layout = device.createBindingLayout(desc);
    if (!layout) {
        ADD_FAILURE() << layout.message();
        return nullptr;
    }
    return layout.value();
}

StateObjectHandle makeHitInfoStateObject(IDevice& device, std::string_view rayGen, const BindingLayoutHandle& layout,
                                         uint32_t pushBytes) {
    StateObjectDesc desc;
    desc.libraries.push_back(shaderLibrary(rayGen, "rayGen", ShaderStage::RayGen));
    desc.libraries.push_back(shaderLibrary("rt/hit_info.rmiss", "miss", ShaderStage::Miss));
    desc.libraries.push_back(shaderLibrary("rt/hit_info.rchit", "closestHit", ShaderStage::ClosestHit));
    desc.hitGroups.push_back({"hitGroup", HitGroupType::Triangles, "closestHit", "", ""});
    desc.maxPayloadBytes = 8;
    desc.globalBindings.layouts = {layout};
    desc.globalBindings.pushConstantBytes = pushBytes;
    desc.debugName = "hit-info state object";
    auto so = device.createStateObject(desc);
    if (!so) {
        ADD_FAILURE() << so.message();
        return nullptr;
    }
    return so.value();
}

ShaderTableHandle makeHitInfoTable(IDevice& device, const StateObjectHandle& stateObject) {
    ShaderTableDesc desc;
    desc.stateObject = stateObject;
    desc.setRayGen("rayGen").addMiss("miss").addHitGroup("hitGroup");
    auto table = device.createShaderTable(desc);
    if (!table) {
        ADD_FAILURE() << table.message();
        return nullptr;
    }
    return table.value();
}

void RayList::add(const Vec3& o, const Vec3& d, float tMin, float tMax) {
    data.insert(data.end(), {float(o[0]), float(o[1]), float(o[2]), tMin, float(d[0]), float(d[1]), float(d[2]), tMax});
}

std::vector<std::array<uint32_t, 2>> traceRayList(IDevice& device, const AccelStructHandle& tlas, const RayList& rays) {
    BindingLayoutHandle layout = makeLayout(device, 1);
    StateObjectHandle so = makeHitInfoStateObject(device, "rt/ray_list.rgen", layout, 0);
    if (!so) return {};
    ShaderTableHandle table = makeHitInfoTable(device, so);
    if (!table) return {};
    BufferHandle rayBuffer = makeUploadBuffer(device, rays.data, BufferUsage::Storage, "rays");
    const uint64_t outBytes = uint64_t(rays.count()) * 8;
    BufferHandle out = makeOutputBuffer(device, outBytes, "hits");
    auto set = device.createBindingSet(BindingSetDesc()
                                           .add(BindingSetItem::accelStructItem(0, tlas))
                                           .add(BindingSetItem::storageBuffer(1, out))
                                           .add(BindingSetItem::storageBuffer(2, rayBuffer, false)),
                                       layout);
    if (!set) {
        ADD_FAILURE() << set.message();
        return {};
    }
    BufferHandle readback = makeReadbackBuffer(device, outBytes);
    bool ran = runAndWait(device, [&](ICommandList& cmd) {
        recordClear(cmd, out);
        cmd.setRayTracingState(so, table);
        cmd.setBindingSet(0, set.value());
        cmd.dispatchRays(rays.count());
        recordReadback(cmd, out, readback, outBytes);
    });
    if (!ran || !readback) return {};
    return readBack<std::array<uint32_t, 2>>(device, readback, rays.count());
}

}  // namespace caustics::test
