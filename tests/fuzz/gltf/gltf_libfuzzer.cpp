// Coverage-guided fuzzing of the glTF loader with clang's libFuzzer under ASan + UBSan (built by
// scripts/fuzz-check.sh, docs/viewer.md "Fuzzing"). A crash, a sanitizer finding, a hang or an error that
// does not name the input stops the run and leaves the input as crash-*/timeout-* for the corpus.
#include <cstdio>
#include <cstdlib>

#include "gltf_fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string problem = caustics::scene::fuzz::loadOne(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "gltf_libfuzzer: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
