#include "descriptor_layout.h"

#include <string>

namespace caustics::rhi::d3d12 {

RegisterClass registerClassOf(BindingType type) {
    switch (type) {
        case BindingType::ConstantBuffer: return RegisterClass::Cbv;
        case BindingType::StorageBufferRO:
        case BindingType::SampledTexture:
        case BindingType::AccelStruct: return RegisterClass::Srv;   // RaytracingAccelerationStructure is a t register
        case BindingType::StorageBufferRW:
        case BindingType::StorageTexture: return RegisterClass::Uav;
        case BindingType::Sampler: return RegisterClass::Sampler;
    }
    return RegisterClass::Cbv;
}

char registerLetter(RegisterClass c) {
    switch (c) {
        case RegisterClass::Cbv: return 'b';
        case RegisterClass::Srv: return 't';
        case RegisterClass::Uav: return 'u';
        case RegisterClass::Sampler: return 's';
    }
    return '?';
}

std::optional<uint32_t> DescriptorTableLayout::offsetOf(BindingType type, uint32_t slot, uint32_t arrayElement) const {
    const RegisterClass cls = registerClassOf(type);
    for (const DescriptorPlacement& p : items) {
        if (p.registerClass != cls || slot < p.slot || slot >= p.slot + p.arraySize) continue;
        // An array is addressed either by (slot, element) or by slot + element (HLSL registers).
        const uint32_t element = (slot - p.slot) + arrayElement;
        if (element >= p.arraySize) return std::nullopt;
        return p.heapOffset + element;
    }
    return std::nullopt;
}

Result<DescriptorTableLayout> computeDescriptorTableLayout(const BindingLayoutDesc& desc) {
    DescriptorTableLayout layout;
    for (const BindingLayoutItem& item : desc.items) {
        DescriptorPlacement p;
        p.slot = item.slot;
        p.type = item.type;
        p.registerClass = registerClassOf(item.type);
        p.arraySize = item.arraySize;
        if (p.arraySize == 0)
            return makeError("d3d12 binding layout: item at slot " + std::to_string(item.slot) + " has arraySize 0");
        for (const DescriptorPlacement& q : layout.items) {
            const bool overlap = q.registerClass == p.registerClass && p.slot < q.slot + q.arraySize &&
                                 q.slot < p.slot + p.arraySize;
            if (overlap)
                return makeError(std::string("d3d12 binding layout: register ") + registerLetter(p.registerClass) +
                                 std::to_string(p.slot) + " is bound twice");
        }
        uint32_t& counter =
            p.registerClass == RegisterClass::Sampler ? layout.samplerDescriptorCount : layout.resourceDescriptorCount;
        p.heapOffset = counter;
        counter += p.arraySize;
        layout.items.push_back(p);
    }
    return layout;
}

}  // namespace caustics::rhi::d3d12
