#pragma once
// Root-signature-like binding model. A BindingLayout is one descriptor table (Vulkan: a descriptor
// set layout; D3D12: a root-signature descriptor table in register space = the layout's index in the
// pipeline). A pipeline takes an ordered list of layouts plus an optional push-constant block
// (Vulkan push constants; D3D12 root constants in register b0 of space 999... see backends).
#include <cstdint>
#include <memory>
#include <vector>

#include "caustics/rhi/resources.h"

namespace caustics::rhi {

class IAccelStruct;
using AccelStructHandle = std::shared_ptr<IAccelStruct>;

enum class ShaderStage : uint32_t {
    None = 0,
    Vertex = 1u << 0,
    Fragment = 1u << 1,
    Compute = 1u << 2,
    RayGen = 1u << 3,
    Miss = 1u << 4,
    ClosestHit = 1u << 5,
    AnyHit = 1u << 6,
    Intersection = 1u << 7,
    Callable = 1u << 8,
    AllGraphics = Vertex | Fragment,
    AllRayTracing = RayGen | Miss | ClosestHit | AnyHit | Intersection | Callable,
    All = AllGraphics | Compute | AllRayTracing,
};
constexpr ShaderStage operator|(ShaderStage a, ShaderStage b) { return ShaderStage(uint32_t(a) | uint32_t(b)); }
constexpr bool hasAny(ShaderStage set, ShaderStage bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

enum class BindingType : uint8_t {
    ConstantBuffer,    // uniform buffer / CBV (b)
    StorageBufferRO,   // readonly storage buffer / SRV (t)
    StorageBufferRW,   // storage buffer / UAV (u)
    SampledTexture,    // sampled image / SRV (t)
    StorageTexture,    // storage image / UAV (u)
    Sampler,           // sampler (s)
    AccelStruct,       // TLAS / SRV (t)
};

struct BindingLayoutItem {
    uint32_t slot = 0;        // Vulkan binding number; D3D12 register number within its class
    BindingType type = BindingType::ConstantBuffer;
    uint32_t arraySize = 1;   // >1: array (e.g. bindless textures); all elements must be written
};

struct BindingLayoutDesc {
    ShaderStage visibility = ShaderStage::All;
    std::vector<BindingLayoutItem> items;
    BindingLayoutDesc& setVisibility(ShaderStage v) { visibility = v; return *this; }
    BindingLayoutDesc& add(uint32_t slot, BindingType type, uint32_t arraySize = 1) {
        items.push_back({slot, type, arraySize});
        return *this;
    }
};

class IBindingLayout {
public:
    virtual ~IBindingLayout() = default;
    virtual const BindingLayoutDesc& desc() const = 0;
};
using BindingLayoutHandle = std::shared_ptr<IBindingLayout>;

struct BindingSetItem {
    uint32_t slot = 0;
    uint32_t arrayElement = 0;
    BindingType type = BindingType::ConstantBuffer;
    BufferHandle buffer;
    uint64_t offset = 0;
    uint64_t range = 0;        // 0 = to the end of the buffer
    TextureHandle texture;
    SamplerHandle sampler;
    AccelStructHandle accelStruct;

    static BindingSetItem constantBuffer(uint32_t slot, BufferHandle b, uint64_t offset = 0, uint64_t range = 0) {
        BindingSetItem i; i.slot = slot; i.type = BindingType::ConstantBuffer; i.buffer = std::move(b);
        i.offset = offset; i.range = range; return i;
    }
    static BindingSetItem storageBuffer(uint32_t slot, BufferHandle b, bool writable = true) {
        BindingSetItem i; i.slot = slot; i.type = writable ? BindingType::StorageBufferRW : BindingType::StorageBufferRO;
        i.buffer = std::move(b); return i;
    }
    static BindingSetItem sampledTexture(uint32_t slot, TextureHandle t, uint32_t element = 0) {
        BindingSetItem i; i.slot = slot; i.type = BindingType::SampledTexture; i.texture = std::move(t);
        i.arrayElement = element; return i;
    }
    static BindingSetItem storageTexture(uint32_t slot, TextureHandle t) {
        BindingSetItem i; i.slot = slot; i.type = BindingType::StorageTexture; i.texture = std::move(t); return i;
    }
    static BindingSetItem samplerItem(uint32_t slot, SamplerHandle s) {
        BindingSetItem i; i.slot = slot; i.type = BindingType::Sampler; i.sampler = std::move(s); return i;
    }
    static BindingSetItem accelStructItem(uint32_t slot, AccelStructHandle a) {
        BindingSetItem i; i.slot = slot; i.type = BindingType::AccelStruct; i.accelStruct = std::move(a); return i;
    }
};

struct BindingSetDesc {
    std::vector<BindingSetItem> items;
    BindingSetDesc& add(BindingSetItem item) { items.push_back(std::move(item)); return *this; }
};

class IBindingSet {
public:
    virtual ~IBindingSet() = default;
    virtual const BindingSetDesc& desc() const = 0;
    virtual const BindingLayoutHandle& layout() const = 0;
};
using BindingSetHandle = std::shared_ptr<IBindingSet>;

}  // namespace caustics::rhi
