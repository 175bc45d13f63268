#include "shader_table_image.h"

#include <algorithm>
#include <cstring>

namespace caustics::rhi::d3d12 {

ShaderTableAlignment d3d12ShaderTableAlignment() {
    return {D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES, D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT,
            D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT, D3D12_RAYTRACING_MAX_SHADER_RECORD_STRIDE};
}

namespace {
uint32_t maxData(const std::vector<ShaderRecord>& records) {
    size_t m = 0;
    for (const ShaderRecord& r : records) m = std::max(m, r.localData.size());
    return uint32_t(m);
}
}  // namespace

Result<ShaderTableImage> buildShaderTableImage(const ShaderTableDesc& desc, uint32_t localDataBytes,
                                               const IdentifierLookup& identifierOf) {
    auto tableError = [&](const std::string& what) {
        return makeError("d3d12 shader table '" + desc.debugName + "': " + what);
    };
    if (desc.rayGen.exportName.empty()) return tableError("no ray-generation record");
    ShaderTableCounts counts;
    counts.missCount = uint32_t(desc.missRecords.size());
    counts.hitGroupCount = uint32_t(desc.hitGroupRecords.size());
    counts.callableCount = uint32_t(desc.callableRecords.size());
    // Strides follow the state object's declared local data so that every record matches the local
    // root signature, even records that carry fewer bytes.
    counts.rayGenDataBytes = std::max<uint32_t>(localDataBytes, uint32_t(desc.rayGen.localData.size()));
    counts.missDataBytes = std::max(localDataBytes, maxData(desc.missRecords));
    counts.hitGroupDataBytes = std::max(localDataBytes, maxData(desc.hitGroupRecords));
    counts.callableDataBytes = std::max(localDataBytes, maxData(desc.callableRecords));

    ShaderTableImage image;
    if (!computeShaderTableLayout(d3d12ShaderTableAlignment(), counts, image.layout))
        return tableError("a record is larger than D3D12's 4096-byte stride limit");
    image.bytes.assign(image.layout.totalBytes, 0);

    auto writeRegion = [&](const ShaderTableRegion& region, const ShaderRecord* records, size_t n) -> Status {
        for (size_t i = 0; i < n; ++i) {
            const ShaderRecord& r = records[i];
            if (r.localData.size() > localDataBytes)
                return tableError("record '" + r.exportName + "' carries " + std::to_string(r.localData.size()) +
                                  " bytes of local data, the state object allows " + std::to_string(localDataBytes));
            std::vector<uint8_t> id = identifierOf(r.exportName);
            if (id.size() != D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES)
                return tableError("'" + r.exportName + "' is not an export or hit group of the state object");
            uint8_t* dst = image.bytes.data() + region.offset + region.stride * i;
            std::memcpy(dst, id.data(), id.size());
            if (!r.localData.empty()) std::memcpy(dst + id.size(), r.localData.data(), r.localData.size());
        }
        return okStatus();
    };
    CAUSTICS_CHECK(writeRegion(image.layout.rayGen, &desc.rayGen, 1));
    CAUSTICS_CHECK(writeRegion(image.layout.miss, desc.missRecords.data(), desc.missRecords.size()));
    CAUSTICS_CHECK(writeRegion(image.layout.hitGroup, desc.hitGroupRecords.data(), desc.hitGroupRecords.size()));
    CAUSTICS_CHECK(writeRegion(image.layout.callable, desc.callableRecords.data(), desc.callableRecords.size()));
    return image;
}

D3D12_DISPATCH_RAYS_DESC makeDispatchRaysDesc(const ShaderTableLayout& layout, uint64_t baseAddress, uint32_t width,
                                              uint32_t height, uint32_t depth) {
    auto range = [&](const ShaderTableRegion& r) {
        return D3D12_GPU_VIRTUAL_ADDRESS_RANGE_AND_STRIDE{r.count ? baseAddress + r.offset : 0, r.size, r.stride};
    };
    D3D12_DISPATCH_RAYS_DESC d{};
    d.RayGenerationShaderRecord = {baseAddress + layout.rayGen.offset, layout.rayGen.size};
    d.MissShaderTable = range(layout.miss);
    d.HitGroupTable = range(layout.hitGroup);
    d.CallableShaderTable = range(layout.callable);
    d.Width = width;
    d.Height = height;
    d.Depth = depth;
    return d;
}

}  // namespace caustics::rhi::d3d12
