// Values that made a black or NaN image, a misleading message, or were out of spec and accepted silently
// (docs/viewer.md, "Untrusted glTF"): each is refused with the field, the value and the limit named, or
// loaded clamped with a warning that names them.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "caustics/rhi/log.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"

namespace caustics::scene {
namespace {

using namespace test;

std::vector<std::string>* gWarnings = nullptr;

class GltfValues : public ::testing::Test {
protected:
    void SetUp() override {
        dir = testDir();
        gWarnings = &warnings;
        setLogCallback([](LogLevel, std::string_view m) { gWarnings->emplace_back(m); });
    }
    void TearDown() override {
        setLogCallback(nullptr);
        gWarnings = nullptr;
    }

    Result<Scene> load() { return loadGltf(writeAsset(dir, asset)); }
    void expectError(const std::string& words) {
        auto scene = load();
        ASSERT_FALSE(scene.ok()) << "loaded";
        EXPECT_NE(scene.message().find(words), std::string::npos) << scene.message();
    }
    bool warned(const std::string& words) const {
        for (const std::string& w : warnings)
            if (w.find(words) != std::string::npos) return true;
        return false;
    }
    std::string allWarnings() const {
        std::string all;
        for (const std::string& w : warnings) all += w + "\n";
        return all;
    }
    void addLight(const json& light) {
        asset.gltf["extensionsUsed"] = {"KHR_lights_punctual"};
        asset.gltf["extensions"]["KHR_lights_punctual"]["lights"] = json::array({light});
        asset.gltf["nodes"].push_back({{"name", "lamp node"}, {"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        asset.gltf["scenes"][0]["nodes"].push_back(asset.gltf["nodes"].size() - 1);
    }

    std::filesystem::path dir;
    TriangleAsset asset = makeTriangleAsset();
    std::vector<std::string> warnings;
};

// Positions scaled into place by a node (the triangle's vertices are at most 1 from the origin).
TEST_F(GltfValues, GeometryFarPast1e6MetresIsSkippedAndAnEmptySceneRefused) {
    asset.gltf["nodes"][0]["translation"] = {1e9, 0, 0};
    expectError("every mesh instance was skipped (1), the image would be empty: node 0 places its mesh up to 1e+09 m from the origin "
                "(more than 1e6 m)");
}

TEST_F(GltfValues, Light1e38IsClampedToTheLimitWithAWarning) {
    addLight({{"type", "point"}, {"name", "sun"}, {"intensity", 1e38}});
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    ASSERT_EQ(scene->lights.size(), 1u);
    EXPECT_EQ(scene->lights[0].intensity, LoadOptions{}.maxLightIntensity);
    EXPECT_TRUE(warned("light 0 ('sun'): intensity 1e+38 cd is outside [0, 1e+06] cd; using 1e+06 cd")) << allWarnings();
}

TEST_F(GltfValues, LightColourPastOneIsClampedWithAWarning) {
    addLight({{"type", "directional"}, {"color", {3e38, 0.5, 1}}, {"intensity", 2}});
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->lights[0].color, glm::vec3(1.0f, 0.5f, 1.0f));
    EXPECT_TRUE(warned("light 0: color[0] 3e+38 is outside [0, 1]; using 1")) << allWarnings();
}

TEST_F(GltfValues, EmissionIsLimitedToTheLightLimit) {
    asset.gltf["materials"] = json::array({{{"emissiveFactor", {1, 1, 1}},
                                            {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e30}}}}}}});
    asset.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->materials[0].emissive, glm::vec3(1e6f));
    EXPECT_TRUE(warned("material 0: KHR_materials_emissive_strength.emissiveStrength 1e+30 is outside [0, 1e+06]")) << allWarnings();
}

// The exporter keeps emissiveFactor in [0, 1] and writes the rest as KHR_materials_emissive_strength,
// so the importer's clamp never loses what the engine itself wrote.
TEST_F(GltfValues, EmissionAboveOneSurvivesTheRoundTripWithoutAWarning) {
    Scene s = makeGlassSphereScene({.tessellation = 4});
    s.materials[0].emissive = {5.0f, 2.5f, 0.0f};
    auto path = (dir / "emissive.gltf").string();
    ASSERT_TRUE(writeGltf(s, path).ok());
    auto loaded = loadGltf(path);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    EXPECT_NEAR(loaded->materials[0].emissive.r, 5.0f, 1e-5f);
    EXPECT_NEAR(loaded->materials[0].emissive.g, 2.5f, 1e-5f);
    EXPECT_FALSE(warned("emissive")) << allWarnings();
}

TEST_F(GltfValues, PrimitiveOfZeroAreaTrianglesIsSkippedAndAFileOfOnlyThoseRefused) {
    float line[9] = {0, 0, 0, 1, 0, 0, 2, 0, 0};   // three collinear points
    std::memcpy(asset.bin.data(), line, sizeof(line));
    expectError("has no triangle of non-zero area (1 primitives, every triangle degenerate): the image would be empty");
    EXPECT_TRUE(warned("mesh 0 primitive 0: all 1 triangles have zero area (nothing to render); skipped")) << allWarnings();
}

TEST_F(GltfValues, NonAffineMatrixIsRefusedNamingTheBottomRow) {
    asset.gltf["nodes"][0]["matrix"] = {1, 0, 0, 0.25, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expectError("node 0 has a matrix whose bottom row is (0.25, 0, 0, 1), not (0, 0, 0, 1): glTF 2.0 node matrices must be affine");
}

TEST_F(GltfValues, ByteStrideOutsideTheSchemaRangeNamesTheRange) {
    for (long long stride : {1LL << 30, 2LL, 6LL, 256LL}) {
        asset.gltf["bufferViews"][0]["byteStride"] = stride;
        expectError("bufferViews[0].byteStride is " + std::to_string(stride) + "; glTF 2.0 allows a multiple of 4 from 4 to 252");
    }
}

TEST_F(GltfValues, BadBase64IsNamedNotBlamedOnByteLength) {
    std::string uri = "data:application/octet-stream;base64,AAAA*AAA";
    asset.gltf["buffers"][0] = {{"uri", uri}, {"byteLength", 6}};
    expectError("buffers[0].uri: the data URI's base64 payload has the invalid character '*' at offset 4");
    asset.gltf["buffers"][0]["uri"] = "data:text/html;base64,AAAA";
    expectError("buffers[0].uri is a data URI of media type 'text/html'");
}

TEST_F(GltfValues, NegativeIntensityIsRefusedWithItsValue) {
    addLight({{"type", "point"}, {"name", "minus"}, {"intensity", -5}});
    expectError("light 0 ('minus') has intensity -5; KHR_lights_punctual requires a finite intensity >= 0");
}

TEST_F(GltfValues, NumericVersionIsRecognisedAsGltf1) {
    asset.gltf["asset"]["version"] = 1;
    expectError("asset.version is the number 1, not a string: a glTF 1 file?");
    asset.gltf["asset"].erase("version");
    expectError("asset.version is missing");
}

TEST_F(GltfValues, PrimitivesAndTopLevelFieldsOfTheWrongTypeAreNamed) {
    asset.gltf["meshes"][0]["primitives"] = {{"attributes", {{"POSITION", 0}}}};   // an object, not an array
    expectError("meshes[0].primitives is object, not an array of primitives");
    asset = makeTriangleAsset();
    asset.gltf["nodes"] = {{"mesh", 0}};
    expectError("\"nodes\" is object, not an array");
}

TEST_F(GltfValues, GlbNamedGltfLoadsByItsMagic) {
    writeBytes(dir / "binary.gltf", makeGlb(asset.gltf, asset.bin));
    auto scene = loadGltf((dir / "binary.gltf").string());
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->meshes.size(), 1u);
}

TEST_F(GltfValues, TruncatedAndOversizedGlbChunksNameTheLengths) {
    std::vector<uint8_t> glb = makeGlb(asset.gltf, asset.bin);
    std::vector<uint8_t> cut(glb.begin(), glb.end() - 8);
    writeBytes(dir / "cut.glb", cut);
    auto scene = loadGltf((dir / "cut.glb").string());
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.message().find("GLB header declares a length of " + std::to_string(glb.size()) + " bytes, but the file has " +
                                   std::to_string(cut.size()) + " (truncated?)"),
              std::string::npos)
        << scene.message();
    std::vector<uint8_t> big = glb;
    uint32_t huge = 0x7FFFFFF0u;
    std::memcpy(big.data() + 12, &huge, 4);   // the JSON chunk's length
    writeBytes(dir / "big.glb", big);
    scene = loadGltf((dir / "big.glb").string());
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.message().find("GLB JSON chunk declares 2147483632 bytes, but only"), std::string::npos) << scene.message();
    std::vector<uint8_t> bin = glb;
    uint32_t binAt = 20 + [&] { uint32_t n; std::memcpy(&n, glb.data() + 12, 4); return n; }();
    std::memcpy(bin.data() + binAt, &huge, 4);   // the BIN chunk's length
    writeBytes(dir / "bin.glb", bin);
    scene = loadGltf((dir / "bin.glb").string());
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.message().find("GLB BIN chunk declares 2147483632 bytes, but only"), std::string::npos) << scene.message();
}

TEST_F(GltfValues, IorBelowOneIsClampedWithAWarning) {
    for (double ior : {0.0, -2.0}) {
        warnings.clear();
        asset.gltf["materials"] = json::array({{{"name", "glass"}, {"extensions", {{"KHR_materials_ior", {{"ior", ior}}}}}}});
        asset.gltf["meshes"][0]["primitives"][0]["material"] = 0;
        auto scene = load();
        ASSERT_TRUE(scene.ok()) << scene.message();
        EXPECT_EQ(scene->materials[0].ior, 1.0f);
        char value[16];
        std::snprintf(value, sizeof(value), "%g", ior);
        EXPECT_TRUE(warned("material 0 ('glass'): KHR_materials_ior.ior " + std::string(value) + " is outside [1, 1000]; using 1"))
            << allWarnings();
    }
}

TEST_F(GltfValues, TransmissionAboveOneIsClampedWithAWarning) {
    asset.gltf["materials"] = json::array({{{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 2.0}}}}}}});
    asset.gltf["meshes"][0]["primitives"][0]["material"] = 0;
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->materials[0].transmission, 1.0f);
    EXPECT_TRUE(warned("material 0: KHR_materials_transmission.transmissionFactor 2 is outside [0, 1]; using 1")) << allWarnings();
}

TEST_F(GltfValues, SpotOuterConePastHalfPiIsClampedWithAWarning) {
    addLight({{"type", "spot"}, {"intensity", 10}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 3.0}}}});
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_NEAR(scene->lights[0].outerConeAngle, 1.5707963f, 1e-6f);
    EXPECT_TRUE(warned("light 0: spot.outerConeAngle 3 rad is outside [0, 1.5708] rad; using 1.5708 rad")) << allWarnings();
}

TEST_F(GltfValues, ZeroQuaternionIsIgnoredAndANonUnitOneNormalisedWithWarnings) {
    asset.gltf["nodes"][0]["rotation"] = {0, 0, 0, 0};
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->instances[0].transform, glm::mat4(1.0f));
    EXPECT_TRUE(warned("node 0 has rotation (0, 0, 0, 0), not a unit quaternion (glTF 2.0 5.25); using no rotation")) << allWarnings();
    warnings.clear();
    asset.gltf["nodes"][0]["rotation"] = {0, 0, 0, 2};   // the identity, twice too long
    scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->instances[0].transform, glm::mat4(1.0f));
    EXPECT_TRUE(warned("node 0 has rotation (0, 0, 0, 2) of length 2, not a unit quaternion (glTF 2.0 5.25); normalised")) << allWarnings();
}

TEST_F(GltfValues, CameraAspectZeroAndZfarBelowZnearAreWarned) {
    asset.gltf["cameras"] = json::array({{{"type", "perspective"},
                                          {"perspective", {{"yfov", 0.8}, {"aspectRatio", 0}, {"znear", 1.0}, {"zfar", 0.5}}}}});
    asset.gltf["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 3}}});
    asset.gltf["scenes"][0]["nodes"].push_back(1);
    auto scene = load();
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_TRUE(warned("cameras[0].perspective.aspectRatio is 0; glTF 2.0 requires a number above 0")) << allWarnings();
    EXPECT_TRUE(warned("cameras[0].perspective.zfar 0.5 is not above znear 1.0 (glTF 2.0 requires zfar > znear)")) << allWarnings();
}

}  // namespace
}  // namespace caustics::scene
