#pragma once
// One fuzz input through the glTF loader, shared by the coverage-guided fuzzer (gltf_libfuzzer.cpp,
// clang's libFuzzer) and the ctest replay of its corpus (gltf_corpus_replay_test.cpp).
#include <cstddef>
#include <cstdint>
#include <string>

namespace caustics::scene::fuzz {

// Loads `data` from memory (no asset root: no file is read) with limits that keep one input fast.
// Returns "" when the load succeeded or failed properly (the error starts with the input's name), else
// what was wrong. Crashes, hangs and sanitizer findings are the fuzzer's to see.
std::string loadOne(const uint8_t* data, size_t size);

}  // namespace caustics::scene::fuzz
