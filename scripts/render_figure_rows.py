#!/usr/bin/python3
"""Renders the image rows of the paper's Figures 10 and 12 with the sample: the caustics alone
(--aov caustics, filter off, one frame) at each rays-per-texel setting (0.25 .. 25, depth 4) and at each
depth (1 .. 16, 1 ray per texel), cropped to the caustic, side by side with their labels.

    python3 scripts/render_figure_rows.py --sample build/samples/sponza/caustics-sponza --out DIR \
        [--scene builtin:atrium] [--width 1920 --height 1080] [--map-resolution 512] [--exposure E]

Writes DIR/figure10_rays_per_texel.png and DIR/figure12_depth.png (and each frame as DIR/frames/*.png).
The crop is the bounding box of the pixels above 2 % of the brightest one in the 25-rays-per-texel
frame, padded by a tenth, so every tile shows the same region. Needs python3-matplotlib.
"""
import argparse
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RAYS = ["0.25", "0.5", "0.75", "1", "2", "4", "8", "25"]
DEPTHS = ["1", "2", "3", "4", "8", "16"]


def render(args, frames_dir, name, rays, depth):
    path = os.path.join(frames_dir, f"{name}.png")
    cmd = [args.sample, "--scene", args.scene, "--width", str(args.width), "--height", str(args.height),
           "--map-resolution", str(args.map_resolution), "--rays-per-texel", rays, "--max-depth", depth,
           "--aov", "caustics", "--no-filter", "--exposure", str(args.exposure), "--out", path]
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"render_figure_rows: {' '.join(cmd)} failed:\n{result.stderr}")
    return mpimg.imread(path)[:, :, :3]


def crop_box(image):
    lum = image.mean(axis=2)
    ys, xs = np.nonzero(lum > 0.02 * max(lum.max(), 1e-12))
    if len(xs) == 0:
        return 0, image.shape[0], 0, image.shape[1]
    pad_y, pad_x = max(4, (ys.max() - ys.min()) // 10), max(4, (xs.max() - xs.min()) // 10)
    return (max(0, ys.min() - pad_y), min(image.shape[0], ys.max() + pad_y + 1),
            max(0, xs.min() - pad_x), min(image.shape[1], xs.max() + pad_x + 1))


def write_row(images, labels, box, title, path):
    y0, y1, x0, x1 = box
    fig, axes = plt.subplots(1, len(images), figsize=(2.2 * len(images), 2.6))
    for ax, img, label in zip(axes, images, labels):
        ax.imshow(img[y0:y1, x0:x1])
        ax.set_title(label, fontsize=9)
        ax.axis("off")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sample", required=True, help="path of the caustics-sponza executable")
    p.add_argument("--out", required=True)
    p.add_argument("--scene", default="builtin:atrium")
    p.add_argument("--width", type=int, default=1920)
    p.add_argument("--height", type=int, default=1080)
    p.add_argument("--map-resolution", type=int, default=512)
    p.add_argument("--exposure", type=float, default=1.0)
    args = p.parse_args()
    frames_dir = os.path.join(args.out, "frames")
    os.makedirs(frames_dir, exist_ok=True)
    rays = [render(args, frames_dir, f"rays_{r}", r, "4") for r in RAYS]
    depths = [render(args, frames_dir, f"depth_{d}", "1", d) for d in DEPTHS]
    box = crop_box(rays[-1])
    write_row(rays, [f"{r} rays/texel" for r in RAYS], box, f"{args.scene}: caustics vs rays per texel (depth 4)",
              os.path.join(args.out, "figure10_rays_per_texel.png"))
    write_row(depths, [f"depth {d}" for d in DEPTHS], box, f"{args.scene}: caustics vs depth (1 ray per texel)",
              os.path.join(args.out, "figure12_depth.png"))


if __name__ == "__main__":
    main()
