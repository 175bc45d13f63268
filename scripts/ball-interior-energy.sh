#!/usr/bin/env bash
# The filter's energy on the second type inside the README's glass ball (docs/caustics.md "Moving
# caustics", the second type's rises): renders the README's view (run.sh's framing, 512x384) as the
# caustics AOV (linear EXR) through the filter, apart (the default) and merged, for N frames, and the mean
# of N unfiltered frames with the same random keys, for each seed given, and prints the red channel's mean
# over the crop inside the ball (60x50 at 280,205: the floor seen through it, second type only) and over
# the whole image. A filter that keeps the energy matches the unfiltered mean up to its own noise.
#   scripts/ball-interior-energy.sh [frames (default 32)] [seeds (default "1 2 3")] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
frames="${1:-32}"
seeds="${2:-1 2 3}"
build="${3:-build}"
source scripts/readme-view.sh
view=("${readme_view[@]}" --aov caustics)
mean() {
    oiiotool "$1" "${@:2}" --ch R --printstats 2>&1 | awk '/Stats Avg/ { print $3; exit }'
}
for seed in $seeds; do
    "$build/bin/caustics-sponza" "${view[@]}" --seed "$seed" --frames "$frames" --out "$out/apart.exr" > /dev/null 2>&1
    "$build/bin/caustics-sponza" "${view[@]}" --seed "$seed" --frames "$frames" --filter-second-type merged \
        --out "$out/merged.exr" > /dev/null 2>&1
    "$build/bin/caustics-sponza" "${view[@]}" --seed "$seed" --accumulate "$frames" --out "$out/unfiltered.exr" > /dev/null 2>&1
    for name in apart merged unfiltered; do
        echo "seed $seed, $frames frames, $name: ball interior $(mean "$out/$name.exr" --cut 60x50+280+205)," \
             "whole image $(mean "$out/$name.exr")"
    done
done
