// Each caustic map rasterises only the instances whose bounding sphere touches its frustum
// (CausticMapPlan::drawnInstances): the specular object and what lies between it and the light stay,
// geometry beside or behind the light goes.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/caustic_map_plan.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics {
namespace {

bool drawn(const CausticMapPlan& plan, uint32_t map, uint32_t instance) {
    const auto& list = plan.drawnInstances[map];
    return std::find(list.begin(), list.end(), instance) != list.end();
}

// The glass-sphere scene (sphere + plane) with copies of the plane's mesh shrunk to 0.1 m placed
// `where`; returns the index of the first added instance.
uint32_t addSmallDiffuseBoxes(scene::Scene& sc, std::initializer_list<glm::vec3> where) {
    uint32_t plane = 0;
    for (uint32_t i = 0; i < sc.instances.size(); ++i)
        if (!sc.materials[sc.meshes[sc.instances[i].mesh].material].isSpecular()) plane = i;
    const uint32_t first = uint32_t(sc.instances.size());
    for (const glm::vec3& p : where) {
        scene::Instance inst = sc.instances[plane];
        inst.transform = glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(0.01f));
        inst.objectId = uint32_t(sc.instances.size()) + 1;
        sc.instances.push_back(inst);
    }
    return first;
}

TEST(CausticMapCulling, SpotMapDrawsTheSpecularObjectAndOccludersButNotWhatIsBesideOrBehindTheLight) {
    scene::AnalyticSceneDesc d;
    d.height = 1.0f;
    scene::Scene sc = scene::makeGlassSphereScene(d);
    sc.lights.clear();
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {0.0f, 4.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeAngle = 0.5f;
    spot.intensity = 10.0f;
    sc.lights.push_back(spot);
    // Between light and sphere (occluder), far to the side, and above (behind) the light.
    const uint32_t first = addSmallDiffuseBoxes(sc, {{0.0f, 2.5f, 0.0f}, {30.0f, 1.0f, 0.0f}, {0.0f, 6.0f, 0.0f}});
    CausticMapPlan plan = planCausticMaps(sc, computeSpecularBounds(sc), true);
    ASSERT_EQ(plan.maps.size(), 1u);
    ASSERT_EQ(plan.drawnInstances.size(), 1u);
    for (uint32_t i = 0; i < first; ++i)
        if (sc.materials[sc.meshes[sc.instances[i].mesh].material].isSpecular()) EXPECT_TRUE(drawn(plan, 0, i));
    EXPECT_TRUE(drawn(plan, 0, first)) << "occluder between the light and the sphere";
    EXPECT_FALSE(drawn(plan, 0, first + 1)) << "box 30 m to the side";
    EXPECT_FALSE(drawn(plan, 0, first + 2)) << "box behind the light";
}

TEST(CausticMapCulling, DirectionalMapDrawsWhatIsUpstreamButNotWhatIsBesideTheBeam) {
    scene::AnalyticSceneDesc d;
    d.height = 1.0f;
    d.lightDirection = {0.0f, -1.0f, 0.0f};
    scene::Scene sc = scene::makeGlassSphereScene(d);
    const uint32_t first = addSmallDiffuseBoxes(sc, {{0.1f, 3.0f, 0.0f}, {0.0f, 1.0f, 5.0f}});
    CausticMapPlan plan = planCausticMaps(sc, computeSpecularBounds(sc), true);
    ASSERT_EQ(plan.maps.size(), 1u);
    EXPECT_TRUE(drawn(plan, 0, first)) << "box in the beam above the sphere";
    EXPECT_FALSE(drawn(plan, 0, first + 1)) << "box 5 m beside the beam";
}

// CausticsSettings::mapOccluders off (the default): the same beam, only the glass is drawn.
TEST(CausticMapCulling, WithoutOccludersOnlyTheSpecularInstancesInTheFrustumAreDrawn) {
    scene::AnalyticSceneDesc d;
    d.height = 1.0f;
    d.lightDirection = {0.0f, -1.0f, 0.0f};
    scene::Scene sc = scene::makeGlassSphereScene(d);
    const uint32_t first = addSmallDiffuseBoxes(sc, {{0.1f, 3.0f, 0.0f}});
    CausticMapPlan plan = planCausticMaps(sc, computeSpecularBounds(sc));
    ASSERT_EQ(plan.maps.size(), 1u);
    ASSERT_EQ(plan.drawnInstances[0].size(), 1u);
    EXPECT_TRUE(sc.materials[sc.meshes[sc.instances[plan.drawnInstances[0][0]].mesh].material].isSpecular());
    EXPECT_FALSE(drawn(plan, 0, first)) << "box in the beam above the sphere";
}

TEST(CausticMapCulling, SphereTestIsConservativeAtTheFrustumCorner) {
    CausticMapGpu m;
    m.origin = glm::vec3(0.0f);
    m.forward = {0, 0, 1};
    m.right = {1, 0, 0};
    m.up = {0, 1, 0};
    m.extent = 0.5f;   // corner of the square on z = 1 at (0.5, 0.5)
    EXPECT_TRUE(mapFrustumTouchesSphere(m, glm::vec4(0.5f, 0.5f, 1.0f, 0.001f)));
    EXPECT_TRUE(mapFrustumTouchesSphere(m, glm::vec4(0.0f, 0.0f, 0.0f, 0.1f)));   // around the apex
    EXPECT_FALSE(mapFrustumTouchesSphere(m, glm::vec4(0.0f, 0.0f, -1.0f, 0.1f)));  // behind
    EXPECT_FALSE(mapFrustumTouchesSphere(m, glm::vec4(3.0f, 0.0f, 1.0f, 0.5f)));   // beside
}

}  // namespace
}  // namespace caustics
