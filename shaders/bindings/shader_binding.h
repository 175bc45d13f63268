#pragma once
// A pass's shader resources, declared once in C++ (docs/shaders.md, "Bindings"). From one PassBindings
// the build generates the GLSL and HLSL declarations its shader shims include
// (shaders/bindings/generate_bindings.cpp), and the pass creates its binding layout and fills its
// binding sets by name (passes/include/caustics/pass_bindings.h). Dependency-free: the generator is a
// host tool, also in cross builds.
#include <cstdint>
#include <span>
#include <string_view>

namespace caustics::shader_bindings {

// The resource kinds, in the order of rhi::BindingType (checked in passes/module/pass_bindings.cpp).
enum class Kind : uint8_t {
    ConstantBuffer,    // GLSL std140 uniform block / HLSL ConstantBuffer<T>
    StorageBufferRO,   // GLSL readonly std430 buffer of T[] / HLSL ByteAddressBuffer
    StorageBufferRW,   // GLSL std430 buffer of T[] / HLSL RWByteAddressBuffer
    SampledTexture,    // GLSL texture2D (utexture2D for uint) / HLSL Texture2D<T>
    StorageTexture,    // GLSL image2D with the format / HLSL RWTexture2D<T>
    Sampler,
    AccelStruct,
};

// Storage-texture formats (their GLSL layout qualifier, the HLSL element type, the C++ format).
enum class ImageFormat : uint8_t { None, Rgba8, Rgba16f, Rgba32f, R32f, R32ui, Rg32ui, Rgba32ui };

// A float4x4 member of a storage buffer's struct element and its byte offset in the struct. HLSL reads
// it column by column (loadFloat4x4, common/lang.h): a C++ glm::mat4 is stored column-major, and a
// templated Load<T> of a matrix would take the matrix's packing from the compiler's flags instead.
struct MatrixMember {
    std::string_view name;
    uint32_t offset;
};

struct Binding {
    std::string_view name;      // the shader-visible name, and the key a binding set is filled by
    Kind kind;
    uint32_t set;               // Vulkan descriptor set = D3D12 register space
    uint32_t slot;              // Vulkan binding = D3D12 register number within its class
    std::string_view element;   // shared-dialect element type: float4, uint, uint2 or a struct name
    ImageFormat format = ImageFormat::None;   // storage textures only
    uint32_t stride = 0;        // storage buffers of a struct: its std430 size (built-in types: derived)
    bool textureArray = false;  // sampled textures: a 2D array (GLSL texture2DArray / HLSL Texture2DArray)
    uint32_t count = 1;         // sampled textures: a descriptor array of `count` (the scene's textures)
    std::string_view header;    // storage buffers: a struct before the array (<name>Header, <name>LoadHeader())
    uint32_t headerBytes = 0;   // its size: where element 0 starts (HLSL; std430 places it there too, checked)
    std::span<const MatrixMember> matrices;   // storage buffers of a struct: its float4x4 members
    std::string_view omitIf;    // a macro that, defined before the include, leaves this binding out
};

struct PassBindings {
    std::string_view name;        // generated header "bindings/<name>.h", one per language
    std::string_view declaredIn;  // the C++ header holding this declaration (named in the generated text)
    std::span<const Binding> bindings;
    std::string_view pushType;    // shared-dialect struct of the push constants; empty: none
    std::string_view pushName;    // the global the push constants are visible as
};

}  // namespace caustics::shader_bindings
