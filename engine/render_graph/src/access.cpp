#include "caustics/render_graph/access.h"

namespace caustics::rg {

using rhi::BufferUsage;
using rhi::ResourceState;
using rhi::TextureUsage;

const char* resourceKindName(ResourceKind kind) {
    switch (kind) {
        case ResourceKind::Texture: return "texture";
        case ResourceKind::Buffer: return "buffer";
        case ResourceKind::AccelStruct: return "acceleration structure";
    }
    return "?";
}

const char* accessName(Access access) {
    switch (access) {
        case Access::SampledRead: return "SampledRead";
        case Access::StorageRead: return "StorageRead";
        case Access::StorageWrite: return "StorageWrite";
        case Access::StorageReadWrite: return "StorageReadWrite";
        case Access::RenderTarget: return "RenderTarget";
        case Access::DepthWrite: return "DepthWrite";
        case Access::DepthRead: return "DepthRead";
        case Access::CopySource: return "CopySource";
        case Access::CopyDest: return "CopyDest";
        case Access::VertexBuffer: return "VertexBuffer";
        case Access::IndexBuffer: return "IndexBuffer";
        case Access::ConstantBuffer: return "ConstantBuffer";
        case Access::IndirectArgument: return "IndirectArgument";
        case Access::AccelStructBuildInput: return "AccelStructBuildInput";
        case Access::AccelStructBuild: return "AccelStructBuild";
        case Access::AccelStructTrace: return "AccelStructTrace";
        case Access::AccelStructBuildRead: return "AccelStructBuildRead";
    }
    return "?";
}

bool accessWrites(Access access) {
    switch (access) {
        case Access::StorageWrite:
        case Access::StorageReadWrite:
        case Access::RenderTarget:
        case Access::DepthWrite:
        case Access::CopyDest:
        case Access::AccelStructBuild: return true;
        default: return false;
    }
}

bool accessValidFor(ResourceKind kind, Access access) {
    switch (access) {
        case Access::SampledRead:
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
        case Access::CopySource:
        case Access::CopyDest: return kind != ResourceKind::AccelStruct;
        case Access::RenderTarget:
        case Access::DepthWrite:
        case Access::DepthRead: return kind == ResourceKind::Texture;
        case Access::VertexBuffer:
        case Access::IndexBuffer:
        case Access::ConstantBuffer:
        case Access::IndirectArgument:
        case Access::AccelStructBuildInput: return kind == ResourceKind::Buffer;
        case Access::AccelStructBuild:
        case Access::AccelStructTrace:
        case Access::AccelStructBuildRead: return kind == ResourceKind::AccelStruct;
    }
    return false;
}

ResourceState accessState(ResourceKind kind, Access access) {
    switch (access) {
        case Access::SampledRead: return ResourceState::ShaderResource;
        // A storage image stays in the UAV state (Vulkan GENERAL layout) even when only loaded; a
        // read-only storage buffer is an SRV in D3D12 terms.
        case Access::StorageRead:
            return kind == ResourceKind::Texture ? ResourceState::UnorderedAccess : ResourceState::ShaderResource;
        case Access::StorageWrite:
        case Access::StorageReadWrite: return ResourceState::UnorderedAccess;
        case Access::RenderTarget: return ResourceState::RenderTarget;
        case Access::DepthWrite: return ResourceState::DepthWrite;
        case Access::DepthRead: return ResourceState::DepthRead;
        case Access::CopySource: return ResourceState::CopySource;
        case Access::CopyDest: return ResourceState::CopyDest;
        case Access::VertexBuffer: return ResourceState::VertexBuffer;
        case Access::IndexBuffer: return ResourceState::IndexBuffer;
        case Access::ConstantBuffer: return ResourceState::ConstantBuffer;
        case Access::IndirectArgument: return ResourceState::IndirectArgument;
        case Access::AccelStructBuildInput: return ResourceState::AccelStructBuildInput;
        case Access::AccelStructBuild: return ResourceState::AccelStructWrite;
        case Access::AccelStructTrace:
        case Access::AccelStructBuildRead: return ResourceState::AccelStructRead;
    }
    return ResourceState::Common;
}

TextureUsage requiredTextureUsage(Access access) {
    switch (access) {
        case Access::SampledRead: return TextureUsage::Sampled;
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite: return TextureUsage::Storage;
        case Access::RenderTarget: return TextureUsage::RenderTarget;
        case Access::DepthWrite: return TextureUsage::DepthStencil;
        case Access::DepthRead: return TextureUsage::DepthStencil;
        case Access::CopySource: return TextureUsage::CopySource;
        case Access::CopyDest: return TextureUsage::CopyDest;
        default: return TextureUsage::None;
    }
}

BufferUsage requiredBufferUsage(Access access) {
    switch (access) {
        case Access::SampledRead:
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite: return BufferUsage::Storage;
        case Access::CopySource: return BufferUsage::CopySource;
        case Access::CopyDest: return BufferUsage::CopyDest;
        case Access::VertexBuffer: return BufferUsage::Vertex;
        case Access::IndexBuffer: return BufferUsage::Index;
        case Access::ConstantBuffer: return BufferUsage::Constant;
        case Access::IndirectArgument: return BufferUsage::Indirect;
        case Access::AccelStructBuildInput: return BufferUsage::AccelStructInput;
        default: return BufferUsage::None;
    }
}

}  // namespace caustics::rg
