#!/usr/bin/python3
"""Plots the CSV files of `caustics-bench sweep --out DIR` as PNG files in the same folder (or --out).

    python3 scripts/plot_bench.py DIR [--out PNG_DIR]

timings.csv -> lights.png (paper Figure 9), rays.png (Figure 11), depth.png (Figure 13), map.png,
image.png: per-pass GPU medians against the swept setting (lights: the visible, away and culled
series), with the forward pass's ray segments per
second on a second axis, next to the incoherent ray ceiling of the same scene measured in the same run; quality.csv -> quality.png: relative L1 of the caustic image against the
converged reference next to the caustic passes' time, filter off and on; memory.csv -> memory.png:
the biggest transient and persistent resources at each image size (stacked). Needs python3-matplotlib (scripts/install-deps.sh).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PASSES = ["maps", "emitters", "forward", "backward", "spheres", "gather", "filter"]


def read_csv(path):
    if not os.path.exists(path):
        sys.exit(f"plot_bench: {path} does not exist (run caustics-bench sweep --out DIR first)")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        sys.exit(f"plot_bench: column '{key}' is missing or not a number in row {row}")


def x_of(sweep, row):
    if sweep == "image":
        w, h = row["value"].split("x")
        return int(w) * int(h) / 1e6
    return number(row, "value")


X_LABEL = {
    "lights": "extra ring lights (visible/away: caustic lights; culled: cone holds no specular object)",
    "rays": "rays per texel",
    "depth": "max specular depth",
    "map": "caustic map side (texels)",
    "image": "image size (megapixels)",
}


def plot_sweep(rows, sweep, out_dir, scene):
    rows = [r for r in rows if r["sweep"] == sweep and r.get("filter", "off") == "off"]
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(8, 5))
    views = sorted({r["view"] for r in rows})
    styles = {"visible": "-", "away": "--", "culled": "-."}
    for view in views:
        part = sorted((r for r in rows if r["view"] == view), key=lambda r: x_of(sweep, r))
        xs = [x_of(sweep, r) for r in part]
        suffix = f" ({view})" if len(views) > 1 else ""
        ax.plot(xs, [number(r, "frame_ms") for r in part], "k" + styles.get(view, "-"), marker="o",
                label="frame" + suffix)
        ax.plot(xs, [number(r, "caustics_ms") for r in part], "r" + styles.get(view, "-"), marker="s",
                label="all caustic passes" + suffix)
        if view == "visible" or len(views) == 1:
            for p in PASSES:
                ys = [number(r, p + "_ms") for r in part]
                if max(ys) > 0:
                    ax.plot(xs, ys, styles.get(view, "-"), marker=".", label=p + suffix, alpha=0.8)
    ax.set_xlabel(X_LABEL[sweep])
    ax.set_ylabel("GPU ms (median)")
    if sweep in ("rays", "map"):
        ax.set_xscale("log", base=2)
    ax.grid(True, alpha=0.3)
    first = "visible" if "visible" in views else views[0]
    visible = sorted((r for r in rows if r["view"] == first), key=lambda r: x_of(sweep, r))
    seg = [number(r, "segments") / (number(r, "forward_ms") * 1e3) if number(r, "forward_ms") > 0 else 0
           for r in visible]
    ax2 = ax.twinx()
    ax2.plot([x_of(sweep, r) for r in visible], seg, "b:", marker="^", label="forward M segments/s")
    ceiling = [number(r, "incoherent_ceiling_mrays_per_s") for r in visible if "incoherent_ceiling_mrays_per_s" in r]
    if ceiling and max(ceiling) > 0:
        # Measured in the same run on the same scene's TLAS (caustics-bench sweep, ceiling.csv).
        xs = [x_of(sweep, r) for r in visible]
        ax2.plot(xs, ceiling, "b-", alpha=0.4, label="incoherent ray ceiling, same scene (M rays/s)")
        ax2.plot(xs, [0.6 * c for c in ceiling], "b--", alpha=0.4, label="60 % of the ceiling (issue 11 target)")
    ax2.set_ylabel("forward pass, M ray segments / s", color="b")
    lines, labels = ax.get_legend_handles_labels()
    l2, lb2 = ax2.get_legend_handles_labels()
    ax.legend(lines + l2, labels + lb2, fontsize=7, loc="upper left")
    ax.set_title(f"{scene}: {sweep} sweep")
    path = os.path.join(out_dir, f"{sweep}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_quality(rows, out_dir, scene):
    rows = [r for r in rows if r["sweep"] == "rays"]
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(7, 5))
    for filt, style in (("off", "o-"), ("on", "s--")):
        part = sorted((r for r in rows if r["filter"] == filt), key=lambda r: number(r, "rays_per_texel"))
        if not part:
            continue
        xs = [number(r, "caustics_ms") for r in part]
        ys = [number(r, "relative_l1") for r in part]
        ax.plot(xs, ys, style, label=f"filter {filt}")
        for r, x, y in zip(part, xs, ys):
            ax.annotate(r["value"], (x, y), fontsize=7, textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("all caustic passes, GPU ms (median)")
    ax.set_ylabel("relative L1 vs converged reference")
    ax.set_yscale("log")
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title(f"{scene}: quality per time (labels: rays per texel)")
    path = os.path.join(out_dir, "quality.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_memory(rows, out_dir, top=10):
    """Stacked bars per image size of the `top` biggest resources (transient and persistent, from
    memory.csv), the rest summed as "other"; the "total" rows are the bars' height check."""
    rows = [r for r in rows if r["sweep"] == "image" and r["view"] == "visible" and r["resource"] != "total"]
    if not rows:
        return None
    sizes = sorted({r["value"] for r in rows}, key=lambda v: int(v.split("x")[0]))
    kind = {r["resource"]: r.get("kind", "transient") for r in rows}
    peak = {}
    for r in rows:
        peak[r["resource"]] = max(peak.get(r["resource"], 0.0), number(r, "bytes"))
    biggest = sorted(peak, key=peak.get, reverse=True)[:top]
    fig, ax = plt.subplots(figsize=(9, 5.5))
    bottom = [0.0] * len(sizes)

    def mib_of(size, keep):
        return sum(number(r, "bytes") for r in rows if r["value"] == size and keep(r["resource"])) / 2**20

    for res in biggest + ["other"]:
        keep = (lambda name, res=res: name == res) if res != "other" else (lambda name: name not in biggest)
        mib = [mib_of(size, keep) for size in sizes]
        label = f"{res} ({kind[res]})" if res != "other" else "everything else"
        ax.bar(sizes, mib, bottom=bottom, label=label, hatch="//" if kind.get(res) == "persistent" else None)
        bottom = [b + m for b, m in zip(bottom, mib)]
    for x, total in zip(sizes, bottom):
        ax.annotate(f"{total:.0f} MiB", (x, total), ha="center", va="bottom", fontsize=8)
    ax.set_ylabel("MiB (transients before aliasing; hatched: persistent)")
    ax.set_xlabel("image size")
    ax.legend(fontsize=7)
    ax.set_title("caustics module GPU memory per resource (CausticsModule::memoryReport + graph transients)")
    path = os.path.join(out_dir, "memory.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv_dir")
    parser.add_argument("--out", help="folder for the PNG files (default: csv_dir)")
    args = parser.parse_args()
    out_dir = args.out or args.csv_dir
    os.makedirs(out_dir, exist_ok=True)
    timings = read_csv(os.path.join(args.csv_dir, "timings.csv"))
    scene = timings[0]["scene"] if timings else "?"
    made = [plot_sweep(timings, s, out_dir, scene) for s in ("lights", "rays", "depth", "map", "image")]
    made.append(plot_quality(read_csv(os.path.join(args.csv_dir, "quality.csv")), out_dir, scene))
    made.append(plot_memory(read_csv(os.path.join(args.csv_dir, "memory.csv")), out_dir))
    for path in made:
        if path:
            print(path)


if __name__ == "__main__":
    main()
