// Ray differentials (common/ray_differential.h, Igehy 1999) against central finite differences of
// rays actually traced through analytic surfaces, and the gather-disk radius policy and membership
// test (common/gather_disk.h).
#include <cmath>

#include <gtest/gtest.h>

#include "common/fresnel.h"
#include "common/gather_disk.h"
#include "common/ray_differential.h"

namespace sh = caustics::shader;

namespace {

struct Ball {
    glm::vec3 centre;
    float radius;
};

// Far intersection (inside = true) or near one of a ray with a sphere; false on a miss.
bool hitBall(const Ball& b, glm::vec3 o, glm::vec3 d, bool inside, float& t) {
    glm::vec3 oc = o - b.centre;
    float bb = glm::dot(oc, d), c = glm::dot(oc, oc) - b.radius * b.radius, disc = bb * bb - c;
    if (disc < 0.0f) return false;
    t = inside ? -bb + std::sqrt(disc) : -bb - std::sqrt(disc);
    return t > 0.0f;
}

struct Traced {
    glm::vec3 floorPoint;
    sh::RayDifferential rd;
};

// Camera ray through `pixel`, into the ball and out (two smooth refractions, or one mirror reflection
// when `mirror`), to the plane y = 0; the differential follows the same chain. An analytic sphere's
// normal N = (P - c) / R has dN = dP / R for dP in the tangent plane.
bool traceBallToFloor(const sh::PinholeCamera& cam, const Ball& ball, glm::vec2 pixel, float ior, bool mirror, Traced& out) {
    glm::vec3 o = cam.eye, d = sh::cameraRayDirection(cam, pixel);
    sh::RayDifferential rd = sh::pinholeRayDifferential(cam, pixel);
    sh::OpticalMaterial mat{glm::vec3(1.0f), mirror ? 1.0f : 0.0f, 0.0f, 1.0f, ior, false};
    for (int event = 0; event < (mirror ? 1 : 2); ++event) {
        float t;
        if (!hitBall(ball, o, d, event == 1, t)) return false;
        glm::vec3 p = o + t * d, n = (p - ball.centre) / ball.radius;
        rd = sh::transferRayDifferential(rd, d, t, n);
        sh::SpecularEvent ev{};
        if (mirror) {
            ev.kind = sh::kEventReflect;
            ev.direction = glm::reflect(d, n);
        } else {
            bool entering = glm::dot(d, n) < 0.0f;
            ev.kind = sh::kEventRefract;
            if (!sh::refractDirection(d, entering ? n : -n, entering ? 1.0f / ior : ior, ev.direction)) return false;
        }
        rd = sh::scatterRayDifferential(rd, d, ev, n, rd.dPdx / ball.radius, rd.dPdy / ball.radius, mat);
        o = p;
        d = ev.direction;
    }
    if (d.y >= 0.0f) return false;
    float t = -o.y / d.y;
    rd = sh::transferRayDifferential(rd, d, t, glm::vec3(0.0f, 1.0f, 0.0f));
    out.floorPoint = o + t * d;
    out.rd = rd;
    return true;
}

void expectMatchesFiniteDifferences(const sh::PinholeCamera& cam, const Ball& ball, float ior, bool mirror, glm::vec2 pixel) {
    Traced c, xp, xm, yp, ym;
    const float h = 0.05f;  // pixels
    ASSERT_TRUE(traceBallToFloor(cam, ball, pixel, ior, mirror, c));
    ASSERT_TRUE(traceBallToFloor(cam, ball, pixel + glm::vec2(h, 0), ior, mirror, xp));
    ASSERT_TRUE(traceBallToFloor(cam, ball, pixel - glm::vec2(h, 0), ior, mirror, xm));
    ASSERT_TRUE(traceBallToFloor(cam, ball, pixel + glm::vec2(0, h), ior, mirror, yp));
    ASSERT_TRUE(traceBallToFloor(cam, ball, pixel - glm::vec2(0, h), ior, mirror, ym));
    glm::vec3 fdX = (xp.floorPoint - xm.floorPoint) / (2.0f * h), fdY = (yp.floorPoint - ym.floorPoint) / (2.0f * h);
    // Central differences are exact to O(h^2); float rounding of points ~1 m apart over 0.1 px
    // steps gives ~1e-7 / 0.1 relative. 2 % of the derivative's length bounds both with margin.
    EXPECT_LT(glm::length(c.rd.dPdx - fdX), 0.02f * glm::length(fdX)) << "pixel " << pixel.x << "," << pixel.y;
    EXPECT_LT(glm::length(c.rd.dPdy - fdY), 0.02f * glm::length(fdY)) << "pixel " << pixel.x << "," << pixel.y;
}

sh::PinholeCamera topCamera() {
    return sh::makePinholeCamera({0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, glm::radians(30.0f), 128.0f, 128.0f);
}

}  // namespace

TEST(RayDifferential, PrimaryRayFootprintOnAPlaneIsThePixelArea) {
    sh::PinholeCamera cam = topCamera();
    sh::RayDifferential rd = sh::pinholeRayDifferential(cam, {64.0f, 64.0f});
    rd = sh::transferRayDifferential(rd, sh::cameraRayDirection(cam, {64.0f, 64.0f}), 2.0f, {0.0f, 1.0f, 0.0f});
    // On axis at distance 2: one pixel spans 2 * 2 tan(15 deg) / 128 (to first order in the pixel).
    float side = 4.0f * std::tan(glm::radians(15.0f)) / 128.0f;
    EXPECT_NEAR(sh::rayFootprintArea(rd), side * side, 1e-3f * side * side);
}

TEST(RayDifferential, GlassBallLensMatchesFiniteDifferencesOfTracedRays) {
    Ball ball{{0.0f, 0.6f, 0.0f}, 0.4f};
    sh::PinholeCamera cam = topCamera();
    for (glm::vec2 px : {glm::vec2(64.5f, 64.5f), glm::vec2(70.5f, 58.5f), glm::vec2(52.25f, 66.75f), glm::vec2(60.5f, 80.5f)})
        expectMatchesFiniteDifferences(cam, ball, 1.5f, false, px);
}

TEST(RayDifferential, MirrorBallMatchesFiniteDifferencesOfTracedRays) {
    Ball ball{{0.0f, 0.5f, 0.0f}, 0.3f};
    sh::PinholeCamera cam = sh::makePinholeCamera({1.2f, 1.0f, 0.3f}, {0.0f, 0.4f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(30.0f), 128.0f, 128.0f);
    // Pixels on the ball's lower-left part, whose reflections go down to the floor.
    for (glm::vec2 px : {glm::vec2(64.5f, 80.5f), glm::vec2(58.5f, 84.5f), glm::vec2(70.25f, 78.75f)})
        expectMatchesFiniteDifferences(cam, ball, 1.5f, true, px);
}

// The lens shrinks the footprint: seen through a ball whose focus is near the floor, a pixel covers
// far less floor than the unfolded estimate (path length x pixel angle) the old policy used.
TEST(RayDifferential, BallLensFootprintIsFarBelowTheUnfoldedPixelWidth) {
    Ball ball{{0.0f, 0.6f, 0.0f}, 0.4f};
    sh::PinholeCamera cam = topCamera();
    Traced c;
    ASSERT_TRUE(traceBallToFloor(cam, ball, {66.5f, 64.5f}, 1.5f, false, c));
    float unfolded = 2.0f * std::sqrt(sh::pinholePixelArea(cam));  // path length ~2 m
    EXPECT_LT(std::sqrt(sh::rayFootprintArea(c.rd)), 0.5f * unfolded);
}

TEST(RayDifferential, InterpolatedNormalDerivativeMatchesFiniteDifferences) {
    glm::vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 0, 1);
    glm::vec3 n0 = glm::normalize(glm::vec3(-0.2f, 1, -0.1f)), n1 = glm::normalize(glm::vec3(0.3f, 1, 0)),
              n2 = glm::normalize(glm::vec3(0, 1, 0.4f));
    auto normalAt = [&](float b1, float b2) { return glm::normalize(n0 + b1 * (n1 - n0) + b2 * (n2 - n0)); };
    const float b1 = 0.3f, b2 = 0.25f, h = 1e-3f;
    glm::vec3 nU = n0 + b1 * (n1 - n0) + b2 * (n2 - n0);
    glm::vec3 dP(0.6f, 0.0f, -0.8f);  // in the plane; moves b1 by 0.6 and b2 by -0.8 per unit
    glm::vec3 analytic = sh::shadingNormalDerivative(p1 - p0, p2 - p0, n1 - n0, n2 - n0, nU, dP);
    glm::vec3 fd = (normalAt(b1 + 0.6f * h, b2 - 0.8f * h) - normalAt(b1 - 0.6f * h, b2 + 0.8f * h)) / (2.0f * h);
    EXPECT_LT(glm::length(analytic - fd), 1e-3f * glm::length(fd) + 1e-5f);
}

TEST(GatherDisk, RadiusIsTheScaledFootprintWidthWithinItsClamps) {
    sh::GatherRadiusLimits l{2.0f, 1.0f / 64.0f, 16.0f, 1e-4f, 0.25f};
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(1e-4f, 0.01f, 0.02f, l), 2.0f * 0.01f);           // square 0.01 m
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(1e-4f, 0.02f, 0.02f, l), 2.0f * 0.01f);           // 1 : 4, untouched
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(0.0f, 0.0f, 0.02f, l), 2.0f * 0.02f / 64.0f);     // collapsed: min magnification
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(1.0f, 1.0f, 0.005f, l), 2.0f * 0.005f * 16.0f);   // grazing: max magnification
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(4.0f, 2.0f, 1.0f, l), 0.25f);                     // metres cap
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(0.0f, 0.0f, 1e-5f, l), 1e-4f);                    // metres floor
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(std::nanf(""), std::nanf(""), 0.02f, l), 2.0f * 0.02f);  // NaN: unfolded width
}

// A fold of the camera path: the footprint is a strip (area -> 0, length finite); the width stays at
// kFoldMinorFraction of the strip's length instead of collapsing with the area.
TEST(GatherDisk, FoldedFootprintKeepsAFractionOfItsLength) {
    sh::GatherRadiusLimits l{1.0f, 1.0f / 64.0f, 16.0f, 1e-4f, 0.25f};
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(1e-8f, 0.01f, 0.01f, l), sh::kFoldMinorFraction * 0.01f);
    EXPECT_FLOAT_EQ(sh::gatherDiskRadius(0.0f, 0.01f, 0.01f, l), sh::kFoldMinorFraction * 0.01f);
}

TEST(RayDifferential, FootprintMajorAxisIsTheParallelogramsLargerSingularValue) {
    sh::RayDifferential rd{};
    rd.dPdx = glm::vec3(3.0f, 0.0f, 0.0f);
    rd.dPdy = glm::vec3(0.0f, 0.0f, 0.5f);
    EXPECT_NEAR(sh::rayFootprintMajorAxis(rd), 3.0f, 1e-5f);
    rd.dPdy = glm::vec3(3.0f, 0.0f, 0.0f);  // parallel (a fold): zero area, singular value 3 sqrt(2)
    EXPECT_NEAR(sh::rayFootprintMajorAxis(rd), 3.0f * std::sqrt(2.0f), 1e-4f);
    rd.dPdx = glm::vec3(1.0f, 0.0f, 1.0f);  // rotated square of side sqrt(2)
    rd.dPdy = glm::vec3(-1.0f, 0.0f, 1.0f);
    EXPECT_NEAR(sh::rayFootprintMajorAxis(rd), std::sqrt(2.0f), 1e-5f);
}

TEST(GatherDisk, HitsCountOnlyNearTheTangentPlaneInsideTheRadius) {
    glm::vec3 c(0.0f), n(0.0f, 1.0f, 0.0f);
    EXPECT_TRUE(sh::insideGatherDisk({0.09f, 0.0f, 0.0f}, c, n, 0.1f));
    EXPECT_FALSE(sh::insideGatherDisk({0.11f, 0.0f, 0.0f}, c, n, 0.1f));
    EXPECT_TRUE(sh::insideGatherDisk({0.0f, 0.02f, 0.0f}, c, n, 0.1f));
    EXPECT_FALSE(sh::insideGatherDisk({0.0f, -0.03f, 0.0f}, c, n, 0.1f));  // another sheet 3 cm below
}
