// The libFuzzer corpus (tests/fuzz/gltf/corpus: seeds plus what `scripts/fuzz-check.sh` found worth
// keeping) and the sample's test files replayed through the same loader entry point as the fuzzer, so an
// input that once crashed or misreported stays fixed in every normal build.
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_fuzz_target.h"

namespace caustics::scene::fuzz {
namespace {

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) files.push_back(entry.path());
    return files;
}

void replay(const std::filesystem::path& dir, size_t minimumFiles) {
    std::vector<std::filesystem::path> files = filesIn(dir);
    ASSERT_GE(files.size(), minimumFiles) << dir;   // a missing corpus must not pass as an empty one
    for (const auto& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        EXPECT_EQ(loadOne(bytes.data(), bytes.size()), "") << file;
    }
}

TEST(GltfFuzzCorpus, EveryCorpusInputLoadsOrFailsNamingTheInput) { replay(CAUSTICS_FUZZ_CORPUS_DIR, 50); }

TEST(GltfFuzzCorpus, EverySampleTestFileLoadsOrFailsNamingTheInput) { replay(CAUSTICS_SAMPLE_DATA_DIR, 20); }

}  // namespace
}  // namespace caustics::scene::fuzz
