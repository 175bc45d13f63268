#pragma once
// How a pass uses a resource. Each access maps to one rhi::ResourceState (the D3D12-style state the
// backend turns into Vulkan stages/access/layout) and says whether the pass writes the resource.
#include <cstdint>

#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/resource_state.h"
#include "caustics/rhi/resources.h"

namespace caustics::rg {

enum class Access : uint8_t {
    SampledRead,          // texture sampled / buffer as read-only storage (SRV)
    StorageRead,          // storage image load (UAV state) / read-only storage buffer (SRV)
    StorageWrite,         // storage image or buffer written (UAV)
    StorageReadWrite,     // read-modify-write, atomics (UAV)
    RenderTarget,         // color attachment
    DepthWrite,           // depth attachment with writes
    DepthRead,            // depth attachment (test only) or depth sampled read-only
    CopySource,
    CopyDest,
    VertexBuffer,
    IndexBuffer,
    ConstantBuffer,
    IndirectArgument,
    AccelStructBuildInput,  // buffer read by an AS build (vertices, indices, AABBs, instances)
    AccelStructBuild,       // AS written by a build / update
    AccelStructTrace,       // TLAS traced against (ray tracing or ray query)
    AccelStructBuildRead,   // BLAS referenced by a TLAS build
};

const char* accessName(Access access);
bool accessWrites(Access access);
// False where the access makes no sense for that kind (e.g. RenderTarget on a buffer).
bool accessValidFor(ResourceKind kind, Access access);
rhi::ResourceState accessState(ResourceKind kind, Access access);
// Usage flags a transient needs so that the backend accepts the access (added to the user's desc).
rhi::TextureUsage requiredTextureUsage(Access access);
rhi::BufferUsage requiredBufferUsage(Access access);

}  // namespace caustics::rg
