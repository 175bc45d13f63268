#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"

namespace caustics::scene {
namespace {

// True if any specular instance's bounding sphere reaches into the light's cone (spot) or the
// light is omnidirectional (point/directional see everything in front of them).
bool lightSeesSpecular(const Scene& scene, const Light& light) {
    for (const Instance& inst : scene.instances) {
        if (!isSpecularInstance(scene, inst)) continue;
        if (light.type != LightType::Spot) return true;
        Aabb box = instanceBounds(scene, inst);
        glm::vec3 toCenter = box.center() - light.position;
        float d = glm::length(toCenter);
        float radius = 0.5f * glm::length(box.extent());
        if (d <= radius) return true;
        float angle = std::acos(std::clamp(glm::dot(toCenter / d, glm::normalize(light.direction)), -1.0f, 1.0f));
        if (angle - std::asin(radius / d) < light.outerConeAngle) return true;
    }
    return false;
}

// Signed volume by the divergence theorem: positive for a closed mesh with outward normals.
double signedVolume(const Mesh& m) {
    double v = 0.0;
    for (size_t t = 0; t < m.indices.size(); t += 3)
        v += glm::dot(glm::dvec3(m.positions[m.indices[t]]),
                      glm::cross(glm::dvec3(m.positions[m.indices[t + 1]]), glm::dvec3(m.positions[m.indices[t + 2]]))) / 6.0;
    return v;
}

const Material* materialNamed(const Scene& s, const std::string& prefix) {
    for (const Material& m : s.materials) if (m.name.rfind(prefix, 0) == 0) return &m;
    return nullptr;
}

TEST(BuiltinTable, HasThreeLightsOfWhichOnlyTheThirdSeesNoSpecularObject) {
    Scene s = makeBuiltinScene("builtin");
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
    EXPECT_EQ(s.lights[1].type, LightType::Point);
    EXPECT_TRUE(lightSeesSpecular(s, s.lights[0]));
    EXPECT_TRUE(lightSeesSpecular(s, s.lights[1]));
    EXPECT_FALSE(lightSeesSpecular(s, s.lights[2]));
}

TEST(BuiltinTable, AliasNameGivesTheSameScene) {
    EXPECT_EQ(triangleCount(makeBuiltinScene("builtin:table")), triangleCount(makeBuiltinScene("builtin")));
}

TEST(BuiltinTable, CausticObjectsHaveThePapersOpticalProperties) {
    Scene s = makeBuiltinScene("builtin");
    const Material* glass = materialNamed(s, "glass");
    const Material* water = materialNamed(s, "water");
    const Material* metal = materialNamed(s, "polished metal");
    ASSERT_TRUE(glass && water && metal);
    EXPECT_FLOAT_EQ(glass->ior, 1.5f);
    EXPECT_FLOAT_EQ(water->ior, 1.33f);
    EXPECT_EQ(glass->roughness, 0.0f);
    EXPECT_EQ(water->transmission, 1.0f);
    EXPECT_EQ(metal->metallic, 1.0f);
    EXPECT_LE(metal->roughness, 0.05f);
    EXPECT_TRUE(glass->isSpecular() && water->isSpecular() && metal->isSpecular());
    size_t specular = 0;
    for (const Instance& i : s.instances) specular += isSpecularInstance(s, i);
    EXPECT_EQ(specular, 4u);   // glass shell, water, sphere, ring
    EXPECT_GT(triangleCount(s), 10000u);   // the 96x48 sphere alone has 9216
    EXPECT_FALSE(s.isStandIn);
    EXPECT_FALSE(s.cameras.empty());
}

TEST(BuiltinTable, ObjectIdsAreUnique) {
    Scene s = makeBuiltinScene("builtin");
    std::set<uint32_t> ids;
    for (const Instance& i : s.instances) ids.insert(i.objectId);
    EXPECT_EQ(ids.size(), s.instances.size());
    EXPECT_EQ(ids.count(0u), 0u);   // 0 means "no object"
}

TEST(BuiltinTable, SpecularObjectsStandOnTheTable) {
    Scene s = makeBuiltinScene("builtin");
    Aabb spec = specularBounds(s);
    // 1 mm: the tessellated sphere touches the table at its pole.
    EXPECT_NEAR(spec.min.y, 0.0f, 1e-3f);
    EXPECT_LT(spec.max.y, 0.2f);
}

TEST(BuiltinAtrium, IsASponzaScaleStandInLabelledAsSuch) {
    auto s = makeBuiltin("builtin:atrium");
    ASSERT_TRUE(s.ok());
    EXPECT_TRUE(s->isStandIn);
    EXPECT_EQ(s->name, "atrium (Sponza stand-in, generated)");
    // Sponza has ~262k triangles; the stand-in must be of the same weight (+-8%).
    EXPECT_GT(triangleCount(*s), 240000u);
    EXPECT_LT(triangleCount(*s), 280000u);
    ASSERT_EQ(s->lights.size(), 3u);
    EXPECT_TRUE(lightSeesSpecular(*s, s->lights[0]));
    EXPECT_FALSE(lightSeesSpecular(*s, s->lights[2]));
    Aabb box = sceneBounds(*s);
    EXPECT_GT(box.extent().x, 20.0f);
    EXPECT_GT(box.extent().y, 10.0f);
    EXPECT_FALSE(s->textures.empty());
}

TEST(BuiltinScenes, UnknownNameIsAnErrorListingTheKnownOnes) {
    auto s = makeBuiltin("builtin:moon");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("builtin:moon"), std::string::npos);
    EXPECT_NE(s.message().find("builtin:atrium"), std::string::npos);
}

TEST(AnalyticScenes, GlassSphereHasTheRequestedRadiusAndOneDirectionalLight) {
    Scene s = makeGlassSphereScene({.radius = 0.25f, .height = 1.0f});
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    Aabb b = specularBounds(s);
    EXPECT_NEAR(b.extent().x, 0.5f, 1e-4f);   // the poles/equator vertices lie on the sphere
    EXPECT_NEAR(b.center().y, 1.0f, 1e-4f);
    const Mesh& sphere = s.meshes[s.instances.back().mesh];
    // Inscribed polyhedron of 128x64: volume within 0.2% of 4/3 pi R^3.
    EXPECT_NEAR(signedVolume(sphere), 4.0 / 3.0 * M_PI * std::pow(0.25, 3), 0.002 * 4.0 / 3.0 * M_PI * std::pow(0.25, 3));
}

TEST(AnalyticScenes, GlassSlabHasTwoParallelFacesAtTheGivenHeights) {
    Scene s = makeGlassSlabScene({.height = 0.5f, .thickness = 0.1f});
    Aabb b = specularBounds(s);
    EXPECT_NEAR(b.min.y, 0.5f, 1e-6f);
    EXPECT_NEAR(b.max.y, 0.6f, 1e-6f);
    EXPECT_FLOAT_EQ(s.materials[s.meshes[s.instances.back().mesh].material].ior, 1.5f);
}

TEST(AnalyticScenes, MetalRingIsAMetallicBandOnThePlane) {
    Scene s = makeMetalRingScene();
    const Instance& ring = s.instances.back();
    EXPECT_TRUE(isSpecularInstance(s, ring));
    EXPECT_EQ(s.materials[s.meshes[ring.mesh].material].metallic, 1.0f);
    EXPECT_NEAR(specularBounds(s).min.y, 0.0f, 1e-6f);
}

TEST(MeshBuilder, ClosedShapesHaveOutwardNormalsAndTheirVolume) {
    // Polygonal approximations with 256 segments: area error ~ (2 pi / 256)^2 / 6 ~ 1e-4 relative.
    double tube = signedVolume(makeTube(0.05f, 0.04f, 0.1f, 256, 0.0f));
    EXPECT_NEAR(tube, M_PI * (0.05 * 0.05 - 0.04 * 0.04) * 0.1, 1e-3 * tube);
    double glass = signedVolume(makeTube(0.05f, 0.04f, 0.1f, 256, 0.01f));
    EXPECT_NEAR(glass, M_PI * (0.05 * 0.05 - 0.04 * 0.04) * 0.09 + M_PI * 0.05 * 0.05 * 0.01, 1e-3 * glass);
    double cyl = signedVolume(makeCylinder(0.3f, 2.0f, 256, 4, true));
    EXPECT_NEAR(cyl, M_PI * 0.09 * 2.0, 1e-3 * cyl);
    double box = signedVolume(makeBox({1.0f, 2.0f, 3.0f}));
    EXPECT_NEAR(box, 48.0, 1e-4);
}

TEST(ModifiedSponza, AddsCausticObjectsAndLightsAtTheFloorCentre) {
    auto dir = test::testDir();
    Scene court;   // a 20 x 10 x 12 m box standing on y = 0, centred at x = 5
    court.materials.push_back({});
    Mesh box = makeBox({10.0f, 5.0f, 6.0f});
    for (glm::vec3& p : box.positions) p += glm::vec3(5.0f, 5.0f, 0.0f);
    court.meshes.push_back(box);
    court.instances.push_back({0, glm::mat4(1.0f), 1});
    std::string path = (dir / "court.glb").string();
    ASSERT_TRUE(writeGltf(court, path).ok());
    auto s = loadModifiedSponza(path);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s->lights.size(), 3u);
    Aabb spec = specularBounds(*s);
    ASSERT_FALSE(spec.empty());
    EXPECT_NEAR(spec.min.y, 0.0f, 1e-2f);
    EXPECT_NEAR(spec.center().x, 5.0f, 2.0f);   // the group is ~0.45 scale units wide around the origin
    EXPECT_NEAR(spec.center().z, 0.0f, 2.0f);
    EXPECT_FALSE(lightSeesSpecular(*s, s->lights[2]));
    std::set<uint32_t> ids;
    for (const Instance& i : s->instances) ids.insert(i.objectId);
    EXPECT_EQ(ids.size(), s->instances.size());
}

TEST(ModifiedSponza, MissingFileErrorNamesIt) {
    auto s = loadModifiedSponza("/nonexistent/sponza.gltf");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message().rfind("/nonexistent/sponza.gltf", 0), 0u);
}

}  // namespace
}  // namespace caustics::scene
