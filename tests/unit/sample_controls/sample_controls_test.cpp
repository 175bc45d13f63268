// caustics-sponza's sample controls: parsed values, and every bad value refused with a message that
// names the option and its range (samples/sponza/sample_controls.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "caustics/caustics_settings.h"
#include "cli_options.h"

namespace caustics::sample {
namespace {

Result<CliOptions> parse(std::vector<std::string> args) {
    args.insert(args.begin(), "caustics-sponza");
    return parseCliOptions(args);
}

void expectRefused(std::vector<std::string> args, const std::string& mentions) {
    auto r = parse(args);
    ASSERT_FALSE(r.ok()) << "accepted: " << args[0] << " " << (args.size() > 1 ? args[1] : "");
    EXPECT_NE(r.message().find(mentions), std::string::npos) << r.message();
}

TEST(SampleControls, DefaultsMatchCausticsSettings) {
    auto r = parse({});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->controls.seed, 1u);
    EXPECT_EQ(r->controls.accumulate, 0u);
    EXPECT_FLOAT_EQ(r->controls.sphereRadiusScale, CausticsSettings{}.sphereRadiusScale);
    EXPECT_FLOAT_EQ(r->controls.sphereRadiusScale, 0.75f);
    EXPECT_EQ(r->controls.sphereRadiusPolicy, SphereRadiusChoice::Pixel);
    EXPECT_FLOAT_EQ(r->controls.sphereWorldRadius, 0.01f);
}

TEST(SampleControls, ParsesEveryControl) {
    auto r = parse({"--seed", "4294967295", "--accumulate", "16", "--sphere-radius-policy", "world",
                    "--sphere-world-radius", "0.02", "--sphere-radius-scale", "3.5"});
    ASSERT_TRUE(r.ok()) << r.message();
    EXPECT_EQ(r->controls.seed, 4294967295u);
    EXPECT_EQ(r->controls.accumulate, 16u);
    EXPECT_EQ(r->controls.sphereRadiusPolicy, SphereRadiusChoice::World);
    EXPECT_FLOAT_EQ(r->controls.sphereWorldRadius, 0.02f);
    EXPECT_FLOAT_EQ(r->controls.sphereRadiusScale, 3.5f);
}

// The second type is filtered apart, on its own guides, unless asked merged (CausticsSettings' default).
TEST(SampleControls, SecondTypeFilteredApartUnlessAskedMerged) {
    auto plain = parse({});
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain->filterSecondTypeApart, CausticsSettings{}.filterSecondTypeApart);
    EXPECT_TRUE(plain->filterSecondTypeApart);
    auto merged = parse({"--filter-second-type", "merged"});
    ASSERT_TRUE(merged.ok()) << merged.message();
    EXPECT_FALSE(merged->filterSecondTypeApart);
    auto apart = parse({"--filter-second-type", "apart"});
    ASSERT_TRUE(apart.ok()) << apart.message();
    EXPECT_TRUE(apart->filterSecondTypeApart);
    auto earlier = parse({"--filter-second-type-apart"});
    ASSERT_TRUE(earlier.ok()) << earlier.message();
    EXPECT_TRUE(earlier->filterSecondTypeApart);
    expectRefused({"--filter-second-type", "both"}, "--filter-second-type: expected apart or merged");
}

TEST(SampleControls, RefusesBadValuesNamingTheOptionAndRange) {
    expectRefused({"--seed", "-1"}, "--seed");
    expectRefused({"--seed", "4294967296"}, "--seed");
    expectRefused({"--accumulate", "0"}, "--accumulate: 0 is outside [1, 4096]");
    expectRefused({"--accumulate", "4097"}, "[1, 4096]");
    expectRefused({"--accumulate", "two"}, "not a whole number");
    expectRefused({"--sphere-radius-scale", "0"}, "--sphere-radius-scale: 0 is outside (0, 64]");
    expectRefused({"--sphere-radius-scale", "65"}, "(0, 64]");
    expectRefused({"--sphere-radius-scale", "nan"}, "not a number");
    expectRefused({"--sphere-radius-policy", "screen"}, "not pixel or world");
    expectRefused({"--sphere-radius-policy", "world", "--sphere-world-radius", "-0.1"}, "(0, 1000]");
    expectRefused({"--seed"}, "--seed: missing value");
}

TEST(SampleControls, RefusesCombinationsThatCannotWork) {
    expectRefused({"--sphere-world-radius", "0.02"}, "only used with --sphere-radius-policy world");
    expectRefused({"--accumulate", "4", "--frames", "4"}, "leave out --frames");
    expectRefused({"--accumulate", "4", "--window"}, "cannot be used with --window");
}

// --set FIELD=VALUE: any CausticsSettings field by its name, kept in order for main to apply last; a
// name that is no field, a value of the wrong form or text without '=' is refused naming it.
TEST(SampleControls, SetTakesAnySettingsFieldByName) {
    auto r = parse({"--set", "atrousIterations=0", "--set", "filterPoolTiles=4096", "--set", "atrousIterations=2"});
    ASSERT_TRUE(r.ok()) << r.message();
    ASSERT_EQ(r->settingFields.size(), 3u);
    EXPECT_EQ(r->settingFields[0], (std::pair<std::string, std::string>{"atrousIterations", "0"}));
    EXPECT_EQ(r->settingFields[1], (std::pair<std::string, std::string>{"filterPoolTiles", "4096"}));
    EXPECT_EQ(r->settingFields[2].second, "2");
    expectRefused({"--set", "atrous=1"}, "unknown CausticsSettings field 'atrous'");
    expectRefused({"--set", "atrousIterations=two"}, "atrousIterations");
    expectRefused({"--set", "atrousIterations"}, "expected FIELD=VALUE");
    expectRefused({"--set", "=1"}, "expected FIELD=VALUE");
    expectRefused({"--set"}, "--set: missing value");
}

TEST(SampleControls, UsageListsTheControls) {
    std::string usage = cliUsage();
    for (const char* option : {"--seed", "--accumulate", "--sphere-radius-policy", "--sphere-radius-scale",
                               "--sphere-world-radius", "--reference", "--window", "--set"})
        EXPECT_NE(usage.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace caustics::sample
