#pragma once
// Resource states in the D3D12 style. Command lists take explicit (before, after) transitions;
// each backend translates a state into its own terms (Vulkan: stages, access, image layout;
// D3D12: D3D12_RESOURCE_STATES). The render graph, not the passes, chooses the transitions.
#include <cstdint>

namespace caustics::rhi {

enum class ResourceState : uint32_t {
    Undefined = 0,
    Common = 1u << 0,
    ConstantBuffer = 1u << 1,
    VertexBuffer = 1u << 2,
    IndexBuffer = 1u << 3,
    IndirectArgument = 1u << 4,
    ShaderResource = 1u << 5,        // sampled texture / read-only storage buffer, any shader stage
    UnorderedAccess = 1u << 6,       // storage image / read-write storage buffer, any shader stage
    RenderTarget = 1u << 7,
    DepthWrite = 1u << 8,
    DepthRead = 1u << 9,
    CopySource = 1u << 10,
    CopyDest = 1u << 11,
    AccelStructRead = 1u << 12,      // traced against (TLAS) or referenced by a TLAS build (BLAS)
    AccelStructWrite = 1u << 13,     // written by a build, update or copy
    AccelStructBuildInput = 1u << 14,// vertex/index/AABB/instance buffers read by a build
    ShaderTable = 1u << 15,
    Present = 1u << 16,
};

constexpr ResourceState operator|(ResourceState a, ResourceState b) {
    return ResourceState(uint32_t(a) | uint32_t(b));
}
constexpr ResourceState operator&(ResourceState a, ResourceState b) {
    return ResourceState(uint32_t(a) & uint32_t(b));
}
constexpr bool hasAny(ResourceState set, ResourceState bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

// True where the state lets the GPU write (so a later access needs a barrier even if the state is unchanged).
constexpr bool isWriteState(ResourceState s) {
    return hasAny(s, ResourceState::UnorderedAccess | ResourceState::RenderTarget | ResourceState::DepthWrite |
                         ResourceState::CopyDest | ResourceState::AccelStructWrite);
}

const char* resourceStateName(ResourceState state);

}  // namespace caustics::rhi
