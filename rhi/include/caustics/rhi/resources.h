#pragma once
// Buffers, textures, samplers and memory heaps. Descriptions are plain structs with defaults and
// chainable setters; objects are reference-counted handles owned by whoever holds them.
#include <cstdint>
#include <memory>
#include <string>

#include "caustics/rhi/format.h"
#include "caustics/rhi/native_object.h"
#include "caustics/rhi/resource_state.h"

namespace caustics::rhi {

enum class MemoryType : uint8_t {
    DeviceLocal,  // GPU only
    Upload,       // host-visible, written by the CPU
    Readback,     // host-visible, read by the CPU
};

enum class BufferUsage : uint32_t {
    None = 0,
    Vertex = 1u << 0,
    Index = 1u << 1,
    Constant = 1u << 2,
    Storage = 1u << 3,            // structured/raw buffer, read or read-write in shaders
    Indirect = 1u << 4,
    AccelStructInput = 1u << 5,   // vertices, indices, AABBs, instances read by an AS build
    AccelStructStorage = 1u << 6, // backing memory of an acceleration structure
    ShaderTable = 1u << 7,
    CopySource = 1u << 8,
    CopyDest = 1u << 9,
};
constexpr BufferUsage operator|(BufferUsage a, BufferUsage b) { return BufferUsage(uint32_t(a) | uint32_t(b)); }
constexpr bool hasAny(BufferUsage set, BufferUsage bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

struct BufferDesc {
    uint64_t byteSize = 0;
    BufferUsage usage = BufferUsage::Storage | BufferUsage::CopySource | BufferUsage::CopyDest;
    MemoryType memory = MemoryType::DeviceLocal;
    uint32_t structStride = 0;   // element size for structured views (D3D12); 0 = raw
    bool isVirtual = false;      // no memory yet: bind it to a Heap (render-graph aliasing)
    std::string debugName;

    BufferDesc& setByteSize(uint64_t v) { byteSize = v; return *this; }
    BufferDesc& setUsage(BufferUsage v) { usage = v; return *this; }
    BufferDesc& setMemory(MemoryType v) { memory = v; return *this; }
    BufferDesc& setStructStride(uint32_t v) { structStride = v; return *this; }
    BufferDesc& setVirtual(bool v) { isVirtual = v; return *this; }
    BufferDesc& setDebugName(std::string v) { debugName = std::move(v); return *this; }
};

class IBuffer {
public:
    virtual ~IBuffer() = default;
    virtual const BufferDesc& desc() const = 0;
    // GPU virtual address (Vulkan buffer device address / D3D12 GPU VA); 0 if unsupported.
    virtual uint64_t deviceAddress() const = 0;
    // Persistently mapped pointer for Upload/Readback memory; nullptr for DeviceLocal.
    virtual void* mappedData() = 0;
    // VkBuffer / ID3D12Resource; null for other types (native_object.h).
    virtual NativeObject getNativeObject(NativeObjectType) const { return {}; }
};
using BufferHandle = std::shared_ptr<IBuffer>;

enum class TextureDimension : uint8_t { Texture2D, Texture2DArray, TextureCube };

enum class TextureUsage : uint32_t {
    None = 0,
    Sampled = 1u << 0,
    Storage = 1u << 1,        // storage image / UAV (atomics on R32_UINT / R32_FLOAT)
    RenderTarget = 1u << 2,
    DepthStencil = 1u << 3,
    CopySource = 1u << 4,
    CopyDest = 1u << 5,
};
constexpr TextureUsage operator|(TextureUsage a, TextureUsage b) { return TextureUsage(uint32_t(a) | uint32_t(b)); }
constexpr bool hasAny(TextureUsage set, TextureUsage bits) { return (uint32_t(set) & uint32_t(bits)) != 0; }

struct TextureDesc {
    TextureDimension dimension = TextureDimension::Texture2D;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t arrayLayers = 1;   // 6 per cube
    uint32_t mipLevels = 1;
    Format format = Format::RGBA8_UNORM;
    TextureUsage usage = TextureUsage::Sampled | TextureUsage::CopyDest | TextureUsage::CopySource;
    bool isVirtual = false;
    float clearColor[4] = {0, 0, 0, 0};  // optimized clear value (D3D12)
    std::string debugName;

    TextureDesc& setDimension(TextureDimension v) { dimension = v; return *this; }
    TextureDesc& setSize(uint32_t w, uint32_t h) { width = w; height = h; return *this; }
    TextureDesc& setArrayLayers(uint32_t v) { arrayLayers = v; return *this; }
    TextureDesc& setMipLevels(uint32_t v) { mipLevels = v; return *this; }
    TextureDesc& setFormat(Format v) { format = v; return *this; }
    TextureDesc& setUsage(TextureUsage v) { usage = v; return *this; }
    TextureDesc& setVirtual(bool v) { isVirtual = v; return *this; }
    TextureDesc& setDebugName(std::string v) { debugName = std::move(v); return *this; }
};

class ITexture {
public:
    virtual ~ITexture() = default;
    virtual const TextureDesc& desc() const = 0;
    // VkImage / ID3D12Resource; null for other types (native_object.h).
    virtual NativeObject getNativeObject(NativeObjectType) const { return {}; }
};
using TextureHandle = std::shared_ptr<ITexture>;

enum class FilterMode : uint8_t { Nearest, Linear };
enum class AddressMode : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct SamplerDesc {
    FilterMode filter = FilterMode::Linear;
    AddressMode address = AddressMode::Repeat;
    float maxAnisotropy = 1.0f;
    SamplerDesc& setFilter(FilterMode v) { filter = v; return *this; }
    SamplerDesc& setAddress(AddressMode v) { address = v; return *this; }
};

class ISampler {
public:
    virtual ~ISampler() = default;
    virtual const SamplerDesc& desc() const = 0;
};
using SamplerHandle = std::shared_ptr<ISampler>;

// A block of device memory into which virtual buffers/textures are placed; the render graph aliases
// transient resources whose lifetimes do not overlap by placing them at overlapping offsets.
struct HeapDesc {
    uint64_t byteSize = 0;
    std::string debugName;
};
class IHeap {
public:
    virtual ~IHeap() = default;
    virtual const HeapDesc& desc() const = 0;
};
using HeapHandle = std::shared_ptr<IHeap>;

struct MemoryRequirements {
    uint64_t size = 0;
    uint64_t alignment = 1;
};

}  // namespace caustics::rhi
