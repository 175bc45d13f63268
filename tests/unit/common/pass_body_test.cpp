// The pass bodies (passes/<pass>/shaders/<name>.h, docs/shaders.md) compiled as C++: the compiler
// type-checks the code the GLSL and HLSL entries run, and these tests pin its behaviour.
#include <gtest/gtest.h>

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "composite/shaders/composite.h"
#include "direct_lighting/shaders/direct_light.h"
#include "caustic_maps/shaders/grid_from_count.h"
#include "caustic_maps/shaders/emitters.h"
#include "caustic_maps/shaders/photon_plan.h"
#include "forward_trace/shaders/forward.h"
#include "gbuffer/shaders/gbuffer.h"
#include "gbuffer/shaders/remap_object_ids.h"
#include "backward_trace/shaders/second_type_guide_fill.h"
#include "backward_trace/shaders/second_type_guides.h"

namespace caustics::shader {

namespace {
std::vector<uint2> gPairs;   // the remap body's storage buffer (bindings/remap_object_ids.h on the GPU)
}  // namespace
uint2 pairsLoad(uint i) { return gPairs.at(i); }

namespace {
std::vector<uint> gCounters, gGrid;   // the grid-from-count body's buffers
}  // namespace
uint countersLoad(uint i) { return gCounters.at(i); }
void gridStore(uint i, uint v) { gGrid.at(i) = v; }

namespace {
std::vector<float> gMapWords;   // the photon plan's buffers
std::vector<CausticLayerPlan> gPlans;
std::vector<uint> gArgs(3);
}  // namespace
float mapWordsLoad(uint i) { return gMapWords.at(i); }
CausticLayerPlan plansLoad(uint i) { return gPlans.at(i); }
void plansStore(uint i, CausticLayerPlan plan) { gPlans.at(i) = plan; }
void argsStore(uint i, uint v) { gArgs.at(i) = v; }

namespace {

CompositeParams params(uint aov, uint hasCaustics) { return {aov, hasCaustics, 2.0f, 10.0f, uint2(4, 4)}; }

CompositeInputs inputs() {
    CompositeInputs t;
    t.direct = float3(0.25f, 0.5f, 0.125f);
    t.caustics = float3(1.0f, 0.0f, 0.5f);
    t.albedo = float3(0.5f);
    t.normal = float3(0.0f, -1.0f, 0.0f);
    t.linearDepth = 2.5f;
    return t;
}

// Exact compares: the body is the same float arithmetic as the references it is compared with.
TEST(CompositeBody, FinalAovIsDirectPlusCausticsExposedAndToneMapped) {
    CompositeOutput o = compositePixel(params(kAovFinal, 1u), inputs());
    EXPECT_EQ(o.linearValue, inputs().direct + inputs().caustics);
    EXPECT_EQ(o.shown, srgbEncode(acesFitted((inputs().direct + inputs().caustics) * 2.0f)));
}

TEST(CompositeBody, WithoutCausticsTheRepeatedBindingIsNotAdded) {
    CompositeOutput o = compositePixel(params(kAovCaustics, 0u), inputs());
    EXPECT_EQ(o.linearValue, float3(0.0f));
    EXPECT_EQ(compositePixel(params(kAovFinal, 0u), inputs()).linearValue, inputs().direct);
}

TEST(CompositeBody, NormalAovIsRemappedToZeroOneWithoutTheSrgbCurve) {
    CompositeOutput o = compositePixel(params(kAovNormal, 1u), inputs());
    EXPECT_EQ(o.shown, float3(0.5f, 0.0f, 0.5f));
    EXPECT_EQ(o.linearValue, inputs().normal);
}

TEST(CompositeBody, DepthAovIsWhiteNearTheCameraAndBlackForTheBackground) {
    EXPECT_FLOAT_EQ(compositePixel(params(kAovDepth, 1u), inputs()).shown.x, 1.0f - 2.5f / 10.0f);
    CompositeInputs background = inputs();
    background.linearDepth = 0.0f;   // the G-buffer clears to 0 where nothing was drawn
    EXPECT_EQ(compositePixel(params(kAovDepth, 1u), background).shown, float3(0.0f));
}

TEST(RemapObjectIdsBody, ListedHostIdsFindTheirModuleIdAndOthersBecomeBackground) {
    gPairs = {{3, 10}, {7, 11}, {8, 12}, {40, 13}, {1000, 14}};   // sorted by host id
    EXPECT_EQ(moduleObjectIdOf(3, 5), 10u);
    EXPECT_EQ(moduleObjectIdOf(8, 5), 12u);
    EXPECT_EQ(moduleObjectIdOf(1000, 5), 14u);
    EXPECT_EQ(moduleObjectIdOf(0, 5), 0u);
    EXPECT_EQ(moduleObjectIdOf(9, 5), 0u);
    EXPECT_EQ(moduleObjectIdOf(5000, 5), 0u);   // past the last pair: no read beyond pairCount (at() throws)
    EXPECT_EQ(moduleObjectIdOf(1000, 4), 0u);   // only the first pairCount pairs are the map
}

TEST(GridFromCountBody, LaunchesFollowTheCounterUpToTheCapAndNoneWhenTheGateIsZero) {
    gCounters = {500, 7, 0};
    gGrid = {9, 9, 9};
    writeGridFromCount({0, 100, 1});
    EXPECT_EQ(gGrid, (std::vector<uint>{100, 1, 1}));   // capped
    writeGridFromCount({1, 100, 0});
    EXPECT_EQ(gGrid, (std::vector<uint>{7, 1, 1}));
    writeGridFromCount({0, 100, 2});
    EXPECT_EQ(gGrid, (std::vector<uint>{0, 1, 1}));     // gate counter 0: no sphere, no gather
}

// Layers with budgets of 100, 50 and 0 photons (0: raysPerTexel per texel) and 10, 0 and 4 emitters.
void planThreeLayers() {
    gMapWords.assign(3 * kCausticMapWords, 0.0f);
    gMapWords[0 * kCausticMapWords + kCausticMapPhotonsWord] = 100.0f;
    gMapWords[1 * kCausticMapWords + kCausticMapPhotonsWord] = 50.0f;
    gPlans.assign(3, CausticLayerPlan{});
    gPlans[0].emitters = 10;
    gPlans[2].emitters = 4;
    planPhotons({3, 2.5f});
}

TEST(PhotonPlanBody, ALayerWithoutEmittersHandsItsShareToTheOthers) {
    planThreeLayers();
    EXPECT_FLOAT_EQ(gPlans[0].raysPerTexel, 15.0f);   // (100 + 50) photons over 10 texels
    EXPECT_EQ(gPlans[0].launches, 150u);
    EXPECT_EQ(gPlans[1].launches, 0u);
}

TEST(PhotonPlanBody, ALayerWithoutABudgetEmitsRaysPerTexelAndLaunchRangesFollowEachOther) {
    planThreeLayers();
    EXPECT_FLOAT_EQ(gPlans[2].raysPerTexel, 2.5f);
    EXPECT_EQ(gPlans[2].samplesPerTexel, 3u);   // the last sample of a texel is emitted with p = 0.5
    EXPECT_EQ(gPlans[2].launchOffset, 150u);
    EXPECT_EQ(gPlans[2].launches, 12u);
    EXPECT_EQ(gArgs, (std::vector<uint>{162, 1, 1}));
}

// The forward trace's layer search reads the photon plan's launch ranges (plansLoad, as above).
TEST(ForwardBody, ALaunchFindsTheLayerWhoseRangeHoldsItAndLaunchesPastTheLastIdle) {
    planThreeLayers();   // ranges [0, 150), empty, [150, 162)
    EXPECT_EQ(forwardLayerOf(0u, 3u), 0);
    EXPECT_EQ(forwardLayerOf(149u, 3u), 0);
    EXPECT_EQ(forwardLayerOf(150u, 3u), 2);
    EXPECT_EQ(forwardLayerOf(161u, 3u), 2);
    EXPECT_EQ(forwardLayerOf(162u, 3u), -1);   // the direct dispatch's upper bound
}

CausticMap perspectiveMap() {
    CausticMap m{};
    m.origin = float3(0.0f, 2.0f, 0.0f);
    m.right = float3(1.0f, 0.0f, 0.0f);
    m.up = float3(0.0f, 0.0f, -1.0f);
    m.forward = float3(0.0f, -1.0f, 0.0f);
    m.extent = 1.0f;   // tan 45 degrees
    m.intensity = float3(10.0f, 5.0f, 1.0f);
    m.cosOuter = -2.0f;   // no cone
    return m;
}

// One photon at the centre of every texel of an N x N map carries the map's whole flux, intensity x
// the frustum's solid angle (common/emission.h; docs/physics.md): the texel solid angles are exact.
// Bound 1e-5: float sums of 64 terms, measured 2.4e-7 (x) and 1.2e-7 (z) relative.
TEST(ForwardBody, PerspectivePhotonsOfAllTexelsCarryTheFrustumsFlux) {
    const CausticMap m = perspectiveMap();
    const float n = 8.0f;
    float3 total(0.0f);
    for (uint y = 0; y < 8u; ++y)
        for (uint x = 0; x < 8u; ++x) {
            ForwardPhoton p = emitPhoton(m, float2(x, y) + 0.5f, uint2(x, y), n, 1.0f);
            EXPECT_NEAR(length(p.dir), 1.0f, 1e-6f);
            EXPECT_EQ(p.origin, m.origin);
            total += p.flux;
        }
    const float omega = perspectiveFrustumSolidAngle(m.extent);
    EXPECT_NEAR(total.x / (m.intensity.x * omega), 1.0f, 1e-5f);
    EXPECT_NEAR(total.z / (m.intensity.z * omega), 1.0f, 1e-5f);
    // Two rays per texel carry half the flux each.
    EXPECT_FLOAT_EQ(emitPhoton(m, float2(3.5f), uint2(3), n, 2.0f).flux.x, 0.5f * emitPhoton(m, float2(3.5f), uint2(3), n, 1.0f).flux.x);
}

TEST(ForwardBody, OrthographicPhotonsLeaveTheMapPlaneAlongItsAxisWithTheTexelsIlluminance) {
    CausticMap m = perspectiveMap();
    m.orthographic = 1u;
    m.extent = 2.0f;   // half-extent, metres
    ForwardPhoton centre = emitPhoton(m, float2(4.0f), uint2(4), 8.0f, 1.0f);
    EXPECT_EQ(centre.origin, m.origin);
    EXPECT_EQ(centre.dir, m.forward);
    EXPECT_FLOAT_EQ(centre.flux.x, m.intensity.x * 0.25f);   // lux x (4 m / 8)^2
    ForwardPhoton corner = emitPhoton(m, float2(0.0f), uint2(0), 8.0f, 1.0f);
    EXPECT_EQ(corner.origin, m.origin - 2.0f * m.right - 2.0f * m.up);
}

// The G-buffer depth test allows 0.1 % plus the depth change across one pixel's footprint at the
// view angle: 1.5 x (2 tan(fov/2) / height) x tan(view angle).
TEST(ForwardBody, SplatDepthToleranceGrowsWithTheViewAngle) {
    PinholeCamera cam = makePinholeCamera(float3(0.0f), float3(0.0f, 0.0f, -1.0f), float3(0.0f, 1.0f, 0.0f),
                                          2.0f * atan(1.0f), 100.0f, 100.0f);   // footprint 0.02
    EXPECT_TRUE(splatDepthMatches(cam, 10.009f, 10.0f, 1.0f));
    EXPECT_FALSE(splatDepthMatches(cam, 10.011f, 10.0f, 1.0f));
    EXPECT_TRUE(splatDepthMatches(cam, 10.5f, 10.0f, 0.5f));    // tolerance 10 x (1e-3 + 0.03 x 1.732) = 0.53
    EXPECT_FALSE(splatDepthMatches(cam, 10.55f, 10.0f, 0.5f));
    EXPECT_FALSE(splatDepthMatches(cam, 9.4f, 10.0f, 0.5f));
}

// A spot light's map texel emits unless its whole footprint lies outside the outer cone.
TEST(EmittersBody, OnlyTexelsWhollyOutsideTheSpotConeAreSkipped) {
    CausticMap m = perspectiveMap();   // 90 degree frustum, 8 x 8 texels
    m.spotAxis = m.forward;
    m.cosOuter = cos(30.0f * kPi / 180.0f);
    EXPECT_FALSE(texelOutsideSpotCone(m, uint2(3, 4), 8.0f));   // 10 degrees off the axis
    EXPECT_TRUE(texelOutsideSpotCone(m, uint2(0, 0), 8.0f));    // the corner, 51 degrees off
    // Texel (1, 4)'s centre is 32.5 degrees off the axis, within its 8.5 degree radius of the cone's edge.
    EXPECT_FALSE(texelOutsideSpotCone(m, uint2(1, 4), 8.0f));
    m.cosOuter = -2.0f;   // no cone
    EXPECT_FALSE(texelOutsideSpotCone(m, uint2(0, 0), 8.0f));
}

// KHR_lights_punctual at a point: E = I / d^2 for point and spot lights, with the range window
// saturate(1 - (d / range)^4)^2; a directional light's lux arrive unchanged.
TEST(DirectLightBody, PunctualLightsFallOffWithTheSquareOfTheDistanceInsideTheirRange) {
    GpuLight point{};
    point.position = float3(0.0f, 2.0f, 0.0f);
    point.type = kLightPoint;
    point.intensity = float3(8.0f, 4.0f, 0.0f);
    LightSample s = sampleLight(point, float3(0.0f));
    EXPECT_FLOAT_EQ(s.distance, 2.0f);
    EXPECT_EQ(s.toLight, float3(0.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(s.irradiance.x, 2.0f);
    point.range = 4.0f;   // (1 - (2 / 4)^4)^2 = (15 / 16)^2
    EXPECT_FLOAT_EQ(sampleLight(point, float3(0.0f)).irradiance.x, 2.0f * (15.0f / 16.0f) * (15.0f / 16.0f));
    EXPECT_EQ(sampleLight(point, float3(0.0f, -3.0f, 0.0f)).irradiance.x, 0.0f);   // beyond the range
    GpuLight sun{};
    sun.type = kLightDirectional;
    sun.direction = float3(0.0f, -1.0f, 0.0f);
    sun.intensity = float3(3.0f);
    EXPECT_EQ(sampleLight(sun, float3(5.0f)).irradiance, float3(3.0f));
    EXPECT_EQ(sampleLight(sun, float3(5.0f)).toLight, float3(0.0f, 1.0f, 0.0f));
}

// The G-buffer stores the side of a surface that is seen, whatever its winding.
TEST(GBufferBody, NormalIsUnitAndFacesTheViewerWhateverTheWinding) {
    EXPECT_EQ(gbufferFacingNormal(float3(0.0f, 0.0f, -2.0f), float3(0.0f, 0.0f, 1.0f)), float3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(gbufferFacingNormal(float3(0.0f, 3.0f, 0.0f), float3(0.0f, 1.0f, 1.0f)), float3(0.0f, 1.0f, 0.0f));
}

// A camera 2 m up looking down -z's way at the origin; `shift` moves it along x.
glm::mat4 viewProjAt(float shift) {
    return glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 100.0f) *
           glm::lookAt(glm::vec3(shift, 0.0f, 2.0f), glm::vec3(shift, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

CameraConstants guideCamera(const glm::mat4& now, const glm::mat4& before) {
    CameraConstants c{};
    c.viewProj = now;
    c.prevViewProj = before;
    return c;
}

TEST(SecondTypeGuideBody, HoldsTheReceiversDepthAndItsShiftBetweenTheTwoProjections) {
    CausticSphere s{};
    s.centre = float3(0.3f, -0.2f, 0.0f);
    s.normal = float3(0.0f, 0.0f, 1.0f);
    s.objectId = 7;
    const glm::mat4 now = viewProjAt(0.0f), before = viewProjAt(-0.1f);
    SecondTypeGuide g = secondTypeGuide(guideCamera(now, before), s, float2(64.0f, 64.0f));
    auto texel = [](const glm::mat4& m, glm::vec3 x) {
        glm::vec4 c = m * glm::vec4(x, 1.0f);
        return (glm::vec2(c) / c.w * 0.5f + 0.5f) * 64.0f - 0.5f;
    };
    const glm::vec2 expected = texel(before, s.centre) - texel(now, s.centre);
    EXPECT_NEAR(g.linearDepth, 2.0f, 1e-5f);      // clip w = distance along the optical axis
    EXPECT_NEAR(g.previousDepth, 2.0f, 1e-5f);
    EXPECT_NEAR(g.motion.x, expected.x, 1e-4f);
    EXPECT_NEAR(g.motion.y, 0.0f, 1e-4f);
    EXPECT_GT(g.motion.x, 1.0f);                  // the point sat further right before the camera moved right
    EXPECT_EQ(g.objectId, 7u);
    EXPECT_EQ(g.normal, s.normal);
}

TEST(SecondTypeGuideBody, AReceiverBehindLastFramesCameraHasNoHistory) {
    CausticSphere s{};
    s.centre = float3(0.0f, 0.0f, 0.0f);
    const glm::mat4 now = viewProjAt(0.0f);
    const glm::mat4 turned = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 100.0f) *
                             glm::lookAt(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    SecondTypeGuide g = secondTypeGuide(guideCamera(now, turned), s, float2(64.0f, 64.0f));
    EXPECT_EQ(g.previousDepth, 0.0f);
    EXPECT_EQ(g.motion.x, kGuideNoHistory);
}

// A reflection can reach a receiver behind the camera: the filter divides by the guide depth.
TEST(SecondTypeGuideBody, AReceiverBehindTheCameraGetsAPositiveDepthAndNoHistory) {
    CausticSphere s{};
    s.centre = float3(0.0f, 0.0f, 3.0f);   // behind the camera at z = 2 looking towards -z
    const glm::mat4 now = viewProjAt(0.0f);
    SecondTypeGuide g = secondTypeGuide(guideCamera(now, now), s, float2(64.0f, 64.0f));
    EXPECT_NEAR(g.linearDepth, 1.0f, 1e-5f);
    EXPECT_EQ(g.previousDepth, 0.0f);
}

// Through a glass that moved (docs/caustics.md "Moving objects"): the motion is the glass point's, not the
// receiver's (the glass, nearer the camera, moves by more pixels), and last frame's depth is the receiver's
// carried by the glass's motion.
TEST(SecondTypeGuideBody, ThroughAMovedGlassTheMotionIsTheGlasssAndTheDepthTheCarriedReceivers) {
    CausticSphere s{};
    s.centre = float3(0.1f, 0.0f, 0.0f);   // the receiver, 2 m from the camera
    const glm::mat4 still = viewProjAt(0.0f);
    const CameraConstants c = guideCamera(still, still);
    const SecondTypeGuide g = secondTypeGuide(c, s, float2(64.0f, 64.0f));
    EXPECT_NEAR(g.motion.x, 0.0f, 1e-4f);   // a still camera: no motion of its own
    const float3 step(-0.05f, 0.0f, 0.0f);   // where the glass was last frame, minus where it is
    const float3 glassNow(0.06f, 0.0f, 1.2f);   // 0.8 m from the camera
    const SecondTypeGuide m = secondTypeGuideThroughMovedGlass(c, g, glassNow, glassNow + step, s.centre + step, float2(64.0f, 64.0f));
    auto texel = [&](glm::vec3 x) {
        glm::vec4 q = still * glm::vec4(x, 1.0f);
        return (glm::vec2(q) / q.w * 0.5f + 0.5f) * 64.0f - 0.5f;
    };
    EXPECT_NEAR(m.motion.x, texel(glassNow + step).x - texel(glassNow).x, 1e-4f);
    EXPECT_LT(m.motion.x, (texel(s.centre + step) - texel(s.centre)).x - 0.5f) << "the nearer glass moves further on screen";
    EXPECT_NEAR(m.motion.y, 0.0f, 1e-4f);
    EXPECT_NEAR(m.previousDepth, 2.0f, 1e-5f);   // the receiver moved along the image plane
    EXPECT_EQ(m.linearDepth, g.linearDepth);
    EXPECT_EQ(m.objectId, g.objectId);
}

// The glass's own guide motion (docs/caustics.md "Second-type guides", incoherent receivers): zero for a
// still glass under a still camera, the glass point's screen motion when it moved, and no history when
// last frame's camera had it behind.
TEST(SecondTypeGuideBody, GlassGuideMotionIsTheGlassPointsOwn) {
    const glm::mat4 still = viewProjAt(0.0f);
    const CameraConstants c = guideCamera(still, still);
    const float3 glassNow(0.06f, 0.0f, 1.2f);
    const float3 at = glassGuideMotion(c, glassNow, glassNow, float2(64.0f, 64.0f));
    EXPECT_NEAR(at.x, 0.0f, 1e-5f);
    EXPECT_NEAR(at.y, 0.0f, 1e-5f);
    EXPECT_NEAR(at.z, 0.8f, 1e-5f);   // last frame's clip w: 0.8 m in front of the camera at z = 2
    const float3 before = glassNow + float3(-0.05f, 0.0f, 0.0f);
    const float3 moved = glassGuideMotion(c, glassNow, before, float2(64.0f, 64.0f));
    const SecondTypeGuide viaReceiver =
        secondTypeGuideThroughMovedGlass(c, SecondTypeGuide{}, glassNow, before, float3(0.0f, 0.0f, 0.0f), float2(64.0f, 64.0f));
    EXPECT_EQ(moved.x, viaReceiver.motion.x);
    EXPECT_EQ(moved.y, viaReceiver.motion.y);
    EXPECT_LT(moved.x, -1.0f);   // it sat left of where it is
    const glm::mat4 turned = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 100.0f) *
                             glm::lookAt(glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const float3 lost = glassGuideMotion(guideCamera(still, turned), glassNow, glassNow, float2(64.0f, 64.0f));
    EXPECT_EQ(lost.x, kGuideNoHistory);
    EXPECT_EQ(lost.z, 0.0f);
}

// Two pixels' guides agree where the a-trous passes' first step would weigh them: the same receiver,
// depths within 3 %, normals within about 8 degrees (second_type_guide_fill.h).
TEST(SecondTypeGuideFillBody, GuidesAgreeOnOneReceiverNearbyInDepthAndNormal) {
    const float3 up(0.0f, 1.0f, 0.0f);
    EXPECT_TRUE(guidesAgree(2.0f, up, 3u, 2.05f, up, 3u));
    EXPECT_FALSE(guidesAgree(2.0f, up, 3u, 2.0f, up, 4u)) << "another receiver";
    EXPECT_FALSE(guidesAgree(2.0f, up, 3u, 2.1f, up, 3u)) << "5 % apart in depth";
    EXPECT_TRUE(guidesAgree(2.1f, up, 3u, 2.0f, up, 3u) == guidesAgree(2.0f, up, 3u, 2.1f, up, 3u)) << "symmetric";
    const float tilt = 0.2f;   // 11.5 degrees
    EXPECT_FALSE(guidesAgree(2.0f, up, 3u, 2.0f, float3(std::sin(tilt), std::cos(tilt), 0.0f), 3u));
    const float slight = 0.1f;   // 5.7 degrees
    EXPECT_TRUE(guidesAgree(2.0f, up, 3u, 2.0f, float3(std::sin(slight), std::cos(slight), 0.0f), 3u));
    EXPECT_LT(kGuideMinAgreeing, 9u);   // a pixel with a coherent neighbourhood keeps its receiver
    EXPECT_EQ(kGuideGlassFlag, 1u << 31) << "the mark is the top bit, far above every instance id + 1";
}

}  // namespace
}  // namespace caustics::shader
