#!/usr/bin/python3
"""Renders the image rows of the paper's Figures 10 and 12 with the sample: the caustics alone
(--aov caustics, filter off, one frame) at each rays-per-texel setting (0.25 .. 25, depth 4) and at each
depth (1 .. 16, 1 ray per texel), cropped to the caustic, side by side with their labels.

    python3 scripts/render_figure_rows.py --sample build/bin/caustics-sponza --out DIR \
        [--scene builtin:atrium] [--width 1920 --height 1080] [--map-resolution 512] [--exposure E]
    python3 scripts/render_figure_rows.py --bench build/bin/caustics-bench --out DIR [same options]
    (--compose-only with --bench: make the rows from the DIR/frames/*.pfm already written)

--sample renders each frame with the sample (it links OpenImageIO and GLFW at load time); --bench uses
`caustics-bench figures`, which links neither (for a headless GPU machine): it writes the linear caustic
radiance as PFM files, tone-mapped here as exposure * x / (1 + exposure * x), then sRGB-encoded.

Writes DIR/figure10_rays_per_texel.png and DIR/figure12_depth.png (and each frame as DIR/frames/*.png).
On a GPU machine without matplotlib: `--print-commands` prints the sample's command lines (run them
there with bash), then `--compose-only` here makes the rows from the DIR/frames/*.png they wrote.
The crop holds the middle 95 % of the 25-rays-per-texel frame's light along each axis (stray photons
stay out), padded by a fifth, so every tile shows the same region. Needs python3-matplotlib.
"""
import argparse
import os
import subprocess
import sys

import shlex

RAYS = ["0.25", "0.5", "0.75", "1", "2", "4", "8", "25"]
DEPTHS = ["1", "2", "3", "4", "8", "16"]


def sample_command(args, path, rays, depth):
    return [args.sample, "--scene", args.scene, "--width", str(args.width), "--height", str(args.height),
            "--map-resolution", str(args.map_resolution), "--rays-per-texel", rays, "--max-depth", depth,
            "--aov", "caustics", "--no-filter", "--exposure", str(args.exposure), "--out", path]


def frames(frames_dir):
    """(name, path, rays, depth) of every frame of both rows."""
    return ([(f"rays_{r}", os.path.join(frames_dir, f"rays_{r}.png"), r, "4") for r in RAYS] +
            [(f"depth_{d}", os.path.join(frames_dir, f"depth_{d}.png"), "1", d) for d in DEPTHS])


def render(args, path, rays, depth):
    import matplotlib.image as mpimg
    if args.compose_only:
        if not os.path.exists(path):
            sys.exit(f"render_figure_rows: --compose-only: {path} is missing (run the --print-commands lines first)")
        return mpimg.imread(path)[:, :, :3]
    cmd = sample_command(args, path, rays, depth)
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"render_figure_rows: {' '.join(cmd)} failed:\n{result.stderr}")
    return mpimg.imread(path)[:, :, :3]


def read_pfm(path):
    """Portable Float Map: 'PF' (RGB), size line, scale line (negative: little endian), bottom row first."""
    import numpy as np
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            sys.exit(f"render_figure_rows: {path} is not an RGB PFM file")
        width, height = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    if data.size != width * height * 3:
        sys.exit(f"render_figure_rows: {path}: {data.size} floats, want {width * height * 3}")
    return data.reshape(height, width, 3)[::-1]


def tone_map(radiance, exposure):
    import numpy as np
    x = np.maximum(radiance * exposure, 0.0)
    x = x / (1.0 + x)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)


def render_with_bench(args):
    """All frames in one `caustics-bench figures` run; returns (rays images, depth images)."""
    frames_dir = os.path.join(args.out, "frames")
    cmd = [args.bench, "figures", "--scene", args.scene, "--width", str(args.width), "--height", str(args.height),
           "--map-size", str(args.map_resolution), "--out", frames_dir]
    if not args.compose_only:
        result = subprocess.run(cmd, capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit(f"render_figure_rows: {' '.join(cmd)} failed:\n{result.stderr}")
    load = lambda name: tone_map(read_pfm(os.path.join(frames_dir, f"{name}.pfm")), args.exposure)  # noqa: E731
    return [load(f"rays_{r}") for r in RAYS], [load(f"depth_{d}") for d in DEPTHS]


def crop_box(image):
    import numpy as np
    lum = image.mean(axis=2)
    total = lum.sum()
    if total <= 0:
        return 0, image.shape[0], 0, image.shape[1]

    def span(profile):   # the rows (columns) between 2.5 % and 97.5 % of the light: stray photons stay out
        c = np.cumsum(profile) / total
        return int(np.searchsorted(c, 0.025)), int(np.searchsorted(c, 0.975))

    y0, y1 = span(lum.sum(axis=1))
    x0, x1 = span(lum.sum(axis=0))
    pad_y, pad_x = max(4, (y1 - y0) // 5), max(4, (x1 - x0) // 5)
    return (max(0, y0 - pad_y), min(image.shape[0], y1 + pad_y + 1),
            max(0, x0 - pad_x), min(image.shape[1], x1 + pad_x + 1))


def write_row(images, labels, box, title, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
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
    p.add_argument("--sample", default="build/bin/caustics-sponza", help="path of the caustics-sponza executable")
    p.add_argument("--bench", help="path of caustics-bench: render with its `figures` mode (no OpenImageIO/GLFW)")
    p.add_argument("--print-commands", action="store_true",
                   help="print the sample's command lines (one per frame, into OUT/frames) and exit")
    p.add_argument("--compose-only", action="store_true", help="make the rows from the frames already in OUT/frames")
    p.add_argument("--out", required=True)
    p.add_argument("--scene", default="builtin:atrium")
    p.add_argument("--width", type=int, default=1920)
    p.add_argument("--height", type=int, default=1080)
    p.add_argument("--map-resolution", type=int, default=512)
    p.add_argument("--exposure", type=float, default=1.0)
    args = p.parse_args()
    frames_dir = os.path.join(args.out, "frames")
    if args.print_commands:
        print(f"mkdir -p {shlex.quote(frames_dir)}")
        for _, path, rays, depth in frames(frames_dir):
            print(shlex.join(sample_command(args, path, rays, depth)))
        return
    os.makedirs(frames_dir, exist_ok=True)
    if args.bench:
        rays, depths = render_with_bench(args)
    else:
        images = [render(args, path, rays, depth) for _, path, rays, depth in frames(frames_dir)]
        rays, depths = images[:len(RAYS)], images[len(RAYS):]
    box = crop_box(rays[-1])
    write_row(rays, [f"{r} rays/texel" for r in RAYS], box, f"{args.scene}: caustics vs rays per texel (depth 4)",
              os.path.join(args.out, "figure10_rays_per_texel.png"))
    write_row(depths, [f"depth {d}" for d in DEPTHS], box, f"{args.scene}: caustics vs depth (1 ray per texel)",
              os.path.join(args.out, "figure12_depth.png"))


if __name__ == "__main__":
    main()
