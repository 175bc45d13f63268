#pragma once
// Minimal stand-ins for host-owned RHI objects that a test imports into the graph; they only carry
// their desc (the graph never looks inside an imported object).
#include <memory>

#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/resources.h"

namespace caustics::rg::test {

class FakeTexture final : public rhi::ITexture {
public:
    explicit FakeTexture(rhi::TextureDesc d = {}) : desc_(std::move(d)) {}
    const rhi::TextureDesc& desc() const override { return desc_; }

private:
    rhi::TextureDesc desc_;
};

class FakeBuffer final : public rhi::IBuffer {
public:
    explicit FakeBuffer(rhi::BufferDesc d = {}) : desc_(std::move(d)) {}
    const rhi::BufferDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return 0; }
    void* mappedData() override { return nullptr; }

private:
    rhi::BufferDesc desc_;
};

class FakeAccelStruct final : public rhi::IAccelStruct {
public:
    const rhi::AccelStructDesc& desc() const override { return desc_; }
    uint64_t deviceAddress() const override { return 0; }
    uint64_t storageBytes() const override { return 0; }

private:
    rhi::AccelStructDesc desc_;
};

inline rhi::TextureHandle fakeTexture() { return std::make_shared<FakeTexture>(); }
inline rhi::BufferHandle fakeBuffer() { return std::make_shared<FakeBuffer>(); }
inline rhi::AccelStructHandle fakeAccelStruct() { return std::make_shared<FakeAccelStruct>(); }

}  // namespace caustics::rg::test
