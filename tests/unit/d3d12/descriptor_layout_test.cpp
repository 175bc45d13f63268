#include <gtest/gtest.h>

#include "descriptor_layout.h"

namespace caustics::rhi::d3d12 {
namespace {

BindingLayoutDesc forwardTraceBindings() {
    BindingLayoutDesc d;
    d.add(0, BindingType::ConstantBuffer)
        .add(0, BindingType::AccelStruct)
        .add(1, BindingType::SampledTexture, 4)
        .add(0, BindingType::StorageTexture)
        .add(0, BindingType::Sampler)
        .add(1, BindingType::StorageBufferRW);
    return d;
}

TEST(D3D12DescriptorLayout, ResourcesAndSamplersGoToSeparateTables) {
    auto l = computeDescriptorTableLayout(forwardTraceBindings());
    ASSERT_TRUE(l.ok()) << l.message();
    EXPECT_EQ(l->resourceDescriptorCount, 1u + 1u + 4u + 1u + 1u);
    EXPECT_EQ(l->samplerDescriptorCount, 1u);
}

TEST(D3D12DescriptorLayout, ItemsTakeConsecutiveOffsetsInDeclarationOrder) {
    auto l = computeDescriptorTableLayout(forwardTraceBindings());
    ASSERT_TRUE(l.ok());
    EXPECT_EQ(l->offsetOf(BindingType::ConstantBuffer, 0), 0u);
    EXPECT_EQ(l->offsetOf(BindingType::AccelStruct, 0), 1u);
    EXPECT_EQ(l->offsetOf(BindingType::SampledTexture, 1, 0), 2u);
    EXPECT_EQ(l->offsetOf(BindingType::SampledTexture, 1, 3), 5u);
    EXPECT_EQ(l->offsetOf(BindingType::StorageTexture, 0), 6u);
    EXPECT_EQ(l->offsetOf(BindingType::StorageBufferRW, 1), 7u);
    EXPECT_EQ(l->offsetOf(BindingType::Sampler, 0), 0u);   // first in the sampler table
}

TEST(D3D12DescriptorLayout, RegistersAreCountedPerClass) {
    auto l = computeDescriptorTableLayout(forwardTraceBindings());
    ASSERT_TRUE(l.ok());
    // t0 is the TLAS, an SRV like the sampled textures at t1..t4.
    EXPECT_EQ(l->items[1].registerClass, RegisterClass::Srv);
    EXPECT_EQ(l->items[3].registerClass, RegisterClass::Uav);
    EXPECT_EQ(l->offsetOf(BindingType::StorageBufferRO, 2), 3u);   // t2 = element 1 of the t1 array
}

TEST(D3D12DescriptorLayout, ArrayElementPastTheEndHasNoOffset) {
    auto l = computeDescriptorTableLayout(forwardTraceBindings());
    ASSERT_TRUE(l.ok());
    EXPECT_FALSE(l->offsetOf(BindingType::SampledTexture, 1, 4).has_value());
    EXPECT_FALSE(l->offsetOf(BindingType::ConstantBuffer, 5).has_value());
}

TEST(D3D12DescriptorLayout, OverlappingRegistersOfOneClassAreRefused) {
    BindingLayoutDesc d;
    d.add(0, BindingType::SampledTexture, 2).add(1, BindingType::StorageBufferRO);   // t0..t1 and t1
    auto l = computeDescriptorTableLayout(d);
    ASSERT_FALSE(l.ok());
    EXPECT_NE(l.message().find("t1"), std::string::npos);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
