#!/usr/bin/env bash
# Configures and builds the project into build/ (Release with debug info). Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICS_WITH_D3D12=ON >/dev/null
cmake --build build -j "$jobs"
