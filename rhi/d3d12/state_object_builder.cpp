#include "state_object_builder.h"

#include <map>

namespace caustics::rhi::d3d12 {
namespace {

caustics::Error soError(const StateObjectDesc& desc, const std::string& what) {
    return makeError("d3d12 state object '" + desc.debugName + "': " + what);
}

bool isAscii(const std::string& s) {
    for (unsigned char c : s)
        if (c == 0 || c > 127) return false;
    return true;
}

}  // namespace

const wchar_t* StateObjectBuilder::wide(const std::string& s) {
    // Export names are ASCII identifiers (checked in build), so widening byte by byte is exact.
    return strings_.emplace_back(s.begin(), s.end()).c_str();
}

D3D12_STATE_SUBOBJECT& StateObjectBuilder::add(D3D12_STATE_SUBOBJECT_TYPE type, const void* desc) {
    // Capacity is reserved up front: the association subobject points into this vector.
    return subobjects_.emplace_back(D3D12_STATE_SUBOBJECT{type, desc});
}

Status StateObjectBuilder::build(const StateObjectDesc& desc, const StateObjectInputs& inputs) {
    if (inputs.libraryBytecode.size() != desc.libraries.size())
        return soError(desc, "bytecode given for " + std::to_string(inputs.libraryBytecode.size()) +
                                 " libraries, the desc has " + std::to_string(desc.libraries.size()));
    if (!inputs.globalRootSignature) return soError(desc, "no global root signature");
    const uint32_t localBytes = desc.localBindings.localDataBytes;
    if (localBytes > 0 && !inputs.localRootSignature)
        return soError(desc, "localDataBytes > 0 but no local root signature");
    if (desc.maxAttributeBytes > D3D12_RAYTRACING_MAX_ATTRIBUTE_SIZE_IN_BYTES)
        return soError(desc, "maxAttributeBytes " + std::to_string(desc.maxAttributeBytes) + " exceeds DXR's 32");
    if (desc.maxRecursionDepth > D3D12_RAYTRACING_MAX_DECLARABLE_TRACE_RECURSION_DEPTH)
        return soError(desc, "maxRecursionDepth " + std::to_string(desc.maxRecursionDepth) + " exceeds DXR's 31");

    // Every name, with the stage it stands for (hit groups map to ShaderStage::None).
    std::map<std::string, ShaderStage> stages;
    for (const ShaderLibraryDesc& lib : desc.libraries)
        for (const ShaderExport& e : lib.exports) {
            if (e.name.empty() || !isAscii(e.name) || !isAscii(e.entryPoint))
                return soError(desc, "export names and entry points must be non-empty ASCII ('" + e.name + "')");
            if (!stages.emplace(e.name, e.stage).second) return soError(desc, "export '" + e.name + "' defined twice");
        }
    auto checkImport = [&](const HitGroupDesc& g, const std::string& name, ShaderStage stage) -> Status {
        if (name.empty()) return okStatus();
        auto it = stages.find(name);
        if (it == stages.end()) return soError(desc, "hit group '" + g.name + "' imports unknown export '" + name + "'");
        if (it->second != stage)
            return soError(desc, "hit group '" + g.name + "' uses export '" + name + "' of the wrong stage");
        return okStatus();
    };
    for (const HitGroupDesc& g : desc.hitGroups) {
        if (g.name.empty() || !isAscii(g.name)) return soError(desc, "hit group names must be non-empty ASCII");
        CAUSTICS_CHECK(checkImport(g, g.closestHit, ShaderStage::ClosestHit));
        CAUSTICS_CHECK(checkImport(g, g.anyHit, ShaderStage::AnyHit));
        CAUSTICS_CHECK(checkImport(g, g.intersection, ShaderStage::Intersection));
        if (g.type == HitGroupType::Procedural && g.intersection.empty())
            return soError(desc, "procedural hit group '" + g.name + "' has no intersection shader");
        if (g.type == HitGroupType::Triangles && !g.intersection.empty())
            return soError(desc, "triangle hit group '" + g.name + "' must not have an intersection shader");
    }
    for (const HitGroupDesc& g : desc.hitGroups)
        if (!stages.emplace(g.name, ShaderStage::None).second)
            return soError(desc, "hit group name '" + g.name + "' is already used");

    const size_t count = desc.libraries.size() + desc.hitGroups.size() + 3 + (localBytes > 0 ? 2 : 0);
    subobjects_.clear();
    subobjects_.reserve(count);
    tableNames_.clear();

    for (size_t i = 0; i < desc.libraries.size(); ++i) {
        const ShaderLibraryDesc& lib = desc.libraries[i];
        auto& exports = exports_.emplace_back();
        for (const ShaderExport& e : lib.exports) {
            const std::string& entry = e.entryPoint.empty() ? e.name : e.entryPoint;
            exports.push_back({wide(e.name), entry == e.name ? nullptr : wide(entry), D3D12_EXPORT_FLAG_NONE});
            if (hasAny(e.stage, ShaderStage::RayGen | ShaderStage::Miss | ShaderStage::Callable))
                tableNames_.push_back(e.name);
        }
        D3D12_DXIL_LIBRARY_DESC& l = libraries_.emplace_back();
        l.DXILLibrary = {inputs.libraryBytecode[i].data(), inputs.libraryBytecode[i].size()};
        l.NumExports = UINT(exports.size());
        l.pExports = exports.data();
        add(D3D12_STATE_SUBOBJECT_TYPE_DXIL_LIBRARY, &l);
    }
    for (const HitGroupDesc& g : desc.hitGroups) {
        D3D12_HIT_GROUP_DESC& h = hitGroups_.emplace_back();
        h.HitGroupExport = wide(g.name);
        h.Type = g.type == HitGroupType::Procedural ? D3D12_HIT_GROUP_TYPE_PROCEDURAL_PRIMITIVE
                                                    : D3D12_HIT_GROUP_TYPE_TRIANGLES;
        h.ClosestHitShaderImport = g.closestHit.empty() ? nullptr : wide(g.closestHit);
        h.AnyHitShaderImport = g.anyHit.empty() ? nullptr : wide(g.anyHit);
        h.IntersectionShaderImport = g.intersection.empty() ? nullptr : wide(g.intersection);
        add(D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP, &h);
        tableNames_.push_back(g.name);
    }
    shaderConfig_ = {desc.maxPayloadBytes, desc.maxAttributeBytes};
    add(D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_SHADER_CONFIG, &shaderConfig_);

    if (localBytes > 0) {
        localRootSignature_.pLocalRootSignature = inputs.localRootSignature;
        const D3D12_STATE_SUBOBJECT& local = add(D3D12_STATE_SUBOBJECT_TYPE_LOCAL_ROOT_SIGNATURE, &localRootSignature_);
        // Every record type carries local data; a hit-group association covers its shaders (DXR spec
        // "Subobject association behavior").
        associatedNames_.clear();
        for (const std::string& name : tableNames_) associatedNames_.push_back(wide(name));
        association_.pSubobjectToAssociate = &local;
        association_.NumExports = UINT(associatedNames_.size());
        association_.pExports = associatedNames_.data();
        add(D3D12_STATE_SUBOBJECT_TYPE_SUBOBJECT_TO_EXPORTS_ASSOCIATION, &association_);
    }
    globalRootSignature_.pGlobalRootSignature = inputs.globalRootSignature;
    add(D3D12_STATE_SUBOBJECT_TYPE_GLOBAL_ROOT_SIGNATURE, &globalRootSignature_);
    pipelineConfig_.MaxTraceRecursionDepth = desc.maxRecursionDepth;
    add(D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_PIPELINE_CONFIG, &pipelineConfig_);

    desc_.Type = D3D12_STATE_OBJECT_TYPE_RAYTRACING_PIPELINE;
    desc_.NumSubobjects = UINT(subobjects_.size());
    desc_.pSubobjects = subobjects_.data();
    return okStatus();
}

}  // namespace caustics::rhi::d3d12
