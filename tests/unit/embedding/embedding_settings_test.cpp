// Settings an embedding host sets (caustics_settings.h) and the host G-buffer requirements
// (gbuffer.h): what is required follows what the configured passes read.
#include <gtest/gtest.h>

#include "caustics/caustics_settings.h"
#include "caustics/gbuffer.h"

namespace caustics {
namespace {

TEST(EmbeddingSettings, FramesInFlightOutsideOneToSixteenIsRefusedNamingTheField) {
    CausticsSettings s;
    s.framesInFlight = 0;
    Status st = s.validate();
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("framesInFlight"), std::string::npos) << st.message();
    s.framesInFlight = 17;
    EXPECT_FALSE(s.validate());
    s.framesInFlight = 5;
    EXPECT_TRUE(s.validate());
}

TEST(HostGBufferRequirements, CausticsOnlyWithoutFilterOrSecondTypeNeedsOnlyDepthAndIds) {
    CausticsSettings s;
    s.causticsOnly = true;
    s.filter = false;
    s.secondType = false;
    HostGBufferRequirements r = hostGBufferRequirements(s);
    EXPECT_FALSE(r.normalRoughness);
    EXPECT_FALSE(r.albedoMetallic);
    EXPECT_FALSE(r.optics);
}

TEST(HostGBufferRequirements, FilterNeedsNormalsAndSecondTypeNeedsOptics) {
    CausticsSettings s;
    s.causticsOnly = true;
    HostGBufferRequirements r = hostGBufferRequirements(s);
    EXPECT_TRUE(r.normalRoughness);
    EXPECT_TRUE(r.optics);
    EXPECT_FALSE(r.albedoMetallic) << "albedo is read only by our direct lighting and composite";
}

TEST(HostGBufferRequirements, FullPipelineNeedsEveryChannelButDepth) {
    HostGBufferRequirements r = hostGBufferRequirements(CausticsSettings{});
    EXPECT_TRUE(r.normalRoughness);
    EXPECT_TRUE(r.albedoMetallic);
    EXPECT_TRUE(r.optics);
}

}  // namespace
}  // namespace caustics
