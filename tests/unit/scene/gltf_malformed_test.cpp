// Each malformed file gives an error that starts with the file path and names the problem.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "caustics/rhi/log.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/procedural_textures.h"

namespace caustics::scene {
namespace {

using namespace test;

class GltfMalformed : public ::testing::Test {
protected:
    void SetUp() override {
        dir = testDir();
        setLogCallback([](LogLevel, std::string_view) {});   // the warnings are not under test here
    }
    void TearDown() override { setLogCallback(nullptr); }

    // Loads and checks: failure, message starts with the path, and contains `problem`.
    void expectError(const std::string& path, const std::string& problem, const LoadOptions& options = {}) {
        auto scene = loadGltf(path, options);
        ASSERT_FALSE(scene.ok()) << "loaded a malformed file: " << path;
        EXPECT_EQ(scene.message().rfind(path, 0), 0u) << scene.message();
        EXPECT_NE(scene.message().find(problem), std::string::npos) << "message: " << scene.message();
    }

    std::filesystem::path dir;
    TriangleAsset asset = makeTriangleAsset();
};

TEST_F(GltfMalformed, MissingFileIsReported) { expectError((dir / "nope.gltf").string(), "file not found"); }

TEST_F(GltfMalformed, EmptyFileIsReported) {
    writeText(dir / "empty.gltf", "");
    expectError((dir / "empty.gltf").string(), "the file is empty");
}

TEST_F(GltfMalformed, InvalidJsonIsReported) {
    writeText(dir / "bad.gltf", "{ \"asset\": { \"version\": \"2.0\" ");
    expectError((dir / "bad.gltf").string(), "parse error");
}

TEST_F(GltfMalformed, MissingBufferFileIsReported) {
    std::string path = writeAsset(dir, asset);
    std::filesystem::remove(dir / "tri.bin");
    expectError(path, "tri.bin");
}

TEST_F(GltfMalformed, AccessorBeyondItsBufferViewIsReported) {
    asset.gltf["accessors"][0]["count"] = 4;   // 4 * 12 bytes > the 36-byte view
    expectError(writeAsset(dir, asset), "accessor 0 (POSITION of mesh 0 primitive 0) (count 4, byteOffset 0, stride 12, needs 48 bytes) is out of range of its buffer view 0 (36 bytes)");
}

TEST_F(GltfMalformed, BufferViewBeyondItsBufferIsReported) {
    asset.gltf["bufferViews"][0]["byteLength"] = 400;
    expectError(writeAsset(dir, asset), "out of range of buffer 0");
}

TEST_F(GltfMalformed, IndexBeyondTheVerticesIsReported) {
    asset.bin[36 + 2 * 2] = 7;   // third index = 7 with 3 vertices
    expectError(writeAsset(dir, asset), "index 7 at position 2 is out of range of the 3 vertices");
}

TEST_F(GltfMalformed, PositionOfWrongTypeIsReported) {
    asset.gltf["accessors"][0]["type"] = "VEC2";
    asset.gltf["accessors"][0]["min"] = {0, 0};
    asset.gltf["accessors"][0]["max"] = {1, 1};
    expectError(writeAsset(dir, asset), "POSITION accessor 0 of mesh 0 primitive 0 is VEC2/FLOAT; glTF requires VEC3/FLOAT");
}

TEST_F(GltfMalformed, IndicesOfFloatComponentTypeAreReported) {
    asset.gltf["accessors"][1]["componentType"] = 5126;
    asset.gltf["accessors"][1]["count"] = 1;
    expectError(writeAsset(dir, asset), "indices accessor 1 of mesh 0 primitive 0 is SCALAR/FLOAT");
}

TEST_F(GltfMalformed, UnsupportedRequiredExtensionIsReported) {
    asset.gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    asset.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectError(writeAsset(dir, asset), "requires the unsupported extension 'KHR_draco_mesh_compression'");
}

TEST_F(GltfMalformed, FileWithoutMeshesIsReported) {
    asset.gltf.erase("meshes");
    asset.gltf["nodes"] = json::array({json::object()});
    expectError(writeAsset(dir, asset), "contains no meshes");
}

TEST_F(GltfMalformed, TriangleLimitIsEnforcedAndNamed) {
    LoadOptions options;
    options.maxTriangles = 0;
    expectError(writeAsset(dir, asset), "LoadOptions::maxTriangles", options);
}

TEST_F(GltfMalformed, TextureLimitIsEnforcedAndNamed) {
    Scene scene = makeGlassSphereScene({.tessellation = 8});
    scene.textures.push_back(makeTileTexture(8, glm::vec3(0.5f), glm::vec3(0.1f), 2, 0.0f, 1));
    std::string path = (dir / "textured.glb").string();
    ASSERT_TRUE(writeGltf(scene, path).ok());
    LoadOptions options;
    options.maxTextureDimension = 4;
    expectError(path, "image 0 is 8x8, larger than the limit LoadOptions::maxTextureDimension = 4", options);
}

TEST_F(GltfMalformed, NanPositionIsReported) {
    float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&asset.bin[4 * 4], &nan, 4);   // vertex 1, y
    expectError(writeAsset(dir, asset), "non-finite value (NaN or inf) at vertex 1");
}

TEST_F(GltfMalformed, NodeCycleIsReported) {
    asset.gltf["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
    expectError(writeAsset(dir, asset), "appears twice in the node hierarchy");
}

TEST_F(GltfMalformed, NodeWithMissingMeshIsReported) {
    asset.gltf["nodes"][0]["mesh"] = 5;
    expectError(writeAsset(dir, asset), "node 0 refers to mesh 5, but the file has 1 meshes");
}

TEST_F(GltfMalformed, MissingMaterialIsReported) {
    asset.gltf["meshes"][0]["primitives"][0]["material"] = 3;
    expectError(writeAsset(dir, asset), "refers to material 3, but the file has 0 materials");
}

TEST_F(GltfMalformed, TruncatedGlbIsReported) {
    std::vector<uint8_t> glb = makeGlb(asset.gltf, asset.bin);
    glb.resize(glb.size() - 20);
    writeBytes(dir / "cut.glb", glb);
    auto scene = loadGltf((dir / "cut.glb").string());
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.message().rfind((dir / "cut.glb").string(), 0), 0u) << scene.message();
}

TEST_F(GltfMalformed, HostileJsonNestingIsRefusedBeforeParsing) {
    std::string text = asset.gltf.dump();
    text.insert(text.size() - 1, ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']'));
    writeBytes(dir / "tri.bin", asset.bin);
    writeText(dir / "deep.gltf", text);
    expectError((dir / "deep.gltf").string(), "nesting deeper than 256 levels");
}

TEST_F(GltfMalformed, GlbWithoutMagicIsReported) {
    writeText(dir / "text.glb", "this is not a binary glTF");
    expectError((dir / "text.glb").string(), "no 'glTF' magic");
}

}  // namespace
}  // namespace caustics::scene
