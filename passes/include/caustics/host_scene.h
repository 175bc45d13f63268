#pragma once
// Scene tables a host engine already has, handed to the module instead of the ones it builds from
// scene::Scene (docs/embedding.md "Host scene tables"). Each handle is optional: a null one means "use
// the module's". The layouts are the module's (caustics/scene/gpu_types.h, caustics/scene/gpu_scene.h):
//
//   tlas       instance i: instanceId = i (the row of `instances`), mask scene::kMaskSpecular for
//              specular objects else scene::kMaskDiffuse, hitGroupOffset 0, opaque triangle geometry
//   positions  float3 per vertex (tightly packed, 12 bytes)
//   vertices   GpuVertex per vertex (48 bytes: normal, u, tangent, v)
//   indices    uint32, relative to the instance's firstVertex
//   materials  GpuMaterial[] (96 bytes)
//   instances  GpuInstance[] (160 bytes): objectToWorld, normalToWorld, material, firstVertex,
//              firstIndex, triangleCount, objectId, mesh, flags (kInstanceSpecular)
//
// The CPU scene (scene::Scene) still tells the module the lights, the specular objects' world bounds
// (caustic map frusta) and, for its own G-buffer and map rasterization, each instance's mesh; it must
// describe the same instances in the same order as these tables. With a host TLAS or instance table
// the host also hands in `instanceRows`, its CPU copy of this frame's instance rows, and every
// addPasses checks the scene against it, naming the first instance that differs: a host that moves
// its TLAS but not scene::Scene gets an error, not a dimmed caustic.
#include <span>

#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/resource_state.h"
#include "caustics/rhi/resources.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/gpu_types.h"
#include "caustics/scene/scene.h"

namespace caustics {

struct HostSceneTables {
    rhi::AccelStructHandle tlas;
    // The state the host leaves its TLAS in before the graph and wants it in after (built and readable).
    rhi::ResourceState tlasState = rhi::ResourceState::AccelStructRead;
    rhi::BufferHandle positions, vertices, indices, materials, instances;
    // The state the host leaves the five tables in before the graph and wants them in after. The module
    // imports them with it and its own barrier makes the host's earlier writes visible to every shader
    // stage (docs/embedding.md "Hand-over states"): CopyDest after a copy or vkCmdUpdateBuffer in the
    // same command buffer, UnorderedAccess after a compute pass wrote them, AccelStructBuildInput after
    // the host's BLAS/TLAS builds read them; ShaderResource (the default) when they are already visible
    // to shader reads (written from the CPU before the submit, or behind the host's own barrier).
    rhi::ResourceState tablesState = rhi::ResourceState::ShaderResource;
    // Required with `tlas` or `instances`: what the host wrote into its instance table (and placed in its
    // TLAS) for this frame, one GpuInstance per scene instance. Read during addPasses only.
    std::span<const scene::GpuInstance> instanceRows;
};

// How far a host row's objectToWorld may be from the scene's (largest absolute entry difference,
// relative to the matrix's largest entry): float rounding of the same transform stays far below it.
inline constexpr float kHostInstanceTransformTolerance = 1e-4f;

// ok, or an error naming the first table the module cannot bind for `scene`: a TLAS that is not top
// level, a buffer without Storage usage, geometry tables not given as a set (positions, vertices and
// indices: the instance rows index all three), or an instance or material table with fewer rows than
// the scene has instances or materials (the hit shaders would read past its end), and, with a host
// TLAS or instance table, missing `instanceRows`, a `tablesState` a buffer cannot be in, or a row whose transform, material or specular flag is
// not the scene instance's (naming the instance, its row and the entry). Device-free; the module calls
// it at every addPasses.
Status checkHostSceneTables(const HostSceneTables& tables, const scene::Scene& scene);

}  // namespace caustics
