#pragma once
// The plain-Vulkan host engine of host_engine_test.cpp (issue 9, "Tests", first bullet): RawVulkanHost's
// own instance, device, queue, command buffer and fence; its own compute G-buffer (host_gbuffer_compute.*),
// output image and, optionally, its own BLASes, TLAS and scene tables (host_ray_tracing_scene.*). It wraps
// all of it (docs/embedding.md), runs the module in caustics-only mode inside its own command buffer and
// submits on its own queue.
#include <cstdint>
#include <string>
#include <vector>

#include "caustics/caustics_module.h"
#include "module_frames.h"

namespace caustics::test {

inline constexpr uint32_t kHostImageSize = 96;

// causticsOnly for the host (it composites); the standalone module runs its own G-buffer pass and
// composite, and its `caustics` output is the same image.
CausticsSettings hostEngineSettings(uint32_t seed, bool causticsOnly);

// Object ids and linear depths of a G-buffer, row 0 = top.
struct IdDepth {
    std::vector<uint32_t> objectId;
    std::vector<float> linearDepth;
};
struct HostEngineFrame {
    FrameImage caustics;
    IdDepth gbuffer;
};

struct HostEngineOptions {
    // The host builds its own BLASes and TLAS and its own geometry/material/instance tables with raw
    // Vulkan and hands them in (FrameInputs::hostScene); the module builds no acceleration structure.
    bool ownSceneTables = false;
    // Rows of the host's instance table (ownSceneTables); fewer than the scene's instances: a refusal.
    size_t instanceRows = SIZE_MAX;
    // Scales the base colour of the diffuse materials in the host's material table only (ownSceneTables):
    // the caustic's receiver BRDF comes from that table, so its radiance scales with it.
    float diffuseAlbedoScale = 1.0f;
    // The host writes its material table in its command buffer (vkCmdUpdateBuffer, no barrier of its
    // own) and hands the tables over in CopyDest (HostSceneTables::tablesState): the module's barrier
    // must make the write visible (ownSceneTables).
    bool materialsWrittenInCommandBuffer = false;
    // The host's G-buffer writes its own object ids, kSparseIdBase + kSparseIdStride * instance row,
    // instead of the module's row + 1; with objectIdMap it hands the module the (hostId, moduleId) map.
    bool sparseObjectIds = false;
    bool objectIdMap = false;
};
inline constexpr uint32_t kSparseIdBase = 1000, kSparseIdStride = 7;

// The engine's whole frame: its G-buffer (and acceleration structures), the module, readback of its
// output image and of its objectId and linearDepth images. `messages`: the validation layer's
// warnings and errors on the host's device, collected after the device is destroyed.
Result<HostEngineFrame> hostEngineFrame(const scene::Scene& scene, const CameraView& camera, uint32_t seed,
                                        const HostEngineOptions& options, std::vector<std::string>& messages);

}  // namespace caustics::test
