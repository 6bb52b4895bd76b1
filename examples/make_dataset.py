#!/usr/bin/env python3
"""A Kubric-like training set through a real lens: one folder per frame with the image and
its labels, made by `lensrt render --frames` and read back with lensrt.read.

    PYTHONPATH=build/python python3 examples/make_dataset.py                 # scenes/propeller.gltf
    PYTHONPATH=build/python python3 examples/make_dataset.py --scene S.gltf --frames 0:47 \\
        --lens wide-22mm --res 640x480 --spp 64 --out out/dataset

OUT/frame_NNNN/ holds (H x W arrays, row 0 at the top; conventions in docs/ground-truth.md):
  rgba.png            the image, sRGB (the EXR beside it keeps linear floats)
  image.exr           everything lensrt wrote: RGBA and every AOV, float, with its header
  depth.npy           float32 metres from the camera's centre (the entrance pupil) to what
                      the pixel sees, along the ray: Kubric's `depth`; 0 where nothing is hit
  z.npy               float32 metres along the viewing axis (Blender's Z)
  normal.npy          float32 H x W x 3, world space
  segmentation.png    uint16: the glTF node index + 1 that covers most of the pixel, 0 for
                      the background (Kubric's segmentation: 0 is the background)
  forward_flow.npy    float32 H x W x 2 (x right, y down, pixels) to the next frame, and
  backward_flow.npy   to the previous one, when lensrt has the flow AOV (docs/ground-truth.md)
  camera.json         the frame's camera: pose (glTF's and OpenCV's conventions), time and
                      the OpenCV intrinsics of the lens as set for the frame
OUT/metadata.json lists the frames, the scene, the lens and the objects' names by id;
OUT/contact_sheet.png shows each frame's image, depth, segmentation and flow."""

import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np

import lensrt

ROOT = pathlib.Path(__file__).resolve().parents[1]


def lensrt_command():
    found = os.environ.get("LENSRT_CLI") or shutil.which("lensrt")
    return found or str(ROOT / "build" / "src" / "app" / "lensrt")


def has_flow(cli):
    """Whether this lensrt writes the flow AOV (its --aov help names it)."""
    help_text = subprocess.run([cli, "render", "--help"], capture_output=True, text=True).stdout
    return "flow" in help_text.split("--aov", 1)[-1].split("\n", 1)[0]


def write_png16(path, values):
    """A uint16 single-channel PNG (OpenCV when present, else matplotlib cannot: numpy's .npy)."""
    try:
        import cv2
    except ImportError:
        np.save(path.with_suffix(".npy"), values)
        return path.with_suffix(".npy")
    cv2.imwrite(str(path), values)
    return path


def flow_channels(result, direction):
    """The H x W x 2 flow to the next (forward) or previous (backward) frame, or None."""
    names = [n for n in result.channels if n.startswith(f"flow.{direction}.")]
    if len(names) != 2:
        return None
    x, y = sorted(names)  # .X then .Y
    return np.dstack([result.channels[x], result.channels[y]])


def flow_colour(flow):
    """Middlebury's colour coding, roughly: hue is the direction, saturation the length."""
    import matplotlib.colors

    u, v = flow[..., 0], flow[..., 1]
    length = np.hypot(u, v)
    scale = max(float(np.percentile(length, 99)), 1e-6)
    hue = (np.arctan2(-v, -u) / np.pi + 1) / 2
    hsv = np.dstack([hue, np.clip(length / scale, 0, 1), np.ones_like(hue)])
    return matplotlib.colors.hsv_to_rgb(hsv)


def contact_sheet(out, frames):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    columns = ["image", "depth (m)", "segmentation", "forward flow"]
    fig, axes = plt.subplots(len(frames), len(columns), figsize=(3 * len(columns), 2.4 * len(frames)),
                             squeeze=False)
    for row, (name, result) in enumerate(frames):
        rgb = np.clip(result.rgb, 0, 1) ** (1 / 2.2)
        depth = result.channels["depth.Z"]
        seg = np.rint(result.channels["object_id.X"]).astype(int)
        flow = flow_channels(result, "forward")
        panels = [rgb, np.where(depth > 0, depth, np.nan), seg, flow_colour(flow) if flow is not None else None]
        for col, (title, panel) in enumerate(zip(columns, panels)):
            ax = axes[row][col]
            ax.set_xticks([])
            ax.set_yticks([])
            if row == 0:
                ax.set_title(title, fontsize=9)
            if col == 0:
                ax.set_ylabel(name, fontsize=8)
            if panel is None:
                ax.text(0.5, 0.5, "no flow AOV", ha="center", va="center", fontsize=8)
                continue
            shown = ax.imshow(panel, cmap="viridis" if col == 1 else "tab10" if col == 2 else None,
                              interpolation="nearest")
            if col == 1:
                fig.colorbar(shown, ax=ax, fraction=0.04)
    fig.tight_layout()
    fig.savefig(out / "contact_sheet.png", dpi=80)
    plt.close(fig)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scene", default=str(ROOT / "scenes" / "propeller.gltf"))
    p.add_argument("--frames", default="0:3", help="A:B, as lensrt render --frames")
    p.add_argument("--fps", default="240")
    p.add_argument("--lens", default="dgauss-50mm", help="a lens of the library, or 'pinhole'")
    p.add_argument("--fstop", default="8")
    p.add_argument("--res", default="160x120")
    p.add_argument("--spp", default="16")
    p.add_argument("--shutter", default="0", help="seconds; 0 (default): sharp frames, labels of one instant")
    p.add_argument("--out", default="out/dataset")
    args = p.parse_args(argv)
    out = pathlib.Path(args.out)
    exr = out / "exr"
    exr.mkdir(parents=True, exist_ok=True)
    cli = lensrt_command()
    aovs = ["depth", "z", "normal", "object_id"] + (["flow"] if has_flow(cli) else [])
    camera = [] if args.lens == "pinhole" else ["--camera", "lens", "--lens", args.lens, "--fstop", args.fstop]
    command = [cli, "render", args.scene, "--frames", args.frames, "--fps", args.fps, "--res", args.res,
               "--spp", args.spp, "--shutter", args.shutter, "--aov", ",".join(aovs), *camera, "-q", "-o", str(exr / "frame_####.exr")]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"make_dataset: {' '.join(command)}: {done.stderr.strip()}")
    first, last = (int(v) for v in args.frames.split(":")[:2])
    shown = []
    for n in range(first, last + 1):
        stem = exr / f"frame_{n:04d}"
        result = lensrt.read(stem.with_suffix(".exr"))
        folder = out / f"frame_{n:04d}"
        folder.mkdir(exist_ok=True)
        shutil.copyfile(stem.with_suffix(".exr"), folder / "image.exr")
        shutil.copyfile(stem.with_suffix(".camera.json"), folder / "camera.json")
        result.write(folder / "rgba.png")
        c = result.channels
        np.save(folder / "depth.npy", c["depth.Z"])
        np.save(folder / "z.npy", c["Z"])
        np.save(folder / "normal.npy", np.dstack([c["normal.X"], c["normal.Y"], c["normal.Z"]]))
        write_png16(folder / "segmentation.png", (np.rint(c["object_id.X"]) + 1).astype(np.uint16))
        for direction in ("forward", "backward"):
            flow = flow_channels(result, direction)
            if flow is not None:
                np.save(folder / f"{direction}_flow.npy", flow)
        shown.append((folder.name, result))
    gltf = json.loads(pathlib.Path(args.scene).read_text()) if args.scene.endswith(".gltf") else {}
    names = {i + 1: node.get("name", f"node{i}") for i, node in enumerate(gltf.get("nodes", []))}
    (out / "metadata.json").write_text(json.dumps({
        "scene": args.scene, "frames": [name for name, _ in shown], "fps": float(args.fps),
        "lens": args.lens, "fstop": None if args.lens == "pinhole" else float(args.fstop),
        "resolution": [int(v) for v in args.res.split("x")], "spp": int(args.spp), "aovs": aovs,
        "segmentation_names": {"0": "background", **{str(k): v for k, v in names.items()}},
        "command": " ".join(command)}, indent=2) + "\n")
    contact_sheet(out, shown)
    print(f"make_dataset: wrote {len(shown)} frames to {out} (contact sheet: {out / 'contact_sheet.png'})")


if __name__ == "__main__":
    main()
