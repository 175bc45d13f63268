#pragma once
// Writes small glTF test files by hand (JSON built with nlohmann json, binary buffers as bytes) so
// tests control every field, including the broken ones.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace caustics::scene::test {

using nlohmann::json;

// A fresh directory per test under the system temp dir.
inline std::filesystem::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::temp_directory_path() / "caustics_scene_tests" /
               (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}
inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

template <typename T>
void appendPod(std::vector<uint8_t>& bytes, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

// One triangle (0,0,0) (1,0,0) (0,1,0) with uint16 indices: bytes 0..36 positions, 36..42 indices.
struct TriangleAsset {
    std::vector<uint8_t> bin;
    json gltf;
};

inline TriangleAsset makeTriangleAsset(const std::string& binUri = "tri.bin") {
    TriangleAsset a;
    float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (float f : pos) appendPod(a.bin, f);
    for (uint16_t i : {uint16_t(0), uint16_t(1), uint16_t(2)}) appendPod(a.bin, i);
    while (a.bin.size() % 4) a.bin.push_back(0);
    a.gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", json::array({0})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
        {"accessors", json::array({
            {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
             {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
            {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
        })},
        {"bufferViews", json::array({
            {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
            {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}},
        })},
        {"buffers", json::array({{{"uri", binUri}, {"byteLength", a.bin.size()}}})},
    };
    return a;
}

// Writes `<dir>/<name>.gltf` and its buffer file; returns the .gltf path.
inline std::string writeAsset(const std::filesystem::path& dir, const TriangleAsset& a, const std::string& name = "tri") {
    writeBytes(dir / a.gltf["buffers"][0].value("uri", std::string("tri.bin")), a.bin);
    auto path = dir / (name + ".gltf");
    writeText(path, a.gltf.dump(2));
    return path.string();
}

// GLB container (glTF 2.0 section 4.4): header, JSON chunk (space padded), BIN chunk (zero padded).
inline std::vector<uint8_t> makeGlb(json gltf, std::vector<uint8_t> bin) {
    gltf["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = gltf.dump();
    while (text.size() % 4) text.push_back(' ');
    while (bin.size() % 4) bin.push_back(0);
    std::vector<uint8_t> out;
    appendPod(out, uint32_t(0x46546C67));   // "glTF"
    appendPod(out, uint32_t(2));
    appendPod(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    appendPod(out, uint32_t(text.size()));
    appendPod(out, uint32_t(0x4E4F534A));   // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    appendPod(out, uint32_t(bin.size()));
    appendPod(out, uint32_t(0x004E4942));   // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

}  // namespace caustics::scene::test
