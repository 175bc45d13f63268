// Caster motion (docs/caustics.md "Moving casters"): the per-instance motion rows the module uploads
// (passes/caustic_maps/caster_motion.cpp) and the receiver shift and fixed-point words the forward pass
// accumulates (shaders/common/caster_motion.h, compiled as C++).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "caustic_maps/caustic_internal.h"
#include "caustics/scene/builtin_scenes.h"
#include "common/caster_motion.h"

namespace caustics {
namespace {

uint32_t specularInstance(const scene::Scene& s) {
    for (uint32_t i = 0; i < s.instances.size(); ++i)
        if (s.materials[s.meshes[s.instances[i].mesh].material].isSpecular()) return i;
    return 0;
}

glm::vec3 applyRows(const std::vector<glm::vec4>& rows, size_t instance, glm::vec3 p) {
    const glm::vec4 h(p, 1.0f);
    const size_t r = shader::kCasterMotionRowsPerInstance * instance;
    return {glm::dot(rows[r], h), glm::dot(rows[r + 1], h), glm::dot(rows[r + 2], h)};
}

// No rows on the first frame; a moved floor gets rows (the history of the pixels that show it follows
// it) but is no moving caster; a moved glass sphere is, with rows that take this frame's point to last
// frame's (the still floor's: to itself); a second view of the same frame sees the same; no rows once
// nothing moves.
TEST(CasterMotion, RowsTakeThisFramesPointToLastFramesWhenAnInstanceMoved) {
    scene::Scene s = scene::makeGlassSphereScene(scene::AnalyticSceneDesc{});
    const uint32_t glass = specularInstance(s);
    const uint32_t floor = glass == 0 ? 1 : 0;
    CasterMotionState state;
    EXPECT_TRUE(instanceMotion(state, s, 0).rows.empty());
    const glm::vec3 lift(0.0f, 0.1f, 0.0f);
    s.instances[floor].transform = glm::translate(glm::mat4(1.0f), lift) * s.instances[floor].transform;
    const InstanceMotion floorMoved = instanceMotion(state, s, 1);
    EXPECT_FALSE(floorMoved.casterMoved) << "a moving receiver is no moving caster";
    ASSERT_EQ(floorMoved.rows.size(), shader::kCasterMotionRowsPerInstance * s.instances.size());
    const glm::vec3 p(0.3f, 0.7f, -0.2f);
    EXPECT_NEAR(glm::length(applyRows(floorMoved.rows, floor, p) - (p - lift)), 0.0f, 1e-6f);
    const glm::vec3 step(0.02f, 0.0f, -0.01f);
    s.instances[glass].transform = glm::translate(glm::mat4(1.0f), step) * s.instances[glass].transform;
    const InstanceMotion glassMoved = instanceMotion(state, s, 2);
    EXPECT_TRUE(glassMoved.casterMoved);
    const std::vector<glm::vec4>& rows = glassMoved.rows;
    ASSERT_EQ(rows.size(), shader::kCasterMotionRowsPerInstance * s.instances.size());
    EXPECT_NEAR(glm::length(applyRows(rows, glass, p) - (p - step)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(applyRows(rows, floor, p) - p), 0.0f, 1e-6f) << "the floor stood still since frame 1";
    EXPECT_EQ(instanceMotion(state, s, 2).rows, rows) << "views of one frame share its motion";
    EXPECT_TRUE(instanceMotion(state, s, 3).rows.empty()) << "nothing moved since frame 2";
}

// A chain that moved along the floor moves the photon on the floor by as much; a chain that moved up
// moves an oblique photon's landing point back along its direction, in the floor's plane; grazing: none.
TEST(CasterMotion, ReceiverShiftStaysInTheReceiversPlane) {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    EXPECT_EQ(shader::casterMotionReceiverShift(glm::vec3(0.1f, 0.0f, 0.0f), down, n), glm::vec3(0.1f, 0.0f, 0.0f));
    const glm::vec3 oblique = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    const glm::vec3 up(0.0f, 0.2f, 0.0f);
    const glm::vec3 shift = shader::casterMotionReceiverShift(up, oblique, n);
    EXPECT_NEAR(glm::dot(shift, n), 0.0f, 1e-6f);
    EXPECT_NEAR(shift.x, 0.2f, 1e-6f);   // 0.2 higher along a 45-degree ray lands 0.2 further
    EXPECT_EQ(shader::casterMotionReceiverShift(up, glm::vec3(1.0f, 0.0f, 0.0f), n), glm::vec3(0.0f));
}

// Fixed point: 1/4096 m, rounded to nearest, clamped at 4 m.
TEST(CasterMotion, FixedPointWordsRoundAndClamp) {
    EXPECT_EQ(shader::casterMotionFixed(glm::vec3(1.0f / 4096.0f, -0.6f / 4096.0f, 0.0f)), glm::ivec3(1, -1, 0));
    EXPECT_EQ(shader::casterMotionFixed(glm::vec3(9.0f, -9.0f, 0.5f)), glm::ivec3(16384, -16384, 2048));
}

}  // namespace
}  // namespace caustics
