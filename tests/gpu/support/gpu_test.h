#pragma once
// GoogleTest fixture of every GPU test: a Vulkan device (lavapipe in CI) with validation, including
// synchronization validation, on. Every WARNING or ERROR message is recorded and fails the test in
// TearDown, listing the messages. A device that cannot be created FAILS the test (never skips).
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "caustics/rhi/rhi.h"

namespace caustics::test_shaders {
// Embedded SPIR-V of tests/gpu/shaders/<name> (e.g. "rhi_core/pattern.comp"); empty if unknown.
std::span<const uint32_t> spirv(std::string_view name);
}  // namespace caustics::test_shaders

namespace caustics::test {

// SPIR-V of an embedded test shader as rhi::ShaderCode (debugName = name). Fails the current test
// (ADD_FAILURE) and returns empty code when no shader has that name.
rhi::ShaderCode testShader(std::string_view name);

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    // Validation messages (WARNING/ERROR) seen so far; the fixture fails the test if any remain.
    std::vector<std::string> validationMessages();
    // For tests that expect messages on purpose: forget the ones seen so far.
    void clearValidationMessages();

    // Host-readable buffer of `bytes` (CopyDest usage, Readback memory).
    rhi::BufferHandle createReadback(uint64_t bytes, std::string name = "readback");
    // Ends nothing: `cmd` must be recorded and end()ed. Submits it and waits; fails the test on error.
    void submitAndWait(const rhi::CommandListHandle& cmd);
    // Records with `record` into a new list, submits and waits.
    void runCommands(const std::function<void(rhi::ICommandList&)>& record);
    // Copies layer/mip of `texture` (currently in `state`) into host memory, tightly packed, and
    // leaves it in `state` again.
    std::vector<uint8_t> readTexture(const rhi::TextureHandle& texture,
                                     rhi::ResourceState state = rhi::ResourceState::CopySource, uint32_t layer = 0,
                                     uint32_t mip = 0);
    // Copies a host-visible buffer's content.
    std::vector<uint8_t> readBuffer(const rhi::BufferHandle& buffer, uint64_t bytes, uint64_t offset = 0);

    // DeviceDesc the fixture uses (validation on, ray tracing required, message counting).
    rhi::DeviceDesc makeDeviceDesc();

    rhi::DeviceHandle device;

private:
    struct Messages {
        std::mutex mutex;
        std::vector<std::string> list;
    };
    std::shared_ptr<Messages> messages_ = std::make_shared<Messages>();
};

}  // namespace caustics::test
