// Deterministic mutation fuzzing of the glTF loader: byte flips, truncation, JSON field deletion and
// random numbers in place of JSON values. The property: loadGltf never crashes or throws, and a
// failure always names the file (the message starts with its path).
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "caustics/rhi/log.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/procedural_textures.h"

namespace caustics::scene {
namespace {

using nlohmann::json;

// Thousands of small rewrites: a RAM file system where there is one (rewrites of files on this
// machine's disk cost ~7 ms each), else the temp directory.
std::filesystem::path fuzzDir() {
    std::error_code ec;
    std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec) ? std::filesystem::path("/dev/shm")
                                                                                : std::filesystem::temp_directory_path();
    auto dir = base / "caustics_gltf_fuzz";
    std::filesystem::create_directories(dir);
    return dir;
}

std::vector<uint8_t> readAll(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeAll(const std::filesystem::path& p, const std::vector<uint8_t>& bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A small but feature-complete seed: meshes, a texture, materials with extensions, 1 light, 1 camera.
Scene seedScene() {
    Scene s = makeGlassSphereScene({.tessellation = 6});
    s.textures.push_back(makeTileTexture(4, glm::vec3(0.5f), glm::vec3(0.1f), 2, 0.1f, 1));
    s.materials[0].baseColorTexture = 0;
    return s;
}

class GltfFuzz : public ::testing::Test {
protected:
    void SetUp() override { setLogCallback([](LogLevel, std::string_view) {}); }
    void TearDown() override { setLogCallback(nullptr); }

    void check(const std::filesystem::path& path, size_t iteration) {
        LoadOptions options;
        options.maxTriangles = 1'000'000;   // mutated counts must not make the test slow
        options.maxVertices = 1'000'000;
        options.maxTextureDimension = 1024;
        auto result = loadGltf(path.string(), options);
        if (result.ok()) {
            ++loaded;
            return;
        }
        ++failed;
        ASSERT_EQ(result.message().rfind(path.string(), 0), 0u) << "iteration " << iteration << ": " << result.message();
    }
    size_t loaded = 0, failed = 0;
};

TEST_F(GltfFuzz, BinaryMutationsNeverCrashAndErrorsNameTheFile) {
    auto dir = fuzzDir();
    auto seedPath = dir / "seed.glb";
    ASSERT_TRUE(writeGltf(seedScene(), seedPath.string()).ok());
    const std::vector<uint8_t> seed = readAll(seedPath);
    std::mt19937 rng(1234);
    auto target = dir / "mutant.glb";
    for (size_t it = 0; it < 3000; ++it) {
        std::vector<uint8_t> bytes = seed;
        switch (rng() % 4) {
            case 0:   // flip 1-8 random bytes
                for (uint32_t k = 0, n = 1 + rng() % 8; k < n; ++k) bytes[rng() % bytes.size()] ^= uint8_t(1 + rng() % 255);
                break;
            case 1:   // truncate
                bytes.resize(rng() % bytes.size());
                break;
            case 2: {   // overwrite a 4-byte word in the first 64 bytes (header, chunk lengths) or JSON
                size_t at = (rng() % 2) ? rng() % 64 : rng() % (bytes.size() - 4);
                uint32_t v = rng() % 3 == 0 ? 0xFFFFFFFFu : rng();
                std::memcpy(&bytes[at], &v, 4);
                break;
            }
            default:   // flip bytes inside the JSON chunk's digits so numbers change
                for (size_t k = 20; k < bytes.size() && k < 4000; ++k)
                    if (bytes[k] >= '0' && bytes[k] <= '9' && rng() % 40 == 0) bytes[k] = uint8_t('0' + rng() % 10);
                break;
        }
        writeAll(target, bytes);
        check(target, it);
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(failed, 0u);   // the mutations did reach the error paths
}

// Walks the JSON tree and returns pointers to every object member / array element.
void collect(json& node, std::vector<std::pair<json*, std::string>>& members, std::vector<json*>& values) {
    values.push_back(&node);
    if (node.is_object()) {
        for (auto it = node.begin(); it != node.end(); ++it) {
            members.push_back({&node, it.key()});
            collect(it.value(), members, values);
        }
    } else if (node.is_array()) {
        for (json& e : node) collect(e, members, values);
    }
}

TEST_F(GltfFuzz, JsonMutationsNeverCrashAndErrorsNameTheFile) {
    auto dir = fuzzDir();
    auto seedPath = dir / "seed.gltf";
    ASSERT_TRUE(writeGltf(seedScene(), seedPath.string()).ok());
    const std::vector<uint8_t> seedBytes = readAll(seedPath);
    const json seed = json::parse(std::string(seedBytes.begin(), seedBytes.end()));
    std::mt19937 rng(5678);
    const json randomValues[] = {-1, 0, 1, 3, 255, 65535, 4294967295.0, -2147483648.0, 1e300, -1e300, 1e-300,
                                 1.5, "x", nullptr, json::array(), json::object(), true, 9007199254740993.0};
    auto target = dir / "mutant.gltf";
    for (size_t it = 0; it < 3000; ++it) {
        json doc = seed;
        for (uint32_t k = 0, n = 1 + rng() % 3; k < n; ++k) {
            std::vector<std::pair<json*, std::string>> members;
            std::vector<json*> values;
            collect(doc, members, values);
            if (rng() % 2 == 0 && !members.empty()) {
                auto& [object, key] = members[rng() % members.size()];
                object->erase(key);   // delete a field
            } else {
                json* v = values[rng() % values.size()];
                if (v->is_string() && v->get<std::string>().rfind("data:", 0) == 0) continue;   // keep buffers intact
                *v = randomValues[rng() % std::size(randomValues)];
            }
        }
        std::string text = doc.dump();
        writeAll(target, std::vector<uint8_t>(text.begin(), text.end()));
        check(target, it);
        if (HasFatalFailure()) return;
    }
    EXPECT_GT(failed, 0u);
    EXPECT_GT(loaded, 0u);   // some mutations are harmless: the loader is not just refusing everything
}

}  // namespace
}  // namespace caustics::scene
