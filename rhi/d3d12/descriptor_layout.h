#pragma once
// Where each item of a binding layout lives in D3D12 descriptor heaps, device-free.
// A binding layout becomes up to two descriptor tables (D3D12 keeps samplers in their own heap):
// one CBV/SRV/UAV table and one sampler table. Items take consecutive heap offsets in declaration
// order, an array taking arraySize descriptors; a binding set writes its descriptors at these offsets
// in its CPU staging range, and the command list copies the range into the shader-visible ring.
#include <cstdint>
#include <optional>
#include <vector>

#include "caustics/rhi/binding.h"
#include "caustics/rhi/result.h"

namespace caustics::rhi::d3d12 {

// HLSL register classes: b (CBV), t (SRV), u (UAV), s (sampler).
enum class RegisterClass : uint8_t { Cbv, Srv, Uav, Sampler };
RegisterClass registerClassOf(BindingType type);
char registerLetter(RegisterClass c);

struct DescriptorPlacement {
    uint32_t slot = 0;          // register number within its class
    BindingType type = BindingType::ConstantBuffer;
    RegisterClass registerClass = RegisterClass::Cbv;
    uint32_t arraySize = 1;
    uint32_t heapOffset = 0;    // first descriptor, in the sampler table for samplers, else the resource table
};

struct DescriptorTableLayout {
    std::vector<DescriptorPlacement> items;   // in the binding layout's order
    uint32_t resourceDescriptorCount = 0;     // CBV/SRV/UAV table size
    uint32_t samplerDescriptorCount = 0;      // sampler table size

    // Heap offset of (type's register class, slot, element); nullopt if the layout has no such item.
    std::optional<uint32_t> offsetOf(BindingType type, uint32_t slot, uint32_t arrayElement = 0) const;
};

// Fails when two items of one register class overlap (slot .. slot + arraySize - 1) or an array is empty.
Result<DescriptorTableLayout> computeDescriptorTableLayout(const BindingLayoutDesc& desc);

}  // namespace caustics::rhi::d3d12
