// The HLSL float compare-and-swap accumulation never drops a contribution silently: each give-up is
// counted in the stats buffer at kStatAccumulationGiveUps (caustic_passes.h) and causticStatsWarnings
// reports it to the host. The stats slots are named once, for the shaders and C++ alike.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "caustics/caustic_passes.h"
#include "caustics/hlsl_sources.h"

namespace caustics {
namespace {

// The files that define a statistics slot (`kStat<Name> =`) among the shader sources: the slots are
// named once, in shaders/common/caustic_stats.h, which caustic_passes.h includes too.
std::vector<std::string> filesDefiningStatSlots() {
    namespace fs = std::filesystem;
    static const std::regex definition("\\bkStat\\w+\\s*=");
    std::vector<std::string> found;
    const fs::path root(CAUSTICS_SOURCE_DIR);
    for (const char* dir : {"shaders", "passes"})
        for (const auto& f : fs::recursive_directory_iterator(root / dir)) {
            if (!f.is_regular_file() || f.path().extension() == ".cpp") continue;
            std::ifstream in(f.path());
            std::ostringstream text;
            text << in.rdbuf();
            if (std::regex_search(text.str(), definition)) found.push_back(fs::relative(f.path(), root).generic_string());
        }
    return found;
}

TEST(AccumulationGiveUps, StatsSlotsAreNamedOnceForShadersAndCpp) {
    EXPECT_EQ(filesDefiningStatSlots(), std::vector<std::string>{"shaders/common/caustic_stats.h"});
    // C++ reads the same constants (caustic_passes.h: using shader::kStat...).
    static_assert(&kStatAccumulationGiveUps == &shader::kStatAccumulationGiveUps);
    static_assert(&kStatSphereCapacity == &shader::kStatSphereCapacity);
    // The HLSL the D3D12 backend compiles carries them (the embedder inlines the header).
    for (const char* name : {"forward_trace/forward.rgen", "backward_trace/backward.rgen"})
        EXPECT_NE(std::string(hlsl::source(name)).find("kStatAccumulationGiveUps = kStatForwardSegments + 4u"),
                  std::string::npos)
            << name;
}

TEST(AccumulationGiveUps, FloatCompareExchangeLoopCountsEachGiveUp) {
    // Both users of the float loop: the forward splat and the gather's any-hit.
    for (const char* name : {"forward_trace/forward.rgen", "backward_trace/gather.rahit"}) {
        const std::string text(hlsl::source(name));
        ASSERT_FALSE(text.empty()) << name;
        EXPECT_NE(text.find("InterlockedCompareExchange"), std::string::npos) << name << " is the float variant";
        // The loop reports whether it stored (shaders/common/radiance_atomics.h), and a failure is counted.
        EXPECT_TRUE(std::regex_search(text, std::regex("stored = original == expected;[^}]*\\}\\s*return stored;")))
            << name << ": the loop must report a value it could not store";
        EXPECT_TRUE(std::regex_search(text, std::regex("if \\(!radianceFloatAdd\\([^;]*\\)\\) statsAtomicAdd\\(kStatAccumulationGiveUps, 1u\\)")))
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
