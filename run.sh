#!/usr/bin/env bash
# The main job: installs what is missing, builds, and renders the built-in caustics scene to
# out/caustics.png (software Vulkan on the CPU when no GPU is present). Extra arguments go to the sample,
# e.g. ./run.sh --width 1280 --height 720   or   ./run.sh --sponza /path/to/Sponza.gltf
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/build.sh
mkdir -p out
# The picture of the paper's Figure 1: seen from above the lights' side, the glass sphere's focal
# spot, the water glass's caustic in its shadow and the ring's cardioid; exposure low enough that the
# caustics do not saturate; 32 frames of a still camera through the caustic filter (its history cap:
# the temporal mean of 32 frames, then the a-trous passes; docs/caustics.md "Filter") for a clean still.
framing=(--camera -0.10,0.36,0.32,0.04,0,-0.05,42 --exposure 0.3)
still=(--frames 32)
for arg in "$@"; do
    case "$arg" in
        --scene|--sponza|--camera) framing=() ;;       # another scene or view: its own framing
        --frames|--window|--accumulate) still=() ;;     # the caller chose how many frames
    esac
done
./build/bin/caustics-sponza --scene builtin --width 512 --height 384 "${framing[@]}" "${still[@]}" \
    --out out/caustics.png "$@"
echo "run.sh: wrote $(pwd)/out/caustics.png"
