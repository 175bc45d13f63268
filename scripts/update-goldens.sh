#!/usr/bin/env bash
# Regenerates every golden image of tests/image from the current build: the direct-lighting golden
# and the caustics goldens (seed 1), then measures the caustics' seed-to-seed noise (seeds 2, 3, 4
# against the new goldens) into tests/image/golden/caustics_noise.txt, from which the caustics golden
# test derives its bounds. Run it only after a deliberate change of the images; look at them (and at
# the printed noise) before committing.
#   scripts/update-goldens.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
cmake --build "$build" --target direct_lighting_image_tests caustics_golden_image_tests
UPDATE_GOLDEN=1 "$build/bin/direct_lighting_image_tests"
UPDATE_GOLDEN=1 "$build/bin/caustics_golden_image_tests"
measurements=$(mktemp)
trap 'rm -f "$measurements"' EXIT
for seed in 2 3 4; do
    # These comparisons fail by design (another seed); only their printed metrics are kept.
    CAUSTICS_GOLDEN_SEED=$seed "$build/bin/caustics_golden_image_tests" | grep -E '^[a-z_]+ seed [0-9]+: ' >> "$measurements" || true
done
python3 - "$measurements" tests/image/golden/caustics_noise.txt <<'PY'
import collections, re, sys
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    m = re.match(r"(\w+) seed \d+: block relative L1 ([\d.eE+-]+), energy ratio ([\d.eE+-]+)", line)
    if m:
        runs[m.group(1)].append((float(m.group(2)), float(m.group(3))))
if not runs:
    sys.exit("update-goldens: no seed-to-seed measurements were printed")
with open(sys.argv[2], "w") as out:
    for name, values in runs.items():
        l1 = sum(v[0] for v in values) / len(values)
        spread = max(abs(v[1] - 1.0) for v in values)
        out.write(f"{name} {l1:.5f} {spread:.5f}\n")
        print(f"{name}: seed-to-seed block L1 {l1:.4f}, energy spread {spread:.4f} ({len(values)} seeds)")
PY
echo "update-goldens: wrote tests/image/golden/*.exr and caustics_noise.txt; look at them before committing"
