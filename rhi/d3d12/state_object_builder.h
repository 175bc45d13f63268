#pragma once
// rhi::StateObjectDesc -> D3D12_STATE_OBJECT_DESC (DXR spec "State objects"), device-free.
// Subobjects, in this order:
//   DXIL_LIBRARY per library (one D3D12_EXPORT_DESC per export; ExportToRename = entry point when it
//   differs from the export name), HIT_GROUP per hit group, RAYTRACING_SHADER_CONFIG,
//   [LOCAL_ROOT_SIGNATURE + SUBOBJECT_TO_EXPORTS_ASSOCIATION to every raygen/miss/callable export and
//   every hit group, when localDataBytes > 0], GLOBAL_ROOT_SIGNATURE, RAYTRACING_PIPELINE_CONFIG.
// Every pointer inside desc() points into the builder, which must outlive the CreateStateObject call.
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <vector>

#include "d3d12_headers.h"
#include "caustics/rhi/result.h"
#include "caustics/rhi/state_object.h"

namespace caustics::rhi::d3d12 {

struct StateObjectInputs {
    // Compiled DXIL per StateObjectDesc::libraries entry, same order.
    std::vector<std::span<const uint8_t>> libraryBytecode;
    ID3D12RootSignature* globalRootSignature = nullptr;   // required by DXR; may be an empty signature
    ID3D12RootSignature* localRootSignature = nullptr;    // used when localBindings.localDataBytes > 0
};

class StateObjectBuilder {
public:
    StateObjectBuilder() = default;
    StateObjectBuilder(const StateObjectBuilder&) = delete;
    StateObjectBuilder& operator=(const StateObjectBuilder&) = delete;

    // Validates the desc (names, stages, hit-group shapes, DXR limits) and fills the subobject list.
    Status build(const StateObjectDesc& desc, const StateObjectInputs& inputs);

    const D3D12_STATE_OBJECT_DESC& desc() const { return desc_; }
    std::span<const D3D12_STATE_SUBOBJECT> subobjects() const { return subobjects_; }
    // Names the shader table can refer to (raygen, miss, callable exports and hit groups).
    const std::vector<std::string>& shaderTableNames() const { return tableNames_; }

private:
    const wchar_t* wide(const std::string& s);
    D3D12_STATE_SUBOBJECT& add(D3D12_STATE_SUBOBJECT_TYPE type, const void* desc);

    std::deque<std::wstring> strings_;
    std::deque<std::vector<D3D12_EXPORT_DESC>> exports_;
    std::deque<D3D12_DXIL_LIBRARY_DESC> libraries_;
    std::deque<D3D12_HIT_GROUP_DESC> hitGroups_;
    std::vector<const wchar_t*> associatedNames_;
    D3D12_RAYTRACING_SHADER_CONFIG shaderConfig_{};
    D3D12_RAYTRACING_PIPELINE_CONFIG pipelineConfig_{};
    D3D12_LOCAL_ROOT_SIGNATURE localRootSignature_{};
    D3D12_GLOBAL_ROOT_SIGNATURE globalRootSignature_{};
    D3D12_SUBOBJECT_TO_EXPORTS_ASSOCIATION association_{};
    std::vector<D3D12_STATE_SUBOBJECT> subobjects_;
    std::vector<std::string> tableNames_;
    D3D12_STATE_OBJECT_DESC desc_{};
};

}  // namespace caustics::rhi::d3d12
