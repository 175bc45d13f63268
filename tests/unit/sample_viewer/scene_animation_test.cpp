// The animation of the viewer and the headless sample (samples/sponza/scene_animation.h): poses are a
// pure function of the clocks, the glass moves as one rigid group, orbiting lights keep their aim.
#include <cmath>

#include <gtest/gtest.h>

#include "animation_options.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/mesh_utils.h"
#include "scene_animation.h"

namespace caustics::sample {
namespace {

constexpr float kQuarterPeriod = 0.25f * kAnimationPeriodSeconds;

scene::Scene tableScene() {
    auto scene = scene::makeBuiltin("builtin");
    EXPECT_TRUE(scene) << scene.message();
    return std::move(*scene);
}

TEST(SceneAnimation, PathStartsAtRestAndIsAPureTranslationAtAQuarterPeriod) {
    scene::Scene scene = tableScene();
    SceneAnimation a = SceneAnimation::capture(scene);
    EXPECT_EQ(a.glassCount(), 4u);   // glass shell, water, glass sphere, metal ring
    EXPECT_GT(a.pathRadius(), 0.1f);
    GroupPose rest = a.groupPose(0.0f);
    EXPECT_FLOAT_EQ(glm::length(rest.offset), 0.0f);
    EXPECT_FLOAT_EQ(rest.yawRadians, 0.0f);
    GroupPose quarter = a.groupPose(kQuarterPeriod);   // the tests' expected caustic shift rests on this
    EXPECT_NEAR(quarter.offset.x, a.pathRadius(), 1e-5f);
    EXPECT_NEAR(quarter.offset.z, 0.0f, 1e-5f);
    EXPECT_NEAR(quarter.yawRadians, 0.0f, 1e-5f);
}

TEST(SceneAnimation, ObjectsOnMovesOnlyTheGlassAsOneRigidGroup) {
    scene::Scene scene = tableScene();
    const scene::Scene rest = scene;
    SceneAnimation a = SceneAnimation::capture(scene);
    a.toggles.objects = true;
    a.advance(kQuarterPeriod);
    a.apply(scene, rest.lights);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        glm::vec3 moved = glm::vec3(scene.instances[i].transform[3] - rest.instances[i].transform[3]);
        if (scene::isSpecularInstance(rest, rest.instances[i]))
            EXPECT_NEAR(glm::length(moved - glm::vec3(a.pathRadius(), 0.0f, 0.0f)), 0.0f, 1e-5f) << i;
        else
            EXPECT_EQ(glm::length(moved), 0.0f) << "instance " << i << " is not glass and must not move";
    }
    a.toggles.objects = false;   // off: back to the rest pose
    a.apply(scene, rest.lights);
    for (size_t i = 0; i < scene.instances.size(); ++i) EXPECT_EQ(scene.instances[i].transform, rest.instances[i].transform);
}

TEST(SceneAnimation, OrbitingSpotKeepsItsHeightRadiusAndAim) {
    scene::Scene scene = tableScene();
    SceneAnimation a = SceneAnimation::capture(scene);
    const scene::Light& spot = scene.lights[0];
    glm::vec3 c = a.centre();
    // Where the spot's axis meets the horizontal plane through the centre: it must turn with the light.
    auto aimPoint = [&](const scene::Light& l) { return l.position + l.direction * ((c.y - l.position.y) / l.direction.y); };
    for (float seconds : {1.0f, kQuarterPeriod, 5.5f}) {
        scene::Light turned = a.orbitLight(spot, seconds);
        EXPECT_NEAR(turned.position.y, spot.position.y, 1e-5f);
        auto radius = [&](const glm::vec3& p) { return std::hypot(p.x - c.x, p.z - c.z); };
        EXPECT_NEAR(radius(turned.position), radius(spot.position), 1e-4f);
        EXPECT_NEAR(radius(aimPoint(turned)), radius(aimPoint(spot)), 1e-4f);
        EXPECT_NEAR(glm::length(turned.direction), 1.0f, 1e-5f);
    }
    scene::Light quarter = a.orbitLight(spot, kQuarterPeriod);   // +90 degrees about +Y: (x, z) -> (z, -x)
    EXPECT_NEAR(quarter.position.x - c.x, spot.position.z - c.z, 1e-4f);
    EXPECT_NEAR(quarter.position.z - c.z, -(spot.position.x - c.x), 1e-4f);
}

TEST(SceneAnimation, ClocksRunOnlyWhileTheirAnimationIsOnAndNotPaused) {
    SceneAnimation a = SceneAnimation::capture(tableScene());
    a.advance(1.0f);
    EXPECT_EQ(a.objectSeconds(), 0.0f);
    a.toggles.objects = true;
    a.toggles.speed = 2.0f;
    a.advance(1.0f);
    EXPECT_FLOAT_EQ(a.objectSeconds(), 2.0f);
    EXPECT_EQ(a.lightSeconds(), 0.0f);
    a.toggles.paused = true;
    a.advance(1.0f);
    EXPECT_FLOAT_EQ(a.objectSeconds(), 2.0f);
}

// True when `option value` was taken as an animation option (and parsed).
bool parsed(const std::string& option, const std::string& value, AnimationOptions& o) {
    auto r = parseAnimationOption(option, value, o);
    return r && r.value();
}

TEST(AnimationOptions, ListSpeedAndFramesAreParsedAndBadItemsNamed) {
    AnimationOptions o;
    ASSERT_TRUE(parsed("--animate", "objects,light:2", o));
    EXPECT_TRUE(o.toggles.objects);
    EXPECT_EQ(o.toggles.orbitingLights.count(2), 1u);
    ASSERT_TRUE(parsed("--animate-speed", "1.5", o));
    EXPECT_FLOAT_EQ(o.toggles.speed, 1.5f);
    auto bad = parseAnimationOption("--animate", "objects,wobble", o);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.message().find("'wobble' is not objects or light:N"), std::string::npos) << bad.message();
    EXPECT_FALSE(parseAnimationOption("--animate-speed", "0", o));
    auto other = parseAnimationOption("--frames", "3", o);
    ASSERT_TRUE(other);
    EXPECT_FALSE(other.value());   // not an animation option: the caller tries its own
}

TEST(AnimationOptions, FramesAreHeadlessAndDefaultToMovingTheGlass) {
    AnimationOptions o;
    o.frames = 4;
    Status windowed = finishAnimationOptions(o, true, false, 0);
    ASSERT_FALSE(windowed);
    EXPECT_NE(windowed.message().find("--animate-frames: renders headless"), std::string::npos);
    EXPECT_FALSE(finishAnimationOptions(o, false, true, 0));   // with --frames
    ASSERT_TRUE(finishAnimationOptions(o, false, false, 0));
    EXPECT_TRUE(o.toggles.objects);
    Status missing = checkAnimatedLights({.orbitingLights = {5}}, 3, "--animate");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.message().find("light 5 does not exist (the scene has 3 lights)"), std::string::npos);
}

TEST(AnimationOptions, FramePathNumbersEachFrame) {
    EXPECT_EQ(framePath("out/anim_{frame}.png", 7), "out/anim_0007.png");
    EXPECT_EQ(framePath("still.png", 7), "still.png");
}

}  // namespace
}  // namespace caustics::sample
