#!/usr/bin/env bash
# Whether the filter's history accumulates every pixel of a still view (docs/caustics.md "Second-type
# guides", still views): renders the README's view as the caustics AOV after N frames through the temporal
# pass alone (no a-trous iteration, the history pool sized for the whole view up front) and the mean of the
# same N frames unfiltered, and counts the pixels whose filtered luminance is zero where the unfiltered mean
# exceeds 0.01 (a history that restarted every frame), and the mean absolute difference.
#   scripts/still-view-history.sh [frames (default 32)] [filter-second-type apart|merged (default apart)] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
frames="${1:-32}"
types="${2:-apart}"
build="${3:-build}"
source scripts/readme-view.sh
view=("${readme_view[@]}" --aov caustics --seed 2)
"$build/bin/caustics-sponza" "${view[@]}" --frames "$frames" --filter-second-type "$types" --set atrousIterations=0 \
    --set filterPoolTiles=4096 --out "$out/temporal.exr" > /dev/null 2>&1
"$build/bin/caustics-sponza" "${view[@]}" --accumulate "$frames" --out "$out/mean.exr" > /dev/null 2>&1
for name in temporal mean; do
    oiiotool "$out/$name.exr" --ch R,G,B --chsum:weight=0.2126,0.7152,0.0722 -o "$out/$name.luminance.exr"
done
paste <(oiiotool --info --dumpdata "$out/temporal.luminance.exr" | awk '/Pixel \(/ { print $NF }') \
      <(oiiotool --info --dumpdata "$out/mean.luminance.exr" | awk '/Pixel \(/ { print $NF }') | awk -v f="$frames" -v t="$types" '
    { d = $1 - $2; sum += (d < 0 ? -d : d); n++; if ($1 == 0 && $2 > 0.01) stuck++ }
    END { printf "%s frames, second type %s, temporal pass only: %d pixels zero where the unfiltered mean exceeds 0.01, " \
                 "mean |difference| %.5f, of %d\n", f, t, stuck, sum / n, n }'
