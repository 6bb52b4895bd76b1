"""examples/make_dataset.py, run as a user would on the small animated scene
(scenes/propeller.gltf): a folder per frame whose labels are the render's own channels in
the dataset's conventions, the frame's camera, the metadata and the contact sheet."""

import json
import os
import subprocess
import sys

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")

import cv2  # noqa: E402
import numpy as np  # noqa: E402

import lensrt  # noqa: E402
from conftest import ROOT  # noqa: E402


def test_dataset_folders_hold_the_render_and_its_labels(tmp_path):
    out = tmp_path / "dataset"
    done = subprocess.run([sys.executable, ROOT / "examples" / "make_dataset.py", "--frames", "1:2", "--res", "48x36",
                           "--spp", "2", "--out", out], capture_output=True, text=True, env=os.environ)
    assert done.returncode == 0, done.stderr
    meta = json.loads((out / "metadata.json").read_text())
    assert meta["frames"] == ["frame_0001", "frame_0002"]
    assert meta["segmentation_names"]["0"] == "background" and meta["segmentation_names"]["3"] == "propeller"
    assert (out / "contact_sheet.png").stat().st_size > 10000
    images = []
    for name in meta["frames"]:
        folder = out / name
        exr = lensrt.read(folder / "image.exr")
        c = exr.channels
        seg = cv2.imread(str(folder / "segmentation.png"), cv2.IMREAD_UNCHANGED)
        assert seg.dtype == np.uint16 and seg.shape == (36, 48)
        assert np.array_equal(seg, np.rint(c["object_id.X"]).astype(np.uint16) + 1)
        # the wall behind and the propeller (node indices 1 and 2), the background past the wall
        assert {2, 3} <= set(np.unique(seg)) <= {0, 2, 3}
        assert np.array_equal(np.load(folder / "depth.npy"), c["depth.Z"])
        assert np.load(folder / "normal.npy").shape == (36, 48, 3)
        rgba = cv2.imread(str(folder / "rgba.png"), cv2.IMREAD_UNCHANGED)
        assert rgba.shape[:2] == (36, 48)
        camera = json.loads((folder / "camera.json").read_text())
        assert abs(camera["time_s"] - int(name[-4:]) / 240) < 1e-12
        assert camera["intrinsics"]["model"] == "opencv" and camera["intrinsics"]["width"] == 48
        # Flow: the still wall reads 0; the blades turn about the hub, so the flow is across them.
        forward = np.load(folder / "forward_flow.npy")
        assert forward.shape == (36, 48, 2)
        assert np.array_equal(forward[..., 0], c["flow.forward.X"]) and np.array_equal(forward[..., 1], c["flow.forward.Y"])
        assert np.abs(forward[seg == 2]).max() == 0 and np.abs(forward[seg == 3]).max() > 0.5
        assert (folder / "backward_flow.npy").exists()
        images.append(c["object_id.X"])
    assert not np.array_equal(images[0], images[1])  # the propeller turned between the frames
