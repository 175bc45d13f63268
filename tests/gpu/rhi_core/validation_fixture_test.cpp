// The fixture must see synchronization hazards: a copy that reads a buffer right after a fill wrote
// it, with no barrier in between, is a read-after-write hazard that synchronization validation reports.
#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

TEST_F(GpuTest, MissingBarrierIsReportedBySynchronizationValidation) {
    auto buffer = device->createBuffer(BufferDesc().setByteSize(256).setDebugName("hazard"));
    ASSERT_TRUE(buffer.ok());
    BufferHandle readback = createReadback(256);
    runCommands([&](ICommandList& cmd) {
        cmd.fillBuffer(buffer.value(), 1u);
        cmd.copyBuffer(readback, 0, buffer.value(), 0, 256);   // no barrier: hazard on purpose
    });
    std::vector<std::string> seen = validationMessages();
    bool hazard = false;
    for (const std::string& m : seen) hazard = hazard || m.find("SYNC-HAZARD") != std::string::npos;
    EXPECT_TRUE(hazard) << "expected a SYNC-HAZARD message, got " << seen.size() << " message(s)";
    clearValidationMessages();   // expected messages must not fail the test in TearDown
}

}  // namespace
}  // namespace caustics::test
