#pragma once
// Test double for memory sizes: tightly packed texels / the buffer's byte size, with a fixed
// alignment, so aliasing tests know every size without a device.
#include "caustics/render_graph/memory_sizer.h"
#include "caustics/rhi/format.h"

namespace caustics::rg::test {

class FakeMemorySizer final : public IMemorySizer {
public:
    explicit FakeMemorySizer(uint64_t alignment = 256) : alignment_(alignment) {}
    rhi::MemoryRequirements requirements(const rhi::TextureDesc& d) const override {
        uint64_t bytes = uint64_t(d.width) * d.height * d.arrayLayers * rhi::formatInfo(d.format).bytesPerPixel;
        return {bytes, alignment_};
    }
    rhi::MemoryRequirements requirements(const rhi::BufferDesc& d) const override { return {d.byteSize, alignment_}; }

private:
    uint64_t alignment_;
};

inline rhi::TextureDesc texDesc(uint32_t w = 64, uint32_t h = 64, rhi::Format f = rhi::Format::RGBA8_UNORM) {
    return rhi::TextureDesc().setSize(w, h).setFormat(f);
}

inline rhi::BufferDesc bufDesc(uint64_t bytes = 1024) { return rhi::BufferDesc().setByteSize(bytes); }

}  // namespace caustics::rg::test
