#!/usr/bin/env bash
# CI step: coverage-guided fuzzing of the glTF loader with clang's libFuzzer under AddressSanitizer +
# UndefinedBehaviorSanitizer (docs/viewer.md, "Fuzzing"). Builds only gltf_libfuzzer into build-fuzz/
# (clang, Vulkan-only configure) and runs it for CAUSTICS_FUZZ_SECONDS (default 120) from the committed
# corpus (tests/fuzz/gltf/corpus) and the sample's test files. A crash, a sanitizer finding, a leak, an
# input slower than 10 s or an error that does not name its input fails the step; the input is left in
# build-fuzz/artifacts/ (add it to the corpus with the fix: ctest replays the corpus in every build).
# New coverage found goes to build-fuzz/corpus/; `CAUSTICS_FUZZ_MERGE=1` merges it into the committed
# corpus (libFuzzer -merge=1 keeps only inputs that add coverage).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
seconds=${CAUSTICS_FUZZ_SECONDS:-120}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICS_SANITIZE=ON \
  -DCAUSTICS_LIBFUZZER=ON -DCAUSTICS_WITH_D3D12=OFF -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" >/dev/null
cmake --build build-fuzz -j "$jobs" --target gltf_libfuzzer
mkdir -p build-fuzz/corpus build-fuzz/artifacts
export ASAN_OPTIONS="abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
fuzzer=build-fuzz/bin/gltf_libfuzzer
seeds=(tests/fuzz/gltf/corpus tests/gpu/sample_runs/data)
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
  -dict=tests/fuzz/gltf/gltf.dict -artifact_prefix=build-fuzz/artifacts/ build-fuzz/corpus "${seeds[@]}"
if [ -n "${CAUSTICS_FUZZ_MERGE:-}" ]; then
  "$fuzzer" -merge=1 -max_len=65536 tests/fuzz/gltf/corpus build-fuzz/corpus
fi
