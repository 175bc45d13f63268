#!/usr/bin/env bash
# CI step: AddressSanitizer + UndefinedBehaviorSanitizer over the code that reads untrusted input.
# Builds ONLY the glTF fuzz tests (mutations and the libFuzzer corpus replay), the sample and its image
# checker into build-sanitize/
# (-DCAUSTICS_SANITIZE=ON, Vulkan-only: the D3D12 backend cannot run here) and runs the CTest labels
# `fuzz` (mutated glTF files) and `sample_messages` (the sample on broken glTF files and absurd
# options, and a few small renders on lavapipe). Any sanitizer finding aborts the test that met it.
# Measured on the 2-core CI machine: see docs/viewer.md ("Sanitizers").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICS_SANITIZE=ON \
  -DCAUSTICS_WITH_D3D12=OFF >/dev/null
cmake --build build-sanitize -j "$jobs" --target gltf_fuzz_tests gltf_corpus_replay_tests caustics-sponza image-check
# Mesa's lavapipe and the Vulkan loader are not instrumented and keep allocations until exit: leak
# reports from them would be noise, so leak checking is off; ASan still catches every bad access.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
ctest --test-dir build-sanitize -L 'fuzz|sample_messages' --output-on-failure --timeout 600 -j "$jobs" "$@"
