// On a machine without the D3D12 runtime (native Linux, CI), asking for the d3d12 backend must fail
// with a message that names the missing library and where to get it, and must not crash.
#include <gtest/gtest.h>

#include <filesystem>

#include "caustics/rhi/device.h"

namespace caustics::rhi {
namespace {

TEST(D3D12CreateDevice, FailsCleanlyNamingTheRuntimeLibraryWhereItIsMissing) {
    if (std::filesystem::exists("/usr/lib/wsl/lib/libd3d12.so"))
        GTEST_SKIP() << "WSL2 with a D3D12 runtime: this test is for machines without one";
    DeviceDesc desc;
    desc.backend = Backend::D3D12;
    auto device = createDevice(desc);
    ASSERT_FALSE(device.ok());
    EXPECT_NE(device.message().find("libd3d12.so"), std::string::npos) << device.message();
    EXPECT_NE(device.message().find("d3d12.dll"), std::string::npos) << device.message();
    EXPECT_NE(device.message().find("--backend vulkan"), std::string::npos) << device.message();
}

}  // namespace
}  // namespace caustics::rhi
