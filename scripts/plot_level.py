#!/usr/bin/python3
"""Plots the CSV files of `caustics-bench level --out DIR` as DIR/level.png (or --out PNG).

    python3 scripts/plot_level.py DIR [--out PNG]

level_sweep.csv: photons traced and caustic GPU time against object count, level extent and photon
budget; level_target.csv: each frame's caustic time and budget of the moving camera under the time
target (1080p and 4K). Needs python3-matplotlib (scripts/install-deps.sh).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    if not os.path.exists(path):
        sys.exit(f"plot_level: {path} does not exist (run caustics-bench level --out DIR first)")
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--out")
    args = parser.parse_args()
    sweep = read_rows(os.path.join(args.dir, "level_sweep.csv"))
    target = read_rows(os.path.join(args.dir, "level_target.csv"))
    fig, axes = plt.subplots(1, 4, figsize=(20, 4.2))
    for ax, name, label in zip(axes[:3], ["objects", "extent", "budget"],
                               ["specular objects (200 m court)", "court side (m), 36 objects", "photon budget"]):
        rows = [r for r in sweep if r["sweep"] == name]
        x = [float(r["value"]) for r in rows]
        ax.plot(x, [float(r["caustics_ms"]) for r in rows], "o-", label="caustic passes (ms)")
        ax.plot(x, [float(r["forward_ms"]) for r in rows], "s--", label="forward (ms)")
        ax.set_xscale("log", base=2)
        ax.set_xlabel(label)
        ax.set_ylabel("GPU ms")
        twin = ax.twinx()
        twin.plot(x, [float(r["photons"]) / 1e3 for r in rows], "^:", color="gray", label="photons (k)")
        twin.set_ylabel("photons traced (thousands)")
        twin.set_ylim(bottom=0)
        ax.set_ylim(bottom=0)
        ax.legend(loc="upper left", fontsize=8)
    ax = axes[3]
    for size in sorted({(r["width"], r["height"]) for r in target}, key=lambda s: int(s[0])):
        rows = [r for r in target if (r["width"], r["height"]) == size]
        ax.plot([int(r["frame"]) for r in rows], [float(r["caustics_ms"]) for r in rows], label=f"{size[0]}x{size[1]}")
    if target:
        t = float(target[0]["target_ms"])
        ax.axhspan(0.85 * t, 1.15 * t, color="green", alpha=0.15, label="target +-15 %")
    ax.set_xlabel("frame (moving camera)")
    ax.set_ylabel("caustic passes (ms)")
    ax.set_ylim(0, 3)
    ax.legend(fontsize=8)
    fig.suptitle("builtin:level (generated stand-in): photons follow the caustics in view")
    fig.tight_layout()
    out = args.out or os.path.join(args.dir, "level.png")
    fig.savefig(out, dpi=90)
    print(f"plot_level: wrote {out}")


if __name__ == "__main__":
    main()
