#include "d3d12_features.h"

#include <cstdlib>
#include <cstring>

namespace caustics::rhi::d3d12 {
namespace {

// The highest shader model the device takes: CheckFeatureSupport fails for models newer than the
// runtime knows, so ask from high to low (D3D12_FEATURE_DATA_SHADER_MODEL docs).
uint32_t highestShaderModel(ID3D12Device5* device) {
    for (D3D_SHADER_MODEL model : {D3D_SHADER_MODEL_6_6, D3D_SHADER_MODEL_6_5, D3D_SHADER_MODEL_6_4,
                                   D3D_SHADER_MODEL_6_3, D3D_SHADER_MODEL_6_0}) {
        D3D12_FEATURE_DATA_SHADER_MODEL data{model};
        if (succeeded(device->CheckFeatureSupport(D3D12_FEATURE_SHADER_MODEL, &data, sizeof(data))))
            return uint32_t(data.HighestShaderModel);
    }
    return 0;
}

}  // namespace

D3D12FeatureReport queryD3D12Features(ID3D12Device5* device) {
    D3D12FeatureReport report;
    D3D12_FEATURE_DATA_D3D12_OPTIONS5 o5{};
    if (succeeded(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS5, &o5, sizeof(o5))))
        report.raytracingTier = uint32_t(o5.RaytracingTier);
    report.highestShaderModel = highestShaderModel(device);
    D3D12_FEATURE_DATA_D3D12_OPTIONS o{};
    if (succeeded(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS, &o, sizeof(o))))
        report.typedUavLoadAdditionalFormats = o.TypedUAVLoadAdditionalFormats != FALSE;
    // A runtime older than Windows build 22000 does not know OPTIONS11 and fails the query: no wide atomics.
    D3D12_FEATURE_DATA_D3D12_OPTIONS11 o11{};
    if (succeeded(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS11, &o11, sizeof(o11))))
        report.atomicInt64OnDescriptorHeapResource = o11.AtomicInt64OnDescriptorHeapResourceSupported != FALSE;
    return report;
}

bool narrowFixedPointForced() {
    const char* v = std::getenv("CAUSTICS_FORCE_FIXED_POINT");
    return v && std::strcmp(v, "32") == 0;
}

}  // namespace caustics::rhi::d3d12
