#include <algorithm>
#include <cmath>
#include <iterator>
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

// The host's instance rows against the CPU scene: what the module plans with (map frusta from the
// scene's bounds, lights) must be what the hit shaders and the host's TLAS see.
Status checkInstanceRows(const HostSceneTables& t, const scene::Scene& scene) {
    if (!t.tlas && !t.instances) return okStatus();
    const std::string ref = " (docs/embedding.md, \"Host scene tables\")";
    if (t.instanceRows.size() != scene.instances.size())
        return makeError("HostSceneTables::instanceRows holds " + std::to_string(t.instanceRows.size()) +
                         " rows; the scene has " + std::to_string(scene.instances.size()) +
                         " instances: a host TLAS or instance table comes with the host's CPU copy of its rows" + ref);
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& inst = scene.instances[i];
        if (inst.mesh >= scene.meshes.size()) continue;   // refused, naming the mesh, by the scene update
        const scene::GpuInstance expected = scene::toGpuInstance(scene, inst, 0, 0);
        const scene::GpuInstance& row = t.instanceRows[i];
        const std::string who = "scene instance " + std::to_string(i) + " (mesh '" +
                                (inst.mesh < scene.meshes.size() ? scene.meshes[inst.mesh].name : std::string("?")) +
                                "') and host instance row " + std::to_string(i);
        float largest = 1.0f, worst = 0.0f;
        int worstColumn = 0, worstRow = 0;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                largest = std::max(largest, std::abs(expected.objectToWorld[c][r]));
                const float d = std::abs(row.objectToWorld[c][r] - expected.objectToWorld[c][r]);
                if (!(d <= worst)) { worst = d; worstColumn = c; worstRow = r; }
            }
        if (!(worst <= kHostInstanceTransformTolerance * largest))
            return makeError(who + " differ in objectToWorld[" + std::to_string(worstColumn) + "][" +
                             std::to_string(worstRow) + "] (" + std::to_string(expected.objectToWorld[worstColumn][worstRow]) +
                             " vs " + std::to_string(row.objectToWorld[worstColumn][worstRow]) +
                             "): move scene::Scene's instance with the host's TLAS" + ref);
        if (row.material != expected.material)
            return makeError(who + " differ in material (" + std::to_string(expected.material) + " vs " +
                             std::to_string(row.material) + ")" + ref);
        if ((row.flags & scene::kInstanceSpecular) != (expected.flags & scene::kInstanceSpecular))
            return makeError(who + " differ in the specular flag (the caustic maps plan from the scene's)" + ref);
    }
    return okStatus();
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
    constexpr rhi::ResourceState kTableStates[] = {
        rhi::ResourceState::ShaderResource, rhi::ResourceState::UnorderedAccess, rhi::ResourceState::CopyDest,
        rhi::ResourceState::CopySource, rhi::ResourceState::AccelStructBuildInput, rhi::ResourceState::Common};
    if (std::find(std::begin(kTableStates), std::end(kTableStates), t.tablesState) == std::end(kTableStates))
        return makeError(std::string("HostSceneTables::tablesState ") + rhi::resourceStateName(t.tablesState) +
                         " is not a state a table buffer can be handed over in (ShaderResource, UnorderedAccess, "
                         "CopyDest, CopySource, AccelStructBuildInput or Common; docs/embedding.md \"Hand-over states\")");
    const int geometryGiven = bool(t.positions) + bool(t.vertices) + bool(t.indices);
    if (geometryGiven != 0 && geometryGiven != 3)
        return makeError("HostSceneTables: positions, vertices and indices come as a set (the instance rows' "
                         "firstVertex and firstIndex index all three); " + std::to_string(geometryGiven) + " of 3 given");
    CAUSTICS_CHECK(checkRows(t.instances, "instances", sizeof(scene::GpuInstance), "GpuInstance", scene.instances.size(),
                             "instances"));
    CAUSTICS_CHECK(checkRows(t.materials, "materials", sizeof(scene::GpuMaterial), "GpuMaterial", scene.materials.size(),
                             "materials"));
    return checkInstanceRows(t, scene);
}

}  // namespace caustics
