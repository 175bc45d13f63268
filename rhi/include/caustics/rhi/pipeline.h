#pragma once
// Compute and graphics (rasterization, dynamic rendering) pipelines.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/rhi/binding.h"
#include "caustics/rhi/shader.h"

namespace caustics::rhi {

// Pipeline-wide binding interface (a D3D12 global root signature / Vulkan pipeline layout):
// binding layout i is descriptor set i (Vulkan) / register space i (D3D12).
struct PipelineBindings {
    std::vector<BindingLayoutHandle> layouts;
    uint32_t pushConstantBytes = 0;   // at most 128 (Vulkan's guaranteed minimum)
};

struct ComputePipelineDesc {
    ShaderEntry shader;
    PipelineBindings bindings;
    std::string debugName;
};

class IComputePipeline {
public:
    virtual ~IComputePipeline() = default;
    virtual const ComputePipelineDesc& desc() const = 0;
};
using ComputePipelineHandle = std::shared_ptr<IComputePipeline>;

enum class CompareOp : uint8_t { Never, Less, LessOrEqual, Equal, Greater, GreaterOrEqual, Always };
enum class CullMode : uint8_t { None, Front, Back };
enum class PrimitiveTopology : uint8_t { TriangleList, TriangleStrip, LineList, PointList };

struct VertexAttribute {
    uint32_t location = 0;
    uint32_t binding = 0;     // vertex buffer slot
    Format format = Format::RGB32_FLOAT;
    uint32_t offset = 0;
};
struct VertexBufferLayout {
    uint32_t binding = 0;
    uint32_t stride = 0;
};

struct GraphicsPipelineDesc {
    ShaderEntry vertexShader;
    ShaderEntry fragmentShader;   // stage None = depth-only
    PipelineBindings bindings;
    std::vector<VertexBufferLayout> vertexBuffers;   // empty = vertex pulling from storage buffers
    std::vector<VertexAttribute> vertexAttributes;
    PrimitiveTopology topology = PrimitiveTopology::TriangleList;
    CullMode cullMode = CullMode::None;
    bool frontCounterClockwise = true;
    std::vector<Format> colorFormats;
    Format depthFormat = Format::Unknown;
    bool depthTest = true;
    bool depthWrite = true;
    CompareOp depthCompare = CompareOp::Less;
    bool additiveBlend = false;   // for every color target: dst += src
    std::string debugName;
};

class IGraphicsPipeline {
public:
    virtual ~IGraphicsPipeline() = default;
    virtual const GraphicsPipelineDesc& desc() const = 0;
};
using GraphicsPipelineHandle = std::shared_ptr<IGraphicsPipeline>;

}  // namespace caustics::rhi
