#pragma once
// Memory sizes of transient resources. The compiler asks this interface instead of a device so that
// compilation (and aliasing) is testable without a GPU; DeviceMemorySizer forwards to the device.
#include "caustics/rhi/device.h"
#include "caustics/rhi/resources.h"

namespace caustics::rg {

class IMemorySizer {
public:
    virtual ~IMemorySizer() = default;
    virtual rhi::MemoryRequirements requirements(const rhi::TextureDesc& desc) const = 0;
    virtual rhi::MemoryRequirements requirements(const rhi::BufferDesc& desc) const = 0;
};

class DeviceMemorySizer final : public IMemorySizer {
public:
    explicit DeviceMemorySizer(rhi::IDevice& device) : device_(device) {}
    rhi::MemoryRequirements requirements(const rhi::TextureDesc& desc) const override {
        return device_.memoryRequirements(desc);
    }
    rhi::MemoryRequirements requirements(const rhi::BufferDesc& desc) const override {
        return device_.memoryRequirements(desc);
    }

private:
    rhi::IDevice& device_;
};

}  // namespace caustics::rg
