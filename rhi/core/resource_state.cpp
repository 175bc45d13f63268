#include "caustics/rhi/resource_state.h"

namespace caustics::rhi {

const char* resourceStateName(ResourceState state) {
    switch (state) {
        case ResourceState::Undefined: return "Undefined";
        case ResourceState::Common: return "Common";
        case ResourceState::ConstantBuffer: return "ConstantBuffer";
        case ResourceState::VertexBuffer: return "VertexBuffer";
        case ResourceState::IndexBuffer: return "IndexBuffer";
        case ResourceState::IndirectArgument: return "IndirectArgument";
        case ResourceState::ShaderResource: return "ShaderResource";
        case ResourceState::UnorderedAccess: return "UnorderedAccess";
        case ResourceState::RenderTarget: return "RenderTarget";
        case ResourceState::DepthWrite: return "DepthWrite";
        case ResourceState::DepthRead: return "DepthRead";
        case ResourceState::CopySource: return "CopySource";
        case ResourceState::CopyDest: return "CopyDest";
        case ResourceState::AccelStructRead: return "AccelStructRead";
        case ResourceState::AccelStructWrite: return "AccelStructWrite";
        case ResourceState::AccelStructBuildInput: return "AccelStructBuildInput";
        case ResourceState::ShaderTable: return "ShaderTable";
        case ResourceState::Present: return "Present";
    }
    return "Combined";
}

}  // namespace caustics::rhi
