#pragma once
// Every pipeline the passes create, as the C++ code describes it: the passes are created on a
// device that only records their descs (no GPU), so the binding layouts, push-constant sizes and
// payload sizes seen here are exactly what the running code hands to Vulkan or D3D12. This is the
// "one binding truth" the shader checks (binding_checker.h) and the D3D12 translation tests compare
// against (docs/d3d12.md).
#include <string>
#include <vector>

#include "caustics/rhi/device.h"
#include "caustics/rhi/pipeline.h"
#include "caustics/rhi/state_object.h"

namespace caustics::test {

enum class PipelineKind : uint8_t { Compute, Graphics, RayTracing };

struct RecordedShader {
    std::string name;        // pass shader name, e.g. "forward_trace/forward.rgen"
    rhi::ShaderStage stage = rhi::ShaderStage::None;
    std::string hlsl;        // the embedded HLSL text (quoted includes already inlined)
};

struct RecordedPipeline {
    PipelineKind kind = PipelineKind::Compute;
    std::string debugName;
    std::vector<rhi::BindingLayoutDesc> layouts;   // index = Vulkan set = D3D12 register space
    uint32_t pushConstantBytes = 0;
    uint32_t maxPayloadBytes = 0;                  // ray tracing only
    uint32_t maxAttributeBytes = 0;
    std::vector<RecordedShader> shaders;
    rhi::ComputePipelineDesc compute;              // the desc of its kind, as created
    rhi::GraphicsPipelineDesc graphics;
    rhi::StateObjectDesc stateObject;
    std::vector<rhi::ShaderTableDesc> shaderTables;   // tables created over this state object
};

struct PassPipelineOptions {
    bool floatAtomics = true;   // Capabilities::shaderFloatAtomicAdd: picks the float or fixed-point shaders
    bool int64Atomics = false;  // Capabilities::shaderBufferInt64Atomics: the fixed-point shaders' 64-bit words
};

// Creates every pass of the module (scene bindings, G-buffer, direct lighting, composite, caustic
// maps, forward, backward, gather, filter) on a recording D3D12-flavoured device and returns what
// they created, in creation order. Errors name the pass that failed.
Result<std::vector<RecordedPipeline>> recordPassPipelines(const PassPipelineOptions& options = {});

}  // namespace caustics::test
