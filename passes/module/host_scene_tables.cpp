#include <string>

#include "caustics/host_scene.h"
#include "caustics/scene/gpu_types.h"

namespace caustics {
namespace {

std::string tableName(const char* field, const rhi::BufferHandle& b) {
    const std::string& name = b->desc().debugName;
    return std::string("HostSceneTables::") + field + (name.empty() ? "" : " ('" + name + "')");
}

// A table of `rowBytes`-byte rows must hold at least `needed` of them.
Status checkRows(const rhi::BufferHandle& b, const char* field, uint64_t rowBytes, const char* rowType, size_t needed,
                 const char* what) {
    if (!b) return okStatus();
    const uint64_t rows = b->desc().byteSize / rowBytes;
    if (rows >= needed) return okStatus();
    return makeError(tableName(field, b) + " holds " + std::to_string(rows) + " " + rowType + " rows (" +
                     std::to_string(b->desc().byteSize) + " bytes); the scene has " + std::to_string(needed) + " " +
                     what + " (docs/embedding.md, \"Host scene tables\")");
}

}  // namespace

Status checkHostSceneTables(const HostSceneTables& t, const scene::Scene& scene) {
    if (t.tlas && !t.tlas->desc().isTopLevel)
        return makeError("HostSceneTables::tlas '" + t.tlas->desc().debugName + "' is not a top-level acceleration structure");
    const std::pair<const rhi::BufferHandle*, const char*> buffers[] = {
        {&t.positions, "positions"}, {&t.vertices, "vertices"}, {&t.indices, "indices"},
        {&t.materials, "materials"}, {&t.instances, "instances"}};
    for (const auto& [buffer, field] : buffers)
        if (*buffer && !rhi::hasAny((*buffer)->desc().usage, rhi::BufferUsage::Storage))
            return makeError(tableName(field, *buffer) + " lacks Storage usage: the hit shaders read it as a storage buffer");
    const int geometryGiven = bool(t.positions) + bool(t.vertices) + bool(t.indices);
    if (geometryGiven != 0 && geometryGiven != 3)
        return makeError("HostSceneTables: positions, vertices and indices come as a set (the instance rows' "
                         "firstVertex and firstIndex index all three); " + std::to_string(geometryGiven) + " of 3 given");
    CAUSTICS_CHECK(checkRows(t.instances, "instances", sizeof(scene::GpuInstance), "GpuInstance", scene.instances.size(),
                             "instances"));
    return checkRows(t.materials, "materials", sizeof(scene::GpuMaterial), "GpuMaterial", scene.materials.size(),
                     "materials");
}

}  // namespace caustics
