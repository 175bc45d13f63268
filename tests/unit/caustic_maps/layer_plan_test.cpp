// Map layers per cluster and the photon budget (caustics/caustic_map_plan.h, caustic_importance.h):
// a ball's layer is the same whether or not other glass stands 40 m away, hidden clusters get no layer,
// the budget follows the view coverage, ranges and the layer cap hold, and every specular instance of a
// light is owned by exactly one of its layers.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/caustic_map_plan.h"
#include "caustics/scene/builtin_scenes.h"

namespace caustics {
namespace {

uint32_t sphereInstance(const scene::Scene& sc) {
    for (uint32_t i = 0; i < sc.instances.size(); ++i)
        if (sc.materials[sc.meshes[sc.instances[i].mesh].material].isSpecular()) return i;
    return 0;
}

// The glass-ball scene (R 0.5 m, centre 1 m over the plane) with copies of the ball at `where`.
scene::Scene ballsAt(std::initializer_list<glm::vec3> where) {
    scene::AnalyticSceneDesc d;
    d.planeHalfSize = 100.0f;
    scene::Scene sc = scene::makeGlassSphereScene(d);
    const uint32_t ball = sphereInstance(sc);
    for (const glm::vec3& p : where) {
        scene::Instance inst = sc.instances[ball];
        inst.transform = glm::translate(glm::mat4(1.0f), p);
        inst.objectId = uint32_t(sc.instances.size()) + 1;
        sc.instances.push_back(inst);
    }
    return sc;
}

CausticView viewOf(glm::vec3 eye, glm::vec3 target, uint32_t w = 192, uint32_t h = 192) {
    scene::Camera cam;
    cam.eye = eye;
    cam.target = target;
    cam.verticalFovRadians = glm::radians(40.0f);
    auto constants = makeCameraConstants(cam, w, h, 0);
    EXPECT_TRUE(constants) << constants.message();
    return causticViewOf(constants.value());
}

TEST(CausticLayers, BallLayerIsTheSameWithFarObjectsOutOfView) {
    const CausticView view = viewOf({0, 3, 2.5f}, {0, 0, 0});
    scene::Scene alone = ballsAt({});
    scene::Scene crowded = ballsAt({{40, 1, 0}, {41.2f, 1, 0.5f}});
    CausticPlanOptions o;
    o.view = &view;
    CausticMapPlan a = planCausticMaps(alone, computeSpecularBounds(alone), o);
    CausticMapPlan c = planCausticMaps(crowded, computeSpecularBounds(crowded), o);
    ASSERT_EQ(a.maps.size(), 1u);
    ASSERT_EQ(c.maps.size(), 1u) << "the far cluster's caustic cannot reach the view";
    EXPECT_EQ(c.hiddenClusters, 1u);
    EXPECT_FLOAT_EQ(a.maps[0].extent, c.maps[0].extent) << "texel footprint on the ball unchanged";
    EXPECT_EQ(glm::vec3(a.maps[0].right), glm::vec3(c.maps[0].right));
    // Without a view both clusters get a layer, each fitted to its own cluster.
    CausticMapPlan all = planCausticMaps(crowded, computeSpecularBounds(crowded));
    ASSERT_EQ(all.maps.size(), 2u);
    EXPECT_FLOAT_EQ(all.maps[0].extent, a.maps[0].extent);
    EXPECT_EQ(all.maps[0].cluster, 0u);
    EXPECT_EQ(all.maps[1].cluster, 1u);
}

TEST(CausticLayers, BudgetIsSplitByViewCoverageAndSumsToTheBudget) {
    // Two balls 8 m apart, the camera nearer the first: its receivers cover more of the image.
    scene::Scene sc = ballsAt({{8, 1, 0}});
    const CausticView view = viewOf({-2, 4, 6}, {4, 0, 0});
    CausticPlanOptions o;
    o.view = &view;
    o.photons = 100000;
    CausticMapPlan p = planCausticMaps(sc, computeSpecularBounds(sc), o);
    ASSERT_EQ(p.maps.size(), 2u);
    EXPECT_NEAR(p.maps[0].photons + p.maps[1].photons, 100000.0f, 1.0f);
    EXPECT_GT(p.coverage[0], p.coverage[1]);
    EXPECT_NEAR(p.maps[0].photons / p.maps[1].photons, p.coverage[0] / p.coverage[1], 1e-3f);
    EXPECT_EQ(p.photonBudget, 100000u);
}

TEST(CausticLayers, ViewCoverageIsZeroBehindAndOutsideAndOneInside) {
    const CausticView view = viewOf({0, 0, 5}, {0, 0, 0});
    EXPECT_EQ(viewCoverage(view, {0, 0, 10, 1}), 0.0f) << "behind the eye";
    EXPECT_EQ(viewCoverage(view, {30, 0, 0, 1}), 0.0f) << "beside the frustum";
    EXPECT_EQ(viewCoverage(view, {0, 0, 5.5f, 1}), 1.0f) << "eye inside";
    const float near = viewCoverage(view, {0, 0, 0, 0.5f}), far = viewCoverage(view, {0, 0, -20, 0.5f});
    EXPECT_GT(near, 0.0f);
    EXPECT_NEAR(near / far, 25.0f, 1.0f) << "coverage falls as distance^-2 (5 m vs 25 m)";
}

TEST(CausticLayers, PointLightRangeKeepsOnlyTheClustersInsideIt) {
    scene::Scene sc = ballsAt({{20, 1, 0}});
    sc.lights.clear();
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = {0, 4, 0};
    point.intensity = 10.0f;
    point.range = 5.0f;
    sc.lights.push_back(point);
    CausticMapPlan p = planCausticMaps(sc, computeSpecularBounds(sc));
    ASSERT_EQ(p.maps.size(), 1u);
    EXPECT_FLOAT_EQ(p.maps[0].range, 5.0f);
    EXPECT_EQ(p.layerInstances[0], (std::vector<uint32_t>{sphereInstance(sc)}));
    sc.lights[0].position = {-30, 4, 0};
    CausticMapPlan none = planCausticMaps(sc, computeSpecularBounds(sc));
    EXPECT_TRUE(none.maps.empty());
    ASSERT_EQ(none.skippedLights.size(), 1u);
    EXPECT_NE(none.skipReasons[0].find("range"), std::string::npos) << none.skipReasons[0];
}

TEST(CausticLayers, LayerCapMergesAndEverySpecularInstanceHasOneOwner) {
    // 120 balls 10 m apart under a sun and a point light: 121 clusters, more than kMaxCausticLayers.
    std::vector<glm::vec3> where;
    for (int i = 0; i < 120; ++i) where.push_back({10.0f * float(i % 11 + 1), 1.0f, 10.0f * float(i / 11)});
    scene::AnalyticSceneDesc d;
    scene::Scene sc = scene::makeGlassSphereScene(d);
    const uint32_t ball = sphereInstance(sc);
    for (const glm::vec3& p : where) {
        scene::Instance inst = sc.instances[ball];
        inst.transform = glm::translate(glm::mat4(1.0f), p);
        sc.instances.push_back(inst);
    }
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = {50, 20, 50};
    point.intensity = 100.0f;
    sc.lights.push_back(point);
    CausticMapPlan p = planCausticMaps(sc, computeSpecularBounds(sc));
    EXPECT_LE(p.maps.size(), size_t(kMaxCausticLayers));
    EXPECT_GT(p.capMerges, 0u);
    const uint32_t rows = uint32_t(p.instanceLayers.size() / p.instanceCount);
    EXPECT_EQ(rows, 2u);
    for (uint32_t row = 0; row < rows; ++row) {
        for (uint32_t i = 0; i < p.instanceCount; ++i) {
            const bool specular = sc.materials[sc.meshes[sc.instances[i].mesh].material].isSpecular();
            const uint32_t owner = p.instanceLayers[size_t(row) * p.instanceCount + i];
            EXPECT_EQ(owner != 0, specular) << "row " << row << " instance " << i;
            // The owning layer lists it.
            for (size_t k = 0; k < p.maps.size(); ++k) {
                if (p.maps[k].ownerRow != row) continue;
                const auto& members = p.layerInstances[k];
                const bool listed = std::find(members.begin(), members.end(), i) != members.end();
                EXPECT_EQ(listed, owner == p.maps[k].cluster + 1) << "layer " << k << " instance " << i;
            }
        }
    }
}

TEST(CausticLayers, LevelSceneShowsOnlyTheCausticsNearTheCamera) {
    scene::Scene level = scene::makeLevelScene();
    ASSERT_GE(level.lights.size(), 17u);
    const scene::Camera& cam = level.cameras.front();
    auto constants = makeCameraConstants(cam, 256, 144, 0);
    ASSERT_TRUE(constants);
    const CausticView view = causticViewOf(constants.value());
    CausticPlanOptions o;
    o.view = &view;
    o.photons = 1u << 18;
    const SpecularBounds bounds = computeSpecularBounds(level);
    EXPECT_GE(bounds.instanceSpheres.size(), 32u);
    CausticMapPlan p = planCausticMaps(level, bounds, o);
    CausticMapPlan unseen = planCausticMaps(level, bounds);
    EXPECT_GT(p.maps.size(), 0u);
    EXPECT_LT(p.maps.size(), unseen.maps.size()) << "clusters out of view get no layer";
    EXPECT_GT(p.hiddenClusters, 0u);
    double sum = 0.0;
    for (const CausticMapGpu& m : p.maps) sum += m.photons;
    EXPECT_NEAR(sum, double(1u << 18), 2.0);
}

}  // namespace
}  // namespace caustics

namespace caustics {
namespace {

// The table top's glass, water, sphere and ring stand within 0.4 m: one layer per light, as with one
// map per light (the paper's scene keeps its images).
TEST(CausticLayers, TableTopKeepsOneLayerPerLight) {
    auto table = scene::makeBuiltin("builtin");
    ASSERT_TRUE(table);
    CausticMapPlan p = planCausticMaps(table.value(), computeSpecularBounds(table.value()));
    ASSERT_EQ(p.maps.size(), 2u);
    for (const CausticMapGpu& m : p.maps) EXPECT_EQ(m.cluster, 0u);
    EXPECT_EQ(p.layerInstances[0].size(), 4u);
}

}  // namespace
}  // namespace caustics
