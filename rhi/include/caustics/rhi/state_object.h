#pragma once
// Ray-tracing pipeline described the DXR way: libraries with named exports, hit groups, shader and
// pipeline config, global and local binding layouts. Vulkan: one VkPipeline with shader groups;
// D3D12: one ID3D12StateObject.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "caustics/rhi/pipeline.h"

namespace caustics::rhi {

struct ShaderExport {
    std::string name;          // the name shader tables and hit groups refer to
    std::string entryPoint;    // function in the library ("main" for GLSL-compiled SPIR-V)
    ShaderStage stage = ShaderStage::RayGen;
};

struct ShaderLibraryDesc {
    ShaderCode code;
    std::vector<ShaderExport> exports;
};

enum class HitGroupType : uint8_t { Triangles, Procedural };

struct HitGroupDesc {
    std::string name;
    HitGroupType type = HitGroupType::Triangles;
    std::string closestHit;    // export names; empty = none
    std::string anyHit;
    std::string intersection;  // required for Procedural
};

// Local (per shader-record) data: raw bytes after the shader identifier, like D3D12 local root
// constants / Vulkan shaderRecordEXT. Each record may carry up to localDataBytes.
struct LocalBindings {
    uint32_t localDataBytes = 0;
};

struct StateObjectDesc {
    std::vector<ShaderLibraryDesc> libraries;
    std::vector<HitGroupDesc> hitGroups;
    uint32_t maxPayloadBytes = 32;
    uint32_t maxAttributeBytes = 8;   // 8 = two floats (triangle barycentrics)
    uint32_t maxRecursionDepth = 1;
    PipelineBindings globalBindings;
    LocalBindings localBindings;
    std::string debugName;
};

class IStateObject {
public:
    virtual ~IStateObject() = default;
    virtual const StateObjectDesc& desc() const = 0;
    // The opaque identifier of an export or hit group (handleSize bytes); empty if unknown.
    virtual std::vector<uint8_t> shaderIdentifier(const std::string& exportName) const = 0;
};
using StateObjectHandle = std::shared_ptr<IStateObject>;

struct ShaderRecord {
    std::string exportName;          // raygen/miss/callable export or hit-group name
    std::vector<uint8_t> localData;  // at most StateObjectDesc::localBindings.localDataBytes
};

struct ShaderTableDesc {
    StateObjectHandle stateObject;
    ShaderRecord rayGen;
    std::vector<ShaderRecord> missRecords;
    std::vector<ShaderRecord> hitGroupRecords;
    std::vector<ShaderRecord> callableRecords;
    std::string debugName;

    ShaderTableDesc& setRayGen(std::string name, std::vector<uint8_t> data = {}) {
        rayGen = {std::move(name), std::move(data)}; return *this;
    }
    ShaderTableDesc& addMiss(std::string name, std::vector<uint8_t> data = {}) {
        missRecords.push_back({std::move(name), std::move(data)}); return *this;
    }
    ShaderTableDesc& addHitGroup(std::string name, std::vector<uint8_t> data = {}) {
        hitGroupRecords.push_back({std::move(name), std::move(data)}); return *this;
    }
    ShaderTableDesc& addCallable(std::string name, std::vector<uint8_t> data = {}) {
        callableRecords.push_back({std::move(name), std::move(data)}); return *this;
    }
};

class IShaderTable {
public:
    virtual ~IShaderTable() = default;
    virtual const ShaderTableDesc& desc() const = 0;
};
using ShaderTableHandle = std::shared_ptr<IShaderTable>;

}  // namespace caustics::rhi
