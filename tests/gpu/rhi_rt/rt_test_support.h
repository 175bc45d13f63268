#pragma once
// Helpers shared by the ray-tracing GPU tests: buffers filled from host data, readbacks, shader
// libraries from the embedded test shaders and uploading a CpuMesh into a bottom level.
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cpu_ray_reference.h"
#include "gpu_test.h"   // caustics::test_shaders::spirv: tests/gpu/shaders/** embedded by gpu/support
#include "caustics/rhi/rhi.h"

namespace caustics::test {

// Host-visible buffer holding `bytes` of `data` (written through the mapping; a submission makes host
// writes visible to the device, Vulkan spec 7.9 "Host Write Ordering Guarantees").
rhi::BufferHandle makeUploadBuffer(rhi::IDevice& device, const void* data, uint64_t bytes, rhi::BufferUsage usage,
                                   std::string name);
template <typename T>
rhi::BufferHandle makeUploadBuffer(rhi::IDevice& device, const std::vector<T>& v, rhi::BufferUsage usage,
                                   std::string name) {
    return makeUploadBuffer(device, v.data(), v.size() * sizeof(T), usage, std::move(name));
}

// Device-local storage buffer the shaders write (Undefined state until recordClear).
rhi::BufferHandle makeOutputBuffer(rhi::IDevice& device, uint64_t bytes, std::string name);
// Zero-fills a buffer made by makeOutputBuffer and leaves it in UnorderedAccess.
void recordClear(rhi::ICommandList& cmd, const rhi::BufferHandle& buffer);

// Objects used by a recording must outlive its submission: tests create them before recording.
// A host-readable buffer and the recording of a copy of `src` (in UnorderedAccess) into it.
rhi::BufferHandle makeReadbackBuffer(rhi::IDevice& device, uint64_t bytes);
void recordReadback(rhi::ICommandList& cmd, const rhi::BufferHandle& src, const rhi::BufferHandle& readback,
                    uint64_t bytes);
template <typename T>
std::vector<T> readBack(rhi::IDevice& device, const rhi::BufferHandle& readback, size_t count) {
    std::vector<T> out(count);
    if (!device.readBuffer(readback, out.data(), count * sizeof(T))) out.clear();
    return out;
}

// Records into a fresh command list, submits it and waits; returns false (with a gtest failure) on error.
bool runAndWait(rhi::IDevice& device, const std::function<void(rhi::ICommandList&)>& record);

// One library per GLSL file: SPIR-V from the embedded test shaders, entry point "main".
rhi::ShaderLibraryDesc shaderLibrary(std::string_view path, std::string exportName, rhi::ShaderStage stage);

// A bottom level over `mesh` (vertex and index buffers in upload memory, kept alive by `keepAlive`).
rhi::AccelStructHandle makeTriangleBlas(rhi::IDevice& device, const CpuMesh& mesh, rhi::AccelBuildFlags flags,
                                        std::vector<rhi::BufferHandle>& keepAlive);

// Binding layout of hit_info.glsl (+ ray list / extra read-only buffers at slots 2.. when asked).
rhi::BindingLayoutHandle makeLayout(rhi::IDevice& device, uint32_t extraReadOnlyBuffers);

// The state object raygen `rayGen` + hit_info.rmiss + hit_info.rchit, push constants of `pushBytes`.
rhi::StateObjectHandle makeHitInfoStateObject(rhi::IDevice& device, std::string_view rayGen,
                                              const rhi::BindingLayoutHandle& layout, uint32_t pushBytes);
rhi::ShaderTableHandle makeHitInfoTable(rhi::IDevice& device, const rhi::StateObjectHandle& stateObject);

// Packs rays for ray_list.rgen: (origin, tMin), (direction, tMax).
struct RayList {
    std::vector<float> data;
    void add(const Vec3& o, const Vec3& d, float tMin, float tMax);
    uint32_t count() const { return uint32_t(data.size() / 8); }
    Vec3 origin(uint32_t i) const { return {data[8 * i], data[8 * i + 1], data[8 * i + 2]}; }
    Vec3 direction(uint32_t i) const { return {data[8 * i + 4], data[8 * i + 5], data[8 * i + 6]}; }
};

// Traces `rays` against `tlas` with ray_list.rgen and returns one (instance id, primitive id) per ray.
std::vector<std::array<uint32_t, 2>> traceRayList(rhi::IDevice& device, const rhi::AccelStructHandle& tlas,
                                                  const RayList& rays);

}  // namespace caustics::test
