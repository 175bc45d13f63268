#!/usr/bin/env bash
# The main job: installs what is missing, builds, and renders the built-in caustics scene to
# out/caustics.png (software Vulkan on the CPU when no GPU is present). Extra arguments go to the sample,
# e.g. ./run.sh --width 1280 --height 720   or   ./run.sh --sponza /path/to/Sponza.gltf
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/build.sh
mkdir -p out
./build/bin/caustics-sponza --scene builtin --width 512 --height 384 --frames 4 --out out/caustics.png "$@"
echo "run.sh: wrote $(pwd)/out/caustics.png"
