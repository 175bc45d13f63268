#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "camera_setup.h"
#include "settings_fields.h"
#include "viewer_script.h"

namespace caustics::sample {
namespace {

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

TEST(SettingsFields, SetsAFieldByItsMemberName) {
    CausticsSettings s;
    ASSERT_TRUE(setSettingsField(s, "exposure", "4"));
    EXPECT_FLOAT_EQ(s.exposure, 4.0f);
    ASSERT_TRUE(setSettingsField(s, "aov", "caustics"));
    EXPECT_EQ(s.aov, CausticsAov::Caustics);
    ASSERT_TRUE(setSettingsField(s, "filter", "off"));
    EXPECT_FALSE(s.filter);
}

TEST(SettingsFields, UnknownFieldIsNamedWithTheAcceptedOnes) {
    CausticsSettings s;
    Status st = setSettingsField(s, "exposrue", "4");
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("unknown CausticsSettings field 'exposrue'"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("exposure"), std::string::npos);
}

TEST(SettingsFields, InvalidValueLeavesTheSettingsUnchanged) {
    CausticsSettings s;
    Status st = setSettingsField(s, "mapResolution", "0");   // refused by CausticsSettings::validate
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("mapResolution"), std::string::npos) << st.message();
    EXPECT_EQ(s.mapResolution, CausticsSettings{}.mapResolution);
    EXPECT_FALSE(setSettingsField(s, "seed", "4294967297"));
}

TEST(ViewerScript, CommandsAreOrderedByFrameAndKeepFileOrderWithinAFrame) {
    auto script = parseScript("# comment\n5 quit\n2 set exposure 2\n2 screenshot a.png  # trailing comment\n", "s.txt");
    ASSERT_TRUE(script) << script.message();
    ASSERT_EQ(script->commands.size(), 3u);
    EXPECT_EQ(script->commands[0].words[0], "set");
    EXPECT_EQ(script->commands[1].words[0], "screenshot");
    EXPECT_EQ(script->commands[2].frame, 5u);
    EXPECT_EQ(script->commands[1].where, "s.txt:4");
}

TEST(ViewerScript, UnknownCommandNamesTheFileAndLine) {
    auto script = parseScript("1 set exposure 2\n3 zoom 2\n", "s.txt");
    ASSERT_FALSE(script);
    EXPECT_NE(script.message().find("s.txt:2: unknown command 'zoom'"), std::string::npos) << script.message();
}

TEST(ViewerScript, WrongArgumentCountIsRefused) {
    auto script = parseScript("1 set exposure\n", "s.txt");
    ASSERT_FALSE(script);
    EXPECT_NE(script.message().find("'set' takes 2 arguments, got 1"), std::string::npos) << script.message();
}

TEST(CameraSetup, LookingStraightDownGetsAnUpThatIsNotParallel) {
    glm::vec3 forward{0.0f, -1.0f, 0.0f};
    glm::vec3 up = robustUp(forward, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_GT(glm::length(glm::cross(forward, up)), 0.99f);
    EXPECT_TRUE(finiteMatrix(glm::lookAtRH(glm::vec3(0, 3, 0), glm::vec3(0), up)));
    EXPECT_EQ(robustUp(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)), glm::vec3(0, 1, 0));   // the usual case is untouched
}

TEST(CameraSetup, FarCameraClipPlanesContainTheWholeScene) {
    SceneBounds b;
    b.min = glm::vec3(-1.0f);
    b.max = glm::vec3(1.0f);
    b.empty = false;
    scene::Camera c;
    c.eye = {0.0f, 0.0f, 400.0f};
    c.target = glm::vec3(0.0f);
    fitClipPlanes(c, b);
    EXPECT_GE(c.farPlane, 400.0f + std::sqrt(3.0f));   // the farthest corner of the box
    EXPECT_LT(c.nearPlane, 400.0f - std::sqrt(3.0f));  // the nearest one
    EXPECT_LE(c.farPlane / c.nearPlane, 1e5f + 1.0f);
    scene::Camera close;   // a camera inside a small scene keeps its defaults
    fitClipPlanes(close, b);
    EXPECT_FLOAT_EQ(close.nearPlane, scene::Camera{}.nearPlane);
    EXPECT_FLOAT_EQ(close.farPlane, scene::Camera{}.farPlane);
}

TEST(CameraSetup, SceneWithoutCamerasIsFramedWhole) {
    SceneBounds b;
    b.min = glm::vec3(100.0f, 0.0f, 100.0f);
    b.max = glm::vec3(140.0f, 10.0f, 120.0f);
    b.empty = false;
    scene::Camera c = framingCamera(b, 0.785398f);
    EXPECT_EQ(c.target, b.centre());
    // The bounding sphere fits inside the vertical field of view.
    EXPECT_GE(glm::length(c.eye - c.target) * std::sin(0.5f * c.verticalFovRadians), b.radius());
}

}  // namespace
}  // namespace caustics::sample
