#!/usr/bin/env bash
# Configures and builds the project into build/ (Release with debug info). Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
launcher=""
if command -v ccache >/dev/null; then
  # Paths relative to the checkout, so clones in other folders share the cache.
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICS_WITH_D3D12=ON $launcher >/dev/null
cmake --build build -j "$jobs"
