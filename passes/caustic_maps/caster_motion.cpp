// instanceMotion (caustic_internal.h; docs/caustics.md "Moving casters", "Moving objects").
#include <cmath>

#include "caustic_maps/caustic_internal.h"
#include "common/caster_motion.h"

namespace caustics {

InstanceMotion instanceMotion(CasterMotionState& state, const scene::Scene& scene, uint32_t frameIndex) {
    if (state.frame != frameIndex) {
        state.previous = std::move(state.current);
        state.current.clear();
        for (const scene::Instance& i : scene.instances) state.current.push_back(i.transform);
        state.frame = frameIndex;
    }
    const size_t n = state.current.size();
    if (state.previous.size() != n || n != scene.instances.size()) return {};
    InstanceMotion motion;
    motion.rows.resize(shader::kCasterMotionRowsPerInstance * n);
    bool moved = false;
    for (size_t i = 0; i < n; ++i) {
        // The transform is the same product in both frames when nothing moved: compare, then build.
        const glm::mat4 toPrevious = state.previous[i] * glm::inverse(state.current[i]);
        const glm::mat4 t = glm::transpose(toPrevious);   // rows of the 3x4 as columns of the transpose
        for (uint32_t r = 0; r < shader::kCasterMotionRowsPerInstance; ++r) motion.rows[shader::kCasterMotionRowsPerInstance * i + r] = t[int(r)];
        if (state.previous[i] == state.current[i]) continue;
        moved = true;
        const scene::Mesh& mesh = scene.meshes[scene.instances[i].mesh];
        if (mesh.material < scene.materials.size() && scene.materials[mesh.material].isSpecular()) motion.casterMoved = true;
    }
    if (!moved) return {};
    return motion;
}

Status CausticResources::Impl::ensureCasterMotion(uint32_t slot, uint64_t rowBytes, uint64_t wordBytes) {
    if (casterMotionRowBuffers.size() < frameSets.size()) casterMotionRowBuffers.resize(frameSets.size());
    if (casterMotionWordBuffers.size() < frameSets.size()) casterMotionWordBuffers.resize(frameSets.size());
    // A slot's buffers are replaced only when the slot comes round again: its last frame has finished.
    auto ensure = [&](rhi::BufferHandle& buffer, uint64_t bytes, const char* name) -> Status {
        if (buffer && buffer->desc().byteSize >= bytes) return okStatus();
        CAUSTICS_TRY(buffer, device->createBuffer(rhi::BufferDesc().setByteSize(std::max<uint64_t>(bytes, 16))
                                                      .setUsage(rhi::BufferUsage::Storage | rhi::BufferUsage::CopyDest)
                                                      .setDebugName(name)));
        return okStatus();
    };
    CAUSTICS_CHECK(ensure(casterMotionRowBuffers[slot], rowBytes, "caustics.instanceMotion"));
    return ensure(casterMotionWordBuffers[slot], wordBytes, "caustics.casterMotion");
}

}  // namespace caustics
