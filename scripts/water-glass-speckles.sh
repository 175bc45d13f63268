#!/usr/bin/env bash
# Renders the README's view (run.sh's framing, 512x384, 32 filtered frames) with the second type filtered
# apart (the default) and merged, and a reference of N accumulated unfiltered frames, and prints for each
# the speckle measure docs/caustics.md quotes ("Second-type guides", receivers the filter cannot follow):
# over the crop around the water glass (140x170 at 0,160), the mean of max(0, image - its 3x3 median),
# sRGB red channel. Single bright pixels raise it; a smooth image keeps it near the reference's.
#   scripts/water-glass-speckles.sh [reference-frames (default 192)] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
reference_frames="${1:-192}"
build="${2:-build}"
source scripts/readme-view.sh
view=("${readme_view[@]}")
speckle() {
    oiiotool "$1" --cut 140x170+0+160 --ch R,G,B --dup --median 3x3 --sub --clamp:min=0 --printstats 2>&1 |
        awk '/Stats Avg/ { print $3; exit }'
}
"$build/bin/caustics-sponza" "${view[@]}" --frames 32 --filter-second-type apart --out "$out/apart.png" > /dev/null
"$build/bin/caustics-sponza" "${view[@]}" --frames 32 --filter-second-type merged --out "$out/merged.png" > /dev/null
"$build/bin/caustics-sponza" "${view[@]}" --accumulate "$reference_frames" --out "$out/reference.png" > /dev/null
for name in apart merged reference; do
    echo "water-glass speckles, $name: $(speckle "$out/$name.png")"
done
