#!/usr/bin/env bash
# CI check that the Windows build compiles: cross-compiles caustics::rhi with the D3D12 backend (and
# the Vulkan one), caustics::passes, the engine and the sample's non-window code (samples/sponza's
# frame loop, scene choice and CLI; samples/bench) with MinGW-w64, warnings as errors.
# MinGW is the CI check; users build with MSVC (preset windows-msvc). See docs/d3d12.md.
#
#   scripts/windows-cross-check.sh [build-dir]     (default build-mingw; the host tool comes from build/)
#
# Exit status 0 only when every Windows object compiled and every library archived.
set -euo pipefail
cd "$(dirname "$0")/.."
crossDir="${1:-build-mingw}"
hostDir="${CAUSTICS_HOST_BUILD_DIR:-build}"
jobs="${CAUSTICS_JOBS:-2}"

if ! command -v x86_64-w64-mingw32-g++-posix >/dev/null; then
  echo "windows-cross-check: x86_64-w64-mingw32-g++-posix not found (scripts/install-deps.sh installs" \
       "g++-mingw-w64-x86-64-posix)" >&2
  exit 2
fi

# The HLSL embedder and the binding generator run during the build, so they are built for the host
# first (a no-op when current).
if [ ! -f "$hostDir/CMakeCache.txt" ]; then
  cmake -S . -B "$hostDir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAUSTICS_WITH_D3D12=ON >/dev/null
fi
cmake --build "$hostDir" --target caustics_embed_hlsl caustics_generate_bindings -j "$jobs" >/dev/null
hostTool="$(cd "$hostDir" && pwd)/shaders/d3d12/caustics_embed_hlsl"
hostBindings="$(cd "$hostDir" && pwd)/shaders/bindings/caustics_generate_bindings"

cmake --preset windows-mingw-cross -B "$crossDir" -DCAUSTICS_HOST_EMBED_HLSL="$hostTool" \
  -DCAUSTICS_HOST_GENERATE_BINDINGS="$hostBindings" >/dev/null
cmake --build "$crossDir" -j "$jobs" --target caustics_rhi caustics_passes caustics_windows_sample_check
echo "windows-cross-check: caustics_rhi (Vulkan + D3D12), caustics_passes, engine and sample code compiled for Windows x64"
