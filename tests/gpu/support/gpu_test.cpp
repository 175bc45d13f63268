#include "gpu_test.h"

#include <algorithm>
#include <cstring>

namespace caustics::test {
using namespace rhi;

ShaderCode testShader(std::string_view name) {
    ShaderCode code;
    code.kind = ShaderCodeKind::SPIRV;
    code.debugName = std::string(name);
    std::span<const uint32_t> words = test_shaders::spirv(name);
    if (words.empty()) {
        ADD_FAILURE() << "no embedded test shader named '" << name << "' (tests/gpu/shaders/...)";
        return code;
    }
    code.bytes.resize(words.size_bytes());
    std::memcpy(code.bytes.data(), words.data(), words.size_bytes());
    return code;
}

DeviceDesc GpuTest::makeDeviceDesc() {
    DeviceDesc desc;
    desc.backend = Backend::Vulkan;
    desc.enableValidation = true;
    desc.requireRayTracing = true;
    std::shared_ptr<Messages> messages = messages_;
    desc.validationCallback = [messages](LogLevel level, std::string_view text) {
        if (level == LogLevel::Warning || level == LogLevel::Error) {
            std::lock_guard lock(messages->mutex);
            messages->list.emplace_back(std::string(level == LogLevel::Error ? "ERROR: " : "WARNING: ") +
                                        std::string(text));
        }
    };
    return desc;
}

void GpuTest::SetUp() {
    auto created = createDevice(makeDeviceDesc());
    ASSERT_TRUE(created.ok()) << "device creation failed: " << created.message();
    device = created.value();
}

void GpuTest::TearDown() {
    if (device) {
        (void)device->waitIdle();
        device.reset();   // destruction may report leaks or late errors too
    }
    std::vector<std::string> seen = validationMessages();
    if (!seen.empty()) {
        std::string all;
        for (const std::string& m : seen) all += "\n  " + m;
        ADD_FAILURE() << seen.size() << " validation message(s):" << all;
    }
}

std::vector<std::string> GpuTest::validationMessages() {
    std::lock_guard lock(messages_->mutex);
    return messages_->list;
}

void GpuTest::clearValidationMessages() {
    std::lock_guard lock(messages_->mutex);
    messages_->list.clear();
}

BufferHandle GpuTest::createReadback(uint64_t bytes, std::string name) {
    auto b = device->createBuffer(BufferDesc()
                                      .setByteSize(bytes)
                                      .setUsage(BufferUsage::CopyDest)
                                      .setMemory(MemoryType::Readback)
                                      .setDebugName(std::move(name)));
    EXPECT_TRUE(b.ok()) << (b.ok() ? "" : b.message());
    return b.ok() ? b.value() : nullptr;
}

void GpuTest::submitAndWait(const CommandListHandle& cmd) {
    auto fence = device->submit(cmd);
    ASSERT_TRUE(fence.ok()) << fence.message();
    auto waited = device->waitForFence(fence.value());
    ASSERT_TRUE(waited.ok()) << waited.message();
}

void GpuTest::runCommands(const std::function<void(ICommandList&)>& record) {
    auto cmd = device->createCommandList();
    ASSERT_TRUE(cmd.ok()) << cmd.message();
    cmd.value()->begin();
    record(*cmd.value());
    cmd.value()->end();
    submitAndWait(cmd.value());
}

std::vector<uint8_t> GpuTest::readTexture(const TextureHandle& texture, ResourceState state, uint32_t layer,
                                          uint32_t mip) {
    const TextureDesc& d = texture->desc();
    const uint64_t bytes = uint64_t(std::max(1u, d.width >> mip)) * std::max(1u, d.height >> mip) *
                           formatInfo(d.format).bytesPerPixel;
    BufferHandle readback = createReadback(bytes, d.debugName + " readback");
    if (!readback) return {};
    runCommands([&](ICommandList& cmd) {
        if (state != ResourceState::CopySource)
            cmd.barrier(TextureBarrier{texture, state, ResourceState::CopySource});
        cmd.copyTextureToBuffer(readback, 0, texture, layer, mip);
        if (state != ResourceState::CopySource)
            cmd.barrier(TextureBarrier{texture, ResourceState::CopySource, state});
    });
    return readBuffer(readback, bytes);
}

std::vector<uint8_t> GpuTest::readBuffer(const BufferHandle& buffer, uint64_t bytes, uint64_t offset) {
    std::vector<uint8_t> out(bytes);
    auto s = device->readBuffer(buffer, out.data(), bytes, offset);
    EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.message());
    return out;
}

}  // namespace caustics::test
