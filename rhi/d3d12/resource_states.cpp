#include "resource_states.h"

namespace caustics::rhi::d3d12 {

D3D12_RESOURCE_STATES toD3D12States(ResourceState state) {
    struct Pair {
        ResourceState rhi;
        D3D12_RESOURCE_STATES d3d;
    };
    static constexpr Pair kPairs[] = {
        {ResourceState::ConstantBuffer, D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER},
        {ResourceState::VertexBuffer, D3D12_RESOURCE_STATE_VERTEX_AND_CONSTANT_BUFFER},
        {ResourceState::IndexBuffer, D3D12_RESOURCE_STATE_INDEX_BUFFER},
        {ResourceState::IndirectArgument, D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT},
        // "Any shader stage": pixel and non-pixel together. Combined as integers: MinGW's
        // DEFINE_ENUM_FLAG_OPERATORS are not constexpr (the Windows SDK's are).
        {ResourceState::ShaderResource,
         D3D12_RESOURCE_STATES(int(D3D12_RESOURCE_STATE_PIXEL_SHADER_RESOURCE) |
                               int(D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE))},
        {ResourceState::UnorderedAccess, D3D12_RESOURCE_STATE_UNORDERED_ACCESS},
        {ResourceState::RenderTarget, D3D12_RESOURCE_STATE_RENDER_TARGET},
        {ResourceState::DepthWrite, D3D12_RESOURCE_STATE_DEPTH_WRITE},
        {ResourceState::DepthRead, D3D12_RESOURCE_STATE_DEPTH_READ},
        {ResourceState::CopySource, D3D12_RESOURCE_STATE_COPY_SOURCE},
        {ResourceState::CopyDest, D3D12_RESOURCE_STATE_COPY_DEST},
        {ResourceState::AccelStructRead, D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE},
        {ResourceState::AccelStructWrite, D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE},
        {ResourceState::AccelStructBuildInput, D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE},
        {ResourceState::ShaderTable, D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE},
        {ResourceState::Present, D3D12_RESOURCE_STATE_PRESENT},
    };
    uint32_t out = D3D12_RESOURCE_STATE_COMMON;   // Undefined and Common
    for (const Pair& p : kPairs)
        if (hasAny(state, p.rhi)) out |= uint32_t(p.d3d);
    return D3D12_RESOURCE_STATES(out);
}

BarrierPlan planBarrier(ResourceState before, ResourceState after, D3D12_RESOURCE_STATES current,
                        bool aliasing) {
    BarrierPlan plan;
    plan.aliasing = aliasing;
    plan.before = before == ResourceState::Undefined ? current : toD3D12States(before);
    plan.after = toD3D12States(after);
    plan.transition = plan.before != plan.after;
    // Write-after-write or read-after-write with no state change still needs ordering.
    plan.uav = !plan.transition && hasAny(before, ResourceState::UnorderedAccess) &&
               hasAny(after, ResourceState::UnorderedAccess);
    return plan;
}

BarrierPlan planAccelStructBarrier(ResourceState before, ResourceState after) {
    BarrierPlan plan;
    plan.before = plan.after = D3D12_RESOURCE_STATE_RAYTRACING_ACCELERATION_STRUCTURE;
    plan.uav = isWriteState(before) || isWriteState(after);
    return plan;
}

}  // namespace caustics::rhi::d3d12
