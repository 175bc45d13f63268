// The Vulkan backend's shader-table bytes: each record = group handle + local data at the offsets of
// computeShaderTableLayout; errors name the offending record.
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "vk_shader_table.h"

namespace caustics::rhi::vulkan {
namespace {

constexpr ShaderTableAlignment kNvidia{32, 32, 64, 4096};

// Fake 32-byte handles: every byte of the handle of a name is that name's first character.
struct FakeHandles {
    std::map<std::string, std::vector<uint8_t>> handles;
    FakeHandles(std::initializer_list<std::string> names) {
        for (const std::string& n : names) handles[n] = std::vector<uint8_t>(32, uint8_t(n[0]));
    }
    const uint8_t* operator()(const std::string& name) const {
        auto it = handles.find(name);
        return it == handles.end() ? nullptr : it->second.data();
    }
};

std::vector<uint8_t> bytesOf(uint32_t v) {
    std::vector<uint8_t> b(4);
    std::memcpy(b.data(), &v, 4);
    return b;
}

TEST(VulkanShaderTableImage, RecordsHoldHandleThenLocalDataAtLayoutOffsets) {
    FakeHandles handles{"rayGen", "miss", "groupA", "Bgroup"};
    ShaderTableDesc desc;
    desc.setRayGen("rayGen").addMiss("miss").addHitGroup("groupA", bytesOf(11)).addHitGroup("Bgroup", bytesOf(22));
    auto image = buildShaderTableImage(desc, kNvidia, 4, handles);
    ASSERT_TRUE(image) << image.message();
    const ShaderTableLayout& l = image->layout;
    EXPECT_EQ(l.hitGroup.stride, 64u);
    ASSERT_EQ(image->bytes.size(), l.totalBytes);
    EXPECT_EQ(image->bytes[l.rayGen.offset], uint8_t('r'));
    EXPECT_EQ(image->bytes[l.miss.offset + 31], uint8_t('m'));
    const uint8_t* second = image->bytes.data() + l.hitGroup.offset + l.hitGroup.stride;
    EXPECT_EQ(second[0], uint8_t('B'));
    uint32_t value = 0;
    std::memcpy(&value, second + 32, 4);
    EXPECT_EQ(value, 22u);
    std::memcpy(&value, image->bytes.data() + l.hitGroup.offset + 32, 4);
    EXPECT_EQ(value, 11u);
}

TEST(VulkanShaderTableImage, LocalDataAboveDeclaredSizeIsAnErrorNamingTheRecord) {
    FakeHandles handles{"rayGen", "groupA"};
    ShaderTableDesc desc;
    desc.setRayGen("rayGen").addHitGroup("groupA", std::vector<uint8_t>(12, 0));
    auto image = buildShaderTableImage(desc, kNvidia, 8, handles);
    ASSERT_FALSE(image);
    EXPECT_NE(image.message().find("groupA"), std::string::npos) << image.message();
    EXPECT_NE(image.message().find("12"), std::string::npos) << image.message();
}

TEST(VulkanShaderTableImage, UnknownNameIsAnErrorNamingIt) {
    FakeHandles handles{"rayGen"};
    ShaderTableDesc desc;
    desc.setRayGen("rayGen").addCallable("ghost");
    auto image = buildShaderTableImage(desc, kNvidia, 0, handles);
    ASSERT_FALSE(image);
    EXPECT_NE(image.message().find("ghost"), std::string::npos) << image.message();
}

TEST(VulkanShaderTableImage, StrideOverDeviceMaximumIsAnError) {
    FakeHandles handles{"rayGen", "miss"};
    ShaderTableDesc desc;
    desc.setRayGen("rayGen").addMiss("miss", std::vector<uint8_t>(5000, 1));
    EXPECT_FALSE(buildShaderTableImage(desc, kNvidia, 8192, handles));
}

}  // namespace
}  // namespace caustics::rhi::vulkan
