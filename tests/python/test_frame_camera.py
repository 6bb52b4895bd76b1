"""The camera JSON beside each frame of `lensrt render --frames`
(api/frame_camera.h): the frame's time, the camera's pose in glTF's and
OpenCV's conventions and the intrinsics fitted to the lens as set for that
frame. Checked against a camera that glTF animation moves and turns by known
amounts, and against OpenCV's own projection (cv2.projectPoints)."""

import base64
import json
import math
import struct

import cv2
import numpy as np

import lensrt

RES = (96, 64)
YAW = math.radians(20)  # the camera node turns left about +y
YFOV = 0.8


def camera_scene(tmp_path):
    """A quad ahead, and a camera node whose translation goes from (0, 1, 5) at
    0 s to (2, 1, 5) at 2 s, turned by YAW."""
    pos = struct.pack("<12f", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0)
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3) + bytes(4)
    times = struct.pack("<2f", 0, 2)
    moves = struct.pack("<6f", 0, 1, 5, 2, 1, 5)
    buf = pos + idx + times + moves
    views = [(0, 48), (48, 12), (64, 8), (72, 24)]
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0},
                  {"camera": 0, "translation": [0, 1, 5],
                   "rotation": [0, math.sin(YAW / 2), 0, math.cos(YAW / 2)]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": YFOV, "znear": 0.1}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-1, -1, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [2]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}],
        "animations": [{"samplers": [{"input": 2, "output": 3}],
                        "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}],
    }
    path = tmp_path / "pan.gltf"
    path.write_text(json.dumps(gltf))
    return path


def frames(cli, tmp_path, *flags):
    scene = camera_scene(tmp_path)
    cli("render", scene, "--frames", "0:2", "--fps", "1", "--res", f"{RES[0]}x{RES[1]}", "--spp", "1",
        "--shutter", "0", "-q", "-o", tmp_path / "f.#.exr", *flags)
    return [json.loads((tmp_path / f"f.{n}.camera.json").read_text()) for n in range(3)]


def test_pose_and_pinhole_intrinsics_are_the_closed_form(cli, tmp_path):
    yaw = np.array([[math.cos(YAW), 0, math.sin(YAW)], [0, 1, 0], [-math.sin(YAW), 0, math.cos(YAW)]])
    for n, j in enumerate(frames(cli, tmp_path)):
        assert j["time_s"] == n
        centre = np.array([n, 1.0, 5.0])  # the animation, linear at 1 m/s
        np.testing.assert_allclose(j["position_m"], centre, atol=1e-6)
        w = np.array(j["world_from_camera"])
        np.testing.assert_allclose(w[:3, :3], yaw, atol=1e-6)
        np.testing.assert_allclose(w[:3, 3], centre, atol=1e-6)
        # OpenCV's frame: y down, looking down +z.
        flip = np.diag([1.0, -1.0, -1.0])
        np.testing.assert_allclose(j["opencv"]["R"], flip @ yaw.T, atol=1e-6)
        np.testing.assert_allclose(j["opencv"]["t"], -flip @ yaw.T @ centre, atol=1e-6)
        k = j["intrinsics"]
        focal = RES[1] / 2 / math.tan(YFOV / 2)  # pixels, from glTF's yfov
        assert abs(k["fx"] / focal - 1) < 1e-6 and abs(k["fy"] / focal - 1) < 1e-6
        assert abs(k["cx"] - (RES[0] - 1) / 2) < 1e-6 and abs(k["cy"] - (RES[1] - 1) / 2) < 1e-6
        assert max(abs(c) for c in k["dist_coeffs"]) < 1e-6


def test_lens_frames_reproject_with_opencv_and_follow_the_focus(cli, tmp_path):
    """Through dgauss-50mm with the focus racked from 2 m to 4 m: each frame's
    JSON, used by cv2.projectPoints, puts world points where Lens.project does,
    and its fx follows the focus (the field breathes)."""
    js = frames(cli, tmp_path, "--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "8", "--focus", "0:2,2:4")
    lens = lensrt.Lens("dgauss-50mm")
    assert [j["intrinsics"]["focus_m"] for j in js] == [2.0, 3.0, 4.0]
    fx = [j["intrinsics"]["fx"] for j in js]
    assert fx[0] > fx[1] > fx[2]
    rng = np.random.default_rng(1)
    for n, j in enumerate(js):
        w = np.array(j["world_from_camera"])
        # Points on the focus plane, inside the field.
        local = np.c_[rng.uniform(-0.3, 0.3, 40), rng.uniform(-0.2, 0.2, 40), np.full(40, -j["intrinsics"]["focus_m"])]
        world = (w @ np.c_[local, np.ones(40)].T).T[:, :3]
        exact = lens.project(world, w, res=RES, focus=j["intrinsics"]["focus_m"], fstop=8)
        assert exact.visible.all()
        k = j["intrinsics"]
        rvec, _ = cv2.Rodrigues(np.array(j["opencv"]["R"]))
        cv, _ = cv2.projectPoints(world, rvec, np.array(j["opencv"]["t"]), np.array(k["camera_matrix"]),
                                  np.array(k["dist_coeffs"]))
        # lensrt's raster puts the top-left pixel's centre at (0.5, 0.5), OpenCV's at (0, 0).
        error = np.linalg.norm(cv.reshape(-1, 2) - (exact.pixels - 0.5), axis=1)
        assert error.max() < 0.05, (n, error.max())
