#!/usr/bin/env bash
# How far the README's picture (run.sh's view and 32 filtered frames) is from a converged render of the
# same view, as a viewer sees it (docs/caustics.md "Second-type guides", still views): the reference is the
# mean of N unfiltered frames of R rays per texel each (default 64 x 16: the photons of 1,024 frames), both
# tone-mapped PNGs; printed are the mean absolute difference of the sRGB channels' mean and the pixels
# darker or brighter than the reference by more than 0.08 (20 sRGB steps: a dot one sees at 100 %).
#   scripts/readme-view-error.sh [reference-frames (default 64)] [reference-rays-per-texel (default 16)] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
reference_frames="${1:-64}"
reference_rays="${2:-16}"
build="${3:-build}"
source scripts/readme-view.sh
view=("${readme_view[@]}")
"$build/bin/caustics-sponza" "${view[@]}" --frames 32 --out "$out/filtered.png" > /dev/null 2>&1
"$build/bin/caustics-sponza" "${view[@]}" --rays-per-texel "$reference_rays" --accumulate "$reference_frames" \
    --out "$out/reference.png" > /dev/null 2>&1
oiiotool "$out/reference.png" --ch R,G,B "$out/filtered.png" --ch R,G,B --sub --chsum:weight=0.3333,0.3333,0.3334 \
    -o "$out/difference.exr"
oiiotool --info --dumpdata "$out/difference.exr" | awk '
    /Pixel \(/ { d = $NF + 0; sum += (d < 0 ? -d : d); n++; if (d > 0.08) darker++; if (d < -0.08) brighter++ }
    END { printf "README view, 32 filtered frames against the reference: mean |sRGB difference| %.5f, " \
                 "%d pixels darker and %d brighter by more than 0.08, of %d\n", sum / n, darker, brighter, n }'
