#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "caustics/rhi/log.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/mesh_utils.h"

namespace caustics::scene {
namespace {

using namespace test;

// Float tolerance: the transforms below are exact in binary except for cos/sin of 90 degrees
// (quaternion components 0.7071...), which leave errors of a few ulps.
constexpr float kEps = 1e-5f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

glm::vec3 worldPosition(const Scene& s, const Instance& inst, uint32_t vertex) {
    return glm::vec3(inst.transform * glm::vec4(s.meshes[inst.mesh].positions[vertex], 1.0f));
}

TEST(GltfImport, AppliesParentTranslationAndChildScale) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["nodes"] = json::array({{{"translation", {1, 2, 3}}, {"children", {1}}}, {{"scale", {2, 2, 2}}, {"mesh", 0}}});
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->instances.size(), 1u);
    const Instance& inst = scene->instances[0];
    // Vertex (1,0,0) -> scaled (2,0,0) -> translated (3,2,3).
    std::vector<glm::vec3> world;
    for (uint32_t v = 0; v < 3; ++v) world.push_back(worldPosition(*scene, inst, v));
    bool found = false;
    for (const glm::vec3& p : world) found |= glm::length(p - glm::vec3(3, 2, 3)) < kEps;
    EXPECT_TRUE(found);
}

TEST(GltfImport, AppliesColumnMajorMatrix) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    // glTF matrices are column-major: the translation (5, 6, 7) is in elements 12..14.
    a.gltf["nodes"] = json::array({{{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}, {"mesh", 0}}});
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    expectNear(glm::vec3(scene->instances[0].transform[3]), {5, 6, 7});
}

TEST(GltfImport, InstancesOfOneMeshGetUniqueObjectIds) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 0, 1}}}, {{"mesh", 0}}});
    a.gltf["scenes"][0]["nodes"] = {0, 1, 2};
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->instances.size(), 3u);
    EXPECT_NE(scene->instances[0].objectId, scene->instances[1].objectId);
    EXPECT_NE(scene->instances[1].objectId, scene->instances[2].objectId);
    EXPECT_NE(scene->instances[0].objectId, scene->instances[2].objectId);
}

TEST(GltfImport, MapsPbrAndMaterialExtensions) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["materials"] = json::array({{
        {"name", "glass"},
        {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.6, 0.7, 1}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.05}}},
        {"extensions", {
            {"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
            {"KHR_materials_ior", {{"ior", 1.33}}},
            {"KHR_materials_volume", {{"thicknessFactor", 0.02}, {"attenuationDistance", 0.5}, {"attenuationColor", {0.9, 0.8, 0.7}}}},
            {"KHR_materials_specular", {{"specularFactor", 0.4}, {"specularColorFactor", {1.0, 0.5, 0.25}}}},
        }},
    }});
    a.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    a.gltf["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume", "KHR_materials_specular"};
    a.gltf["extensionsRequired"] = {"KHR_materials_transmission"};
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    const Material& m = scene->materials[scene->meshes[0].material];
    expectNear(m.baseColor, {0.5f, 0.6f, 0.7f});
    EXPECT_FLOAT_EQ(m.roughness, 0.05f);
    EXPECT_FLOAT_EQ(m.transmission, 0.9f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.thickness, 0.02f);
    EXPECT_FLOAT_EQ(m.attenuationDistance, 0.5f);
    expectNear(m.attenuationColor, {0.9f, 0.8f, 0.7f});
    EXPECT_FLOAT_EQ(m.specular, 0.4f);
    expectNear(m.specularColor, {1.0f, 0.5f, 0.25f});
    EXPECT_TRUE(m.isSpecular());
}

TEST(GltfImport, ImportsLightsShiningAlongNodeMinusZ) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
    a.gltf["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({
        {{"type", "spot"}, {"intensity", 12.0}, {"color", {1, 0.5, 0.25}}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}},
        {{"type", "directional"}, {"intensity", 3.0}},
        {{"type", "point"}, {"intensity", 7.0}, {"range", 9.0}},
    })}}}};
    const double h = std::sqrt(0.5);   // rotation of -90 degrees about X maps -Z to -Y
    a.gltf["nodes"].push_back({{"translation", {1, 4, 2}}, {"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    a.gltf["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    a.gltf["nodes"].push_back({{"translation", {0, 3, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    a.gltf["scenes"][0]["nodes"] = {0, 1, 2, 3};
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->lights.size(), 3u);
    const Light& spot = scene->lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    expectNear(spot.position, {1, 4, 2});
    expectNear(spot.direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(spot.intensity, 12.0f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.4f);
    expectNear(spot.color, {1.0f, 0.5f, 0.25f});
    EXPECT_EQ(scene->lights[1].type, LightType::Directional);
    expectNear(scene->lights[1].direction, {0, 0, -1});
    EXPECT_EQ(scene->lights[2].type, LightType::Point);
    EXPECT_FLOAT_EQ(scene->lights[2].range, 9.0f);
    expectNear(scene->lights[2].position, {0, 3, 0});
}

TEST(GltfImport, ImportsPerspectiveCameraLookingDownMinusZ) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.1}, {"zfar", 50.0}}}}});
    a.gltf["nodes"].push_back({{"translation", {0, 1, 5}}, {"camera", 0}});
    a.gltf["scenes"][0]["nodes"] = {0, 1};
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->cameras.size(), 1u);
    const Camera& c = scene->cameras[0];
    expectNear(c.eye, {0, 1, 5});
    expectNear(glm::normalize(c.target - c.eye), {0, 0, -1});
    expectNear(c.up, {0, 1, 0});
    EXPECT_FLOAT_EQ(c.verticalFovRadians, 0.6f);
    EXPECT_FLOAT_EQ(c.nearPlane, 0.1f);
    EXPECT_FLOAT_EQ(c.farPlane, 50.0f);
}

TEST(GltfImport, LoadsGlbWithUint8Indices) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    std::vector<uint8_t> bin(a.bin.begin(), a.bin.begin() + 36);
    for (uint8_t i : {0, 1, 2}) bin.push_back(i);
    a.gltf["accessors"][1]["componentType"] = 5121;
    a.gltf["bufferViews"][1]["byteLength"] = 3;
    writeBytes(dir / "tri.glb", makeGlb(a.gltf, bin));
    auto scene = loadGltf((dir / "tri.glb").string());
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(triangleCount(*scene), 1u);
}

TEST(GltfImport, NonIndexedPrimitiveGetsFlatNormals) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["meshes"][0]["primitives"][0].erase("indices");
    auto scene = loadGltf(writeAsset(dir, a));
    ASSERT_TRUE(scene.ok()) << scene.message();
    const Mesh& mesh = scene->meshes[0];
    ASSERT_EQ(mesh.indices.size(), 3u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    // Counter-clockwise (0,0,0) (1,0,0) (0,1,0) faces +Z.
    for (const glm::vec3& n : mesh.normals) expectNear(n, {0, 0, 1});
}

TEST(GltfImport, MissingTextureImageIsWarnedAndReplacedByWhite) {
    auto dir = testDir();
    TriangleAsset a = makeTriangleAsset();
    a.gltf["images"] = json::array({{{"uri", "missing.png"}}});
    a.gltf["textures"] = json::array({{{"source", 0}}});
    a.gltf["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    a.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    std::vector<std::string> warnings;
    setLogCallback([&](LogLevel level, std::string_view msg) { if (level == LogLevel::Warning) warnings.emplace_back(msg); });
    auto scene = loadGltf(writeAsset(dir, a));
    setLogCallback(nullptr);
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->textures.size(), 1u);
    EXPECT_EQ(scene->textures[0].width, 1u);
    EXPECT_EQ(scene->textures[0].rgba8, (std::vector<uint8_t>{255, 255, 255, 255}));
    EXPECT_EQ(scene->materials[0].baseColorTexture, 0);
    bool named = false;
    for (const std::string& w : warnings) named |= w.find("missing.png") != std::string::npos && w.find("tri.gltf") != std::string::npos;
    EXPECT_TRUE(named) << "no warning naming the file and the image";
}

TEST(GltfRoundTrip, BuiltinTableSurvivesWriteAndLoadAsGlb) {
    auto dir = testDir();
    Scene original = makeBuiltinScene("builtin");
    std::string path = (dir / "builtin.glb").string();
    ASSERT_TRUE(writeGltf(original, path).ok());
    LoadOptions options;
    options.sortTriangles = false;   // keep the stored order so triangles compare one to one
    auto loaded = loadGltf(path, options);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    ASSERT_EQ(loaded->meshes.size(), original.meshes.size());
    EXPECT_EQ(triangleCount(*loaded), triangleCount(original));
    for (size_t m = 0; m < original.meshes.size(); ++m) {
        EXPECT_EQ(loaded->meshes[m].indices, original.meshes[m].indices);
        EXPECT_EQ(loaded->meshes[m].positions, original.meshes[m].positions);
    }
    ASSERT_EQ(loaded->materials.size(), original.materials.size());
    for (size_t i = 0; i < original.materials.size(); ++i) {
        EXPECT_FLOAT_EQ(loaded->materials[i].ior, original.materials[i].ior);
        EXPECT_FLOAT_EQ(loaded->materials[i].transmission, original.materials[i].transmission);
        EXPECT_FLOAT_EQ(loaded->materials[i].metallic, original.materials[i].metallic);
        EXPECT_EQ(loaded->materials[i].isSpecular(), original.materials[i].isSpecular());
        EXPECT_EQ(loaded->materials[i].baseColorTexture, original.materials[i].baseColorTexture);
    }
    ASSERT_EQ(loaded->textures.size(), original.textures.size());
    EXPECT_EQ(loaded->textures[0].rgba8, original.textures[0].rgba8);   // PNG is lossless
    ASSERT_EQ(loaded->lights.size(), original.lights.size());
    for (size_t i = 0; i < original.lights.size(); ++i) {
        EXPECT_EQ(loaded->lights[i].type, original.lights[i].type);
        expectNear(loaded->lights[i].position, original.lights[i].position);
        expectNear(loaded->lights[i].direction, original.lights[i].direction, 1e-4f);   // via a quaternion
        EXPECT_FLOAT_EQ(loaded->lights[i].intensity, original.lights[i].intensity);
    }
    ASSERT_EQ(loaded->cameras.size(), original.cameras.size());
    expectNear(loaded->cameras[0].eye, original.cameras[0].eye);
    expectNear(glm::normalize(loaded->cameras[0].target - loaded->cameras[0].eye),
               glm::normalize(original.cameras[0].target - original.cameras[0].eye), 1e-4f);
}

TEST(GltfRoundTrip, GltfTextFormWithEmbeddedBufferLoads) {
    auto dir = testDir();
    Scene original = makeGlassSphereScene();
    std::string path = (dir / "sphere.gltf").string();
    ASSERT_TRUE(writeGltf(original, path).ok());
    auto loaded = loadGltf(path);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    EXPECT_EQ(triangleCount(*loaded), triangleCount(original));
    EXPECT_EQ(loaded->lights.size(), 1u);
}

}  // namespace
}  // namespace caustics::scene
