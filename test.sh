#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test suite (unit, gpu on lavapipe with Vulkan
# validation, image, physics, fuzz). Extra arguments go to ctest, e.g. ./test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/build.sh
cd build
ctest --output-on-failure --timeout 600 "$@"
