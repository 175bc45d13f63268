#pragma once
// rhi::ResourceState -> D3D12 legacy resource barriers, device-free.
// Rules (D3D12 "Using resource barriers"; DXR spec "Acceleration structure memory restrictions"):
//  - an acceleration structure lives in RAYTRACING_ACCELERATION_STRUCTURE for its whole life, so
//    ordering between builds and traces is a UAV barrier, never a transition;
//  - UAV -> UAV on the same resource needs a UAV barrier (no transition is possible);
//  - shader tables and AS build inputs are read as NON_PIXEL_SHADER_RESOURCE.
#include "d3d12_headers.h"
#include "caustics/rhi/resource_state.h"

namespace caustics::rhi::d3d12 {

D3D12_RESOURCE_STATES toD3D12States(ResourceState state);

struct BarrierPlan {
    bool transition = false;             // emit D3D12_RESOURCE_BARRIER_TYPE_TRANSITION before -> after
    D3D12_RESOURCE_STATES before = D3D12_RESOURCE_STATE_COMMON;
    D3D12_RESOURCE_STATES after = D3D12_RESOURCE_STATE_COMMON;
    bool uav = false;                    // emit D3D12_RESOURCE_BARRIER_TYPE_UAV
    // Emit D3D12_RESOURCE_BARRIER_TYPE_ALIASING (before = any placed resource) ahead of the
    // transition: the resource takes over heap memory another one used (render-graph aliasing).
    bool aliasing = false;
};

// `current` is the state the backend last put the resource in; it stands in for `before` when the
// caller says Undefined (contents may be discarded, but D3D12 still needs the real state).
BarrierPlan planBarrier(ResourceState before, ResourceState after, D3D12_RESOURCE_STATES current,
                        bool aliasing = false);

// Acceleration-structure barriers: always a UAV barrier when a build/update/copy wrote it.
BarrierPlan planAccelStructBarrier(ResourceState before, ResourceState after);

}  // namespace caustics::rhi::d3d12
