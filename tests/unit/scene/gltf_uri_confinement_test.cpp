// External URIs stay inside the asset root (docs/viewer.md, "Untrusted glTF"). "Never opened" is
// observed, not assumed: the file outside the folder is a FIFO, and a watcher thread keeps trying to open
// its write end without blocking, which succeeds only while some reader has the FIFO open. A loader that
// opened it would be seen (and then released by the watcher's open, so the test cannot hang).
#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "caustics/rhi/log.h"
#include "caustics/scene/gltf.h"

namespace caustics::scene {
namespace {

using namespace test;
namespace fs = std::filesystem;

class GltfUris : public ::testing::Test {
protected:
    void SetUp() override {
        root = testDir();
        model = root / "model";
        fs::create_directories(model);
        setLogCallback([](LogLevel, std::string_view) {});
    }
    void TearDown() override { setLogCallback(nullptr); }

    // Loads `a` written into model/ and expects a failure whose message holds every one of `words`.
    void expectRefused(const TriangleAsset& a, std::initializer_list<std::string> words, const LoadOptions& options = {}) {
        std::string path = (model / "tri.gltf").string();
        writeText(path, a.gltf.dump(2));
        auto scene = loadGltf(path, options);
        ASSERT_FALSE(scene.ok()) << "loaded " << path;
        for (const std::string& w : words) EXPECT_NE(scene.message().find(w), std::string::npos) << scene.message();
    }

    fs::path root, model;
};

// Runs `load` while watching `fifo`; true if any reader had it open meanwhile.
template <typename Load>
bool openedDuring(const fs::path& fifo, Load&& load) {
    std::atomic<bool> stop{false}, opened{false};
    std::thread watcher([&] {
        while (!stop) {
            int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);   // ENXIO while no reader has it open
            if (fd >= 0) {
                opened = true;
                ::close(fd);   // the reader now sees end-of-file and the load goes on
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
    load();
    stop = true;
    watcher.join();
    return opened;
}

fs::path makeFifo(const fs::path& path) {
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
    return path;
}

TEST_F(GltfUris, DotDotEscapeIsRefusedAndTheFileOutsideIsNeverOpened) {
    fs::path fifo = makeFifo(root / "outside.bin");
    TriangleAsset a = makeTriangleAsset();
    a.gltf["buffers"][0]["uri"] = "../outside.bin";
    bool opened = openedDuring(fifo, [&] {
        expectRefused(a, {"buffers[0].uri '../outside.bin' resolves to '" + fs::canonical(root).string() + "/outside.bin'",
                          "outside the asset root '" + fs::canonical(model).string() + "'", "--asset-root DIR"});
    });
    EXPECT_FALSE(opened) << "the loader opened the file outside the asset root";
}

TEST_F(GltfUris, PercentEncodedDotDotIsRefused) {
    fs::path fifo = makeFifo(root / "outside.bin");
    TriangleAsset a = makeTriangleAsset();
    a.gltf["buffers"][0]["uri"] = "%2e%2e/outside.bin";   // tinygltf decodes it to ../outside.bin
    EXPECT_FALSE(openedDuring(fifo, [&] { expectRefused(a, {"buffers[0].uri '%2e%2e/outside.bin' resolves to", "outside the asset root"}); }));
}

TEST_F(GltfUris, AbsolutePathOutsideTheRootIsRefusedAndNeverOpened) {
    fs::path fifo = makeFifo(root / "absolute.bin");
    TriangleAsset a = makeTriangleAsset();
    a.gltf["buffers"][0]["uri"] = fifo.string();
    EXPECT_FALSE(openedDuring(fifo, [&] { expectRefused(a, {"resolves to '" + fs::canonical(fifo).string() + "', outside the asset root"}); }));
}

TEST_F(GltfUris, AbsolutePathInsideTheRootIsRefusedWithItsRelativeForm) {
    TriangleAsset a = makeTriangleAsset();
    writeBytes(model / "tri.bin", a.bin);
    a.gltf["buffers"][0]["uri"] = (fs::canonical(model) / "tri.bin").string();
    expectRefused(a, {"is an absolute path; glTF 2.0 (3.3) URIs are relative to the glTF file: write it as 'tri.bin'"});
}

TEST_F(GltfUris, EtcPasswdAndDevZeroAreRefusedNotFileNotFound) {
    for (const char* uri : {"/etc/passwd", "/dev/zero", "../../../../../../../../etc/passwd"}) {
        TriangleAsset a = makeTriangleAsset();
        a.gltf["buffers"][0]["uri"] = uri;
        expectRefused(a, {"buffers[0].uri '" + std::string(uri) + "'", "outside the asset root"});
    }
}

TEST_F(GltfUris, FifoInsideTheRootIsRefusedAsNotARegularFileAndNeverOpened) {
    fs::path fifo = makeFifo(model / "pipe.bin");
    TriangleAsset a = makeTriangleAsset();
    a.gltf["buffers"][0]["uri"] = "pipe.bin";
    EXPECT_FALSE(openedDuring(fifo, [&] { expectRefused(a, {"buffers[0].uri 'pipe.bin' resolves to", "which is a FIFO (named pipe); only regular files are read"}); }));
}

TEST_F(GltfUris, LinkInsideTheRootThatPointsOutIsJudgedByItsTarget) {
    fs::path fifo = makeFifo(root / "target.bin");
    fs::create_symlink(fifo, model / "link.bin");
    TriangleAsset a = makeTriangleAsset();
    a.gltf["buffers"][0]["uri"] = "link.bin";
    EXPECT_FALSE(openedDuring(fifo, [&] { expectRefused(a, {"buffers[0].uri 'link.bin' resolves to '" + fs::canonical(fifo).string() + "', outside"}); }));
    fs::create_symlink("/dev/zero", model / "zero.bin");
    a.gltf["buffers"][0]["uri"] = "zero.bin";
    expectRefused(a, {"resolves to '/dev/zero', outside the asset root"});
}

TEST_F(GltfUris, ImageUriOutsideTheRootIsRefusedAndNeverOpened) {
    fs::path fifo = makeFifo(root / "outside.png");
    TriangleAsset a = makeTriangleAsset();
    writeBytes(model / "tri.bin", a.bin);
    a.gltf["images"] = json::array({{{"uri", "../outside.png"}}});
    a.gltf["textures"] = json::array({{{"source", 0}}});
    EXPECT_FALSE(openedDuring(fifo, [&] { expectRefused(a, {"images[0].uri '../outside.png' resolves to", "outside the asset root"}); }));
}

TEST_F(GltfUris, AssetRootWidensTheFolderForASiblingBufferFolder) {
    TriangleAsset a = makeTriangleAsset("../buffers/tri.bin");
    fs::create_directories(root / "buffers");
    writeBytes(root / "buffers" / "tri.bin", a.bin);
    expectRefused(a, {"buffers[0].uri '../buffers/tri.bin'", "outside the asset root"});
    LoadOptions wide;
    wide.assetRoot = root.string();
    auto scene = loadGltf((model / "tri.gltf").string(), wide);
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->meshes.size(), 1u);
    wide.assetRoot = (root / "missing").string();
    expectRefused(a, {"LoadOptions::assetRoot '" + (root / "missing").string() + "' is not a directory"}, wide);
}

TEST_F(GltfUris, MissingFileInsideTheRootSaysWhereItLooked) {
    TriangleAsset a = makeTriangleAsset("absent.bin");
    expectRefused(a, {"buffers[0].uri 'absent.bin': file not found (looked for '" + fs::canonical(model).string() + "/absent.bin')"});
}

TEST_F(GltfUris, ModelPathThatIsAFifoIsRefusedWithoutOpeningIt) {
    fs::path fifo = makeFifo(root / "model.gltf");
    bool opened = openedDuring(fifo, [&] {
        auto scene = loadGltf(fifo.string());
        ASSERT_FALSE(scene.ok());
        EXPECT_NE(scene.message().find("is not a regular file (a device, FIFO or socket)"), std::string::npos) << scene.message();
    });
    EXPECT_FALSE(opened);
}

TEST_F(GltfUris, MemoryLoadReadsNoFileWithoutAnAssetRootAndResolvesInsideOne) {
    TriangleAsset a = makeTriangleAsset();
    writeBytes(model / "tri.bin", a.bin);
    std::string text = a.gltf.dump();
    std::vector<unsigned char> bytes(text.begin(), text.end());
    auto none = loadGltfFromMemory(bytes, "memory.gltf");
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.message().rfind("memory.gltf: ", 0), 0u) << none.message();
    EXPECT_NE(none.message().find("buffers[0].uri 'tri.bin' names an external file, but the glTF was loaded from memory without "
                                  "LoadOptions::assetRoot"),
              std::string::npos)
        << none.message();
    LoadOptions options;
    options.assetRoot = model.string();
    auto scene = loadGltfFromMemory(bytes, "memory.gltf", options);
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->name, "memory");
}

}  // namespace
}  // namespace caustics::scene
