// The HLSL float compare-and-swap accumulation never drops a contribution silently: each give-up is
// counted in the stats buffer at kStatAccumulationGiveUps (caustic_passes.h) and causticStatsWarnings
// reports it to the host. The shaders' copies of the stats slot numbers must equal the C++ ones.
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "caustics/caustic_passes.h"
#include "caustics/hlsl_sources.h"

namespace caustics {
namespace {

std::map<std::string, uint32_t> statSlots(const std::string& text) {
    std::map<std::string, uint32_t> slots;
    static const std::regex constant("\\b(kStat\\w+)\\s*=\\s*(\\d+)u");
    for (std::sregex_iterator it(text.begin(), text.end(), constant), end; it != end; ++it)
        slots[(*it)[1]] = uint32_t(std::stoul((*it)[2]));
    return slots;
}

void expectSlotsMatchCpp(const std::map<std::string, uint32_t>& slots, const std::string& where) {
    const std::map<std::string, uint32_t> cpp = {
        {"kStatStoredHitAttempts", kStatStoredHitAttempts}, {"kStatSplats", kStatSplats},
        {"kStatGatherHits", kStatGatherHits},               {"kStatSpheres", kStatSpheres},
        {"kStatRaysPerLight", kStatRaysPerLight},           {"kStatAccumulationGiveUps", kStatAccumulationGiveUps}};
    for (const auto& [name, value] : cpp) {
        auto it = slots.find(name);
        ASSERT_NE(it, slots.end()) << where << " does not declare " << name;
        EXPECT_EQ(it->second, value) << where << ": " << name << " differs from caustic_passes.h";
    }
}

TEST(AccumulationGiveUps, StatsSlotsOfHlslAndGlslEqualTheCppSlots) {
    expectSlotsMatchCpp(statSlots(std::string(hlsl::source("forward_trace/forward.rgen"))), "forward.rgen.hlsl");
    std::ifstream glsl(std::string(CAUSTICS_SOURCE_DIR) + "/shaders/vulkan/forward_trace/caustic_hit.glsl");
    std::ostringstream text;
    text << glsl.rdbuf();
    expectSlotsMatchCpp(statSlots(text.str()), "caustic_hit.glsl");
}

// The second type's cost slots (caustic_passes.h) as the backward shaders declare them.
TEST(AccumulationGiveUps, SecondTypeCostSlotsOfHlslAndGlslEqualTheCppSlots) {
    const std::map<std::string, uint32_t> cpp = {{"kStatSpecularPixels", kStatSpecularPixels},
                                                 {"kStatBackwardLaunches", kStatBackwardLaunches},
                                                 {"kStatSpheresDropped", kStatSpheresDropped},
                                                 {"kStatSphereCapacity", kStatSphereCapacity}};
    std::ifstream glsl(std::string(CAUSTICS_SOURCE_DIR) + "/shaders/vulkan/backward_trace/sphere_list.glsl");
    std::ostringstream text;
    text << glsl.rdbuf();
    for (const auto& [where, slots] :
         {std::pair{std::string("backward.rgen.hlsl"), statSlots(std::string(hlsl::source("backward_trace/backward.rgen")))},
          std::pair{std::string("sphere_list.glsl"), statSlots(text.str())}})
        for (const auto& [name, value] : cpp) {
            auto it = slots.find(name);
            ASSERT_NE(it, slots.end()) << where << " does not declare " << name;
            EXPECT_EQ(it->second, value) << where << ": " << name << " differs from caustic_passes.h";
        }
}

TEST(AccumulationGiveUps, FloatCompareExchangeLoopCountsEachGiveUp) {
    // Both users of the float loop: the forward splat and the gather's any-hit.
    for (const char* name : {"forward_trace/forward.rgen", "backward_trace/gather.rahit"}) {
        const std::string text(hlsl::source(name));
        ASSERT_FALSE(text.empty()) << name;
        EXPECT_NE(text.find("InterlockedCompareExchange"), std::string::npos) << name << " is the float variant";
        EXPECT_TRUE(std::regex_search(text, std::regex("if \\(!stored\\) stats\\.InterlockedAdd\\(4u \\* kStatAccumulationGiveUps")))
            << name << " must count contributions it could not store";
    }
}

TEST(AccumulationGiveUps, HostIsWarnedWithTheNumberDropped) {
    std::vector<uint32_t> stats(kStatCount, 0);
    CausticsSettings settings;
    EXPECT_TRUE(causticStatsWarnings(stats, settings).empty());
    stats[kStatAccumulationGiveUps] = 17;
    auto warnings = causticStatsWarnings(stats, settings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("17 caustic radiance contributions were dropped"), std::string::npos) << warnings[0];
}

TEST(AccumulationGiveUps, ShortStatsBufferFromAnOlderHostIsNotReadPastItsEnd) {
    std::vector<uint32_t> stats(kStatAccumulationGiveUps, 0);   // one slot short
    EXPECT_TRUE(causticStatsWarnings(stats, CausticsSettings{}).empty());
}

}  // namespace
}  // namespace caustics
