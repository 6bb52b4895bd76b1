"""--aov flow (docs/ground-truth.md, "Flow"): the image motion of the surface point each
sample sees, against closed forms (a plane translating square to the axis: f dx / Z /
pitch through the pinhole and the thin lens), against Lens.project through dgauss-50mm,
by warping the next frame back, and the .flo files and the anchors' conventions (Blender's
Vector pass as Cycles computes it, Kubric's conversion of it)."""

import base64
import json
import math
import pathlib
import shutil
import struct
import subprocess
import zlib

import numpy as np
import pytest

import lensrt
from conftest import SCENES

Z = 2.0  # metres from the camera to the plane
SPEED = 1.2  # metres per second along +x
FPS = 24.0
YFOV = 0.5  # radians
RES = (64, 48)
PITCH_MM = min(36.0 / RES[0], 24.0 / RES[1])  # 36 x 24 mm cropped to the frame's 4:3: 32 x 24 mm


def png(rgb):
    """An 8-bit RGB PNG's bytes."""
    h, w, _ = rgb.shape
    raw = b"".join(b"\0" + rgb[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def plane_scene(path, plane_speed=SPEED, camera_speed=0.0, size=6.0, plane_speed_y=0.0):
    """A size x size emissive plane (a smooth texture) Z metres down -z, moving along +x at
    plane_speed (and +y at plane_speed_y), and a camera at the origin looking down -z,
    moving along +x at camera_speed (LINEAR keyframes at 0 and 10 s)."""
    u = np.linspace(0, 2 * math.pi, 256)
    pattern = 0.5 + 0.25 * np.sin(13 * u)[None, :] + 0.2 * np.cos(11 * u)[:, None]
    texture = (np.clip(np.dstack([pattern, pattern[::-1], pattern.T]), 0, 1) * 255).astype(np.uint8)
    s = size / 2
    positions = np.array([[-s, -s, 0], [s, -s, 0], [s, s, 0], [-s, s, 0]], np.float32)
    uvs = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    times = np.array([0, 10], np.float32)
    plane_path = np.array([[0, 0, -Z], [10 * plane_speed, 10 * plane_speed_y, -Z]], np.float32)
    camera_path = np.array([[0, 0, 0], [10 * camera_speed, 0, 0]], np.float32)
    blobs = [positions.tobytes(), uvs.tobytes(), indices.tobytes() + b"\0\0\0\0", times.tobytes(),
             plane_path.tobytes(), camera_path.tobytes()]
    views, offset = [], 0
    for b in blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(b)})
        offset += len(b)
    views[2]["byteLength"] = 12
    data = b"".join(blobs)
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "translation": [0, 0, -Z]}, {"camera": 0}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": YFOV, "znear": 0.1}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1],
                       "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png(texture)).decode()}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-s, -s, 0], "max": [s, s, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [10]},
            {"bufferView": 4, "componentType": 5126, "count": 2, "type": "VEC3"},
            {"bufferView": 5, "componentType": 5126, "count": 2, "type": "VEC3"},
        ],
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "translation"}}],
                        "samplers": [{"input": 3, "output": 4, "interpolation": "LINEAR"},
                                     {"input": 3, "output": 5, "interpolation": "LINEAR"}]}],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(data).decode()}],
    }
    path.write_text(json.dumps(doc))
    return path


def read_flo(path):
    """A Middlebury .flo file, read per its format: float32 tag 202021.25, int32 width and
    height, then row-major float32 (u, v)."""
    raw = path.read_bytes()
    tag = np.frombuffer(raw, "<f4", 1)[0]
    w, h = np.frombuffer(raw, "<i4", 2, 4)
    assert tag == np.float32(202021.25) and raw[:4] == b"PIEH"
    assert len(raw) == 12 + 8 * w * h
    return np.frombuffer(raw, "<f4", 2 * w * h, 12).reshape(h, w, 2)


def pinhole_focal_px():
    return RES[1] / 2 / math.tan(YFOV / 2)


def thin_focal_px():
    f = 50.0
    v = f * Z * 1000 / (Z * 1000 - f)  # the image distance, focused on the plane
    return v / PITCH_MM


CAMERAS = [
    (["--camera", "pinhole"], pinhole_focal_px),
    (["--camera", "thin", "--focal-length", "50", "--fstop", "8", "--focus", str(Z)], thin_focal_px),
]


@pytest.mark.parametrize("flags, focal_px", CAMERAS, ids=["pinhole", "thin"])
def test_frames_of_a_translating_plane_give_the_closed_form(cli, tmp_path, flags, focal_px):
    scene = plane_scene(tmp_path / "plane.gltf")
    cli("render", scene, "--res", f"{RES[0]}x{RES[1]}", "--spp", 2, "--frames", "3:3", "--flo", "on",
        "--aov", "flow", "-q", "-o", tmp_path / "f.####.exr", *flags)
    forward = read_flo(tmp_path / "f.0003.forward.flo")
    backward = read_flo(tmp_path / "f.0003.backward.flo")
    expected = focal_px() * SPEED / FPS / Z  # f dx / Z over the pixel pitch
    assert forward.shape == (RES[1], RES[0], 2)
    np.testing.assert_allclose(forward[..., 0], expected, atol=0.02)
    np.testing.assert_allclose(forward[..., 1], 0, atol=0.02)
    np.testing.assert_allclose(backward[..., 0], -expected, atol=0.02)
    np.testing.assert_allclose(backward[..., 1], 0, atol=0.02)


def test_python_flow_step_gives_the_frames_bits(cli, tmp_path):
    # Scene.render(flow_step=...) at a frame's time is --frames' render of it.
    scene = plane_scene(tmp_path / "plane.gltf")
    cli("render", scene, "--res", f"{RES[0]}x{RES[1]}", "--spp", 2, "--frames", "3:3", "--flo", "on",
        "--aov", "flow", "-q", "-o", tmp_path / "f.####.exr")
    result = lensrt.Scene(scene, time=3 / FPS).render(res=RES, spp=2, aov="flow", flow_step=1 / FPS)
    c = result.channels
    for direction in ("forward", "backward"):
        flo = read_flo(tmp_path / f"f.0003.{direction}.flo")
        np.testing.assert_array_equal(c[f"flow.{direction}.X"], flo[..., 0])
        np.testing.assert_array_equal(c[f"flow.{direction}.Y"], flo[..., 1])
    np.testing.assert_allclose(c["flow.forward.X"], pinhole_focal_px() * SPEED / FPS / Z, atol=0.02)


def test_a_moving_camera_moves_the_image_the_other_way(cli, tmp_path):
    scene = plane_scene(tmp_path / "pan.gltf", plane_speed=0.0, camera_speed=-0.6)
    cli("render", scene, "--res", f"{RES[0]}x{RES[1]}", "--spp", 1, "--frames", "2:4:2", "--flo", "on",
        "--aov", "flow", "-q", "-o", tmp_path / "p.####.exr", "--camera", "pinhole")
    forward = read_flo(tmp_path / "p.0004.forward.flo")  # the step is 2 frames
    expected = pinhole_focal_px() * 0.6 * 2 / FPS / Z
    np.testing.assert_allclose(forward[..., 0], expected, atol=0.02)
    np.testing.assert_allclose(read_flo(tmp_path / "p.0004.backward.flo")[..., 0], -expected, atol=0.02)


@pytest.mark.parametrize("kwargs, focal_px", [(dict(camera="pinhole"), pinhole_focal_px),
                                              (dict(camera="thin", focal_length=50, fstop=8, focus=Z),
                                               thin_focal_px)], ids=["pinhole", "thin"])
@pytest.mark.parametrize("plane_speed, camera_speed", [(SPEED, 0.0), (0.0, -SPEED), (SPEED / 2, -SPEED / 2)],
                         ids=["plane", "camera", "both"])
def test_a_still_frame_gives_the_motion_over_its_shutter(tmp_path, kwargs, focal_px, plane_speed, camera_speed):
    scene = lensrt.Scene(plane_scene(tmp_path / "plane.gltf", plane_speed, camera_speed), time=1.0)
    result = scene.render(res=RES, spp=2, aov="flow", shutter=0.05, **kwargs)
    c = result.channels
    expected = focal_px() * (plane_speed - camera_speed) * 0.05 / Z
    np.testing.assert_allclose(c["flow.forward.X"], expected, atol=0.02)
    np.testing.assert_allclose(c["flow.forward.Y"], 0, atol=0.02)
    np.testing.assert_allclose(c["flow.backward.X"], -expected, atol=0.02)


def test_through_dgauss_the_corners_move_as_lens_project_says(tmp_path):
    # The plane in focus at f/8: each corner pixel's samples see (nearly) the point its
    # centre's chief ray meets, so the pixel's mean flow is Lens.project's motion of it.
    res, shutter = (48, 32), 0.05
    lens = lensrt.Lens("dgauss-50mm")
    optics = dict(res=res, focus=Z, fstop=8, sensor="36x24")
    scene = lensrt.Scene(plane_scene(tmp_path / "plane.gltf", size=20.0), time=1.0)
    result = scene.render(camera="lens", lens="dgauss-50mm", spp=16, aov="flow", shutter=shutter, env="none",
                          **optics)
    corners = np.array([[0.5, 0.5], [res[0] - 0.5, 0.5], [0.5, res[1] - 0.5], [res[0] - 0.5, res[1] - 0.5]])
    rays = lens.unproject(corners, None, **optics)
    t = (-Z - rays.origins[:, 2]) / rays.directions[:, 2]
    seen = rays.origins + t[:, None] * rays.directions
    moved = seen + [SPEED * shutter, 0, 0]
    expected = lens.project(moved, None, **optics).pixels - lens.project(seen, None, **optics).pixels
    for (x, y), e in zip(corners.astype(int), expected):
        got = [result.channels["flow.forward.X"][y, x], result.channels["flow.forward.Y"][y, x]]
        np.testing.assert_allclose(got, e, atol=0.05)
    # The distortion shows: the corners' flow differs from the centre's by more than the tolerance.
    centre = result.channels["flow.forward.X"][res[1] // 2, res[0] // 2]
    assert abs(expected[0][0] - centre) > 0.05


def test_a_keyed_focus_breathes_the_flow_of_a_still_plane(cli, tmp_path):
    # Racking the focus between frames moves a still point's image (the field of view
    # breathes): each neighbouring frame projects through its own focus.
    res, optics = (48, 32), dict(fstop=8, sensor="36x24")
    scene = plane_scene(tmp_path / "still.gltf", plane_speed=0.0, size=20.0)
    cli("render", scene, "--res", f"{res[0]}x{res[1]}", "--spp", 4, "--frames", "3:3", "--aov", "flow",
        "--camera", "lens", "--lens", "dgauss-50mm", "--fstop", 8, "--sensor", "36x24", "--focus", "0:0.6,1:3",
        "--env", "none", "-q", "-o", tmp_path / "k.####.exr")
    c = lensrt.read(tmp_path / "k.0003.exr").channels
    focus = lambda t: 0.6 + 2.4 * t  # metres, the keys' line
    lens = lensrt.Lens("dgauss-50mm")
    corners = np.array([[0.5, 0.5], [res[0] - 0.5, 0.5], [0.5, res[1] - 0.5], [res[0] - 0.5, res[1] - 0.5]])
    rays = lens.unproject(corners, None, res=res, focus=focus(3 / FPS), **optics)
    t = (-Z - rays.origins[:, 2]) / rays.directions[:, 2]
    seen = rays.origins + t[:, None] * rays.directions
    now = lens.project(seen, None, res=res, focus=focus(3 / FPS), **optics).pixels
    for frame, direction in ((4, "forward"), (2, "backward")):
        expected = lens.project(seen, None, res=res, focus=focus(frame / FPS), **optics).pixels - now
        assert np.abs(expected).max() > 0.1  # the breathing shows at the corners
        for (x, y), e in zip(corners.astype(int), expected):
            got = [c[f"flow.{direction}.X"][y, x], c[f"flow.{direction}.Y"][y, x]]
            np.testing.assert_allclose(got, e, atol=0.03, err_msg=direction)


def test_warping_the_next_frame_back_by_the_forward_flow_gives_this_frame(cli, tmp_path):
    scene = lensrt.Scene(plane_scene(tmp_path / "plane.gltf"), time=1.0)
    common = dict(res=RES, spp=64, camera="pinhole", env="none", max_depth=0)
    frame = scene.render(shutter=1e-6, **common).rgb
    step = 0.05
    flow = scene.render(shutter=step, aov="flow", **common).channels
    following = scene.at(1.0 + step).render(shutter=1e-6, **common).rgb
    ys, xs = np.mgrid[0:RES[1], 0:RES[0]].astype(np.float64)
    fx, fy = xs + flow["flow.forward.X"], ys + flow["flow.forward.Y"]
    # Bilinear lookup of the next frame where each pixel's point went.
    x0, y0 = np.floor(fx).astype(int), np.floor(fy).astype(int)
    inside = (x0 >= 0) & (y0 >= 0) & (x0 + 1 < RES[0]) & (y0 + 1 < RES[1])
    x0, y0 = np.clip(x0, 0, RES[0] - 2), np.clip(y0, 0, RES[1] - 2)
    ax, ay = (fx - x0)[..., None], (fy - y0)[..., None]
    warped = ((1 - ax) * (1 - ay) * following[y0, x0] + ax * (1 - ay) * following[y0, x0 + 1]
              + (1 - ax) * ay * following[y0 + 1, x0] + ax * ay * following[y0 + 1, x0 + 1])
    error = np.abs(warped - frame)[inside]
    assert inside.mean() > 0.8
    # Against the difference without the flow (the frames differ by ~3 px of motion).
    unwarped = np.abs(following - frame)[inside]
    # Measured: 0.0025 mean and 0.021 at the 99th percentile (the bilinear lookup's error
    # at the pattern's crests) against 0.113 unwarped.
    assert error.mean() < 0.05 * unwarped.mean(), (error.mean(), unwarped.mean())
    assert np.percentile(error, 99) < 0.25 * unwarped.mean()


def blender_vector(forward, backward):
    """Blender's 4-channel Vector pass from lensrt's flow (docs/ground-truth.md)."""
    return np.stack([backward[..., 0], -backward[..., 1], -forward[..., 0], forward[..., 1]], -1)


def kubric_flows(forward, backward):
    """Kubric's (drow, dcol) forward_flow and backward_flow (docs/ground-truth.md)."""
    return (np.stack([forward[..., 1], forward[..., 0]], -1),
            np.stack([-backward[..., 1], -backward[..., 0]], -1))


def test_the_anchors_conventions():
    # Cycles' Vector pass (intern/cycles/kernel/geom/primitive.h, primitive_motion_vector):
    # pre - centre and centre - post in its raster space, y up from the bottom row.
    height = 48.0
    rng = np.random.default_rng(3)
    centre, prev, nxt = (rng.uniform(0, 40, (5, 2)) for _ in range(3))  # lensrt raster, y down
    cycles = lambda p: np.c_[p[:, 0], height - p[:, 1]]  # noqa: E731
    vector = np.c_[cycles(prev) - cycles(centre), cycles(centre) - cycles(nxt)]
    forward, backward = nxt - centre, prev - centre  # lensrt's flow.forward, flow.backward
    np.testing.assert_allclose(blender_vector(forward, backward), vector, atol=1e-12)
    # Kubric reads that pass (kubric/renderer/blender_utils.py) as
    # backward_flow = (V.G, -V.R) and forward_flow = (V.A, -V.B).
    kubric_forward = np.c_[vector[:, 3], -vector[:, 2]]
    kubric_backward = np.c_[vector[:, 1], -vector[:, 0]]
    ours_forward, ours_backward = kubric_flows(forward, backward)
    np.testing.assert_allclose(ours_forward, kubric_forward, atol=1e-12)
    np.testing.assert_allclose(ours_backward, kubric_backward, atol=1e-12)
    # So Kubric's forward flow is (drow, dcol) of the motion to the next frame, and its
    # backward flow the motion from the previous frame to this one (minus ours).
    np.testing.assert_allclose(ours_forward, np.c_[forward[:, 1], forward[:, 0]])


def read_exr(path):
    """The channels of an uncompressed scanline OpenEXR file (float32 or half), per the
    OpenEXR file layout: the header's attributes, the line offsets, then each line's
    channels in the order of the channel list."""
    raw = path.read_bytes()
    assert raw[:4] == b"\x76\x2f\x31\x01"
    pos, attrs = 8, {}
    while raw[pos] != 0:
        fields = []
        for _ in range(2):
            end = raw.index(b"\0", pos)
            fields.append(raw[pos:end].decode())
            pos = end + 1
        size, = struct.unpack_from("<i", raw, pos)
        attrs[fields[0]] = raw[pos + 4:pos + 4 + size]
        pos += 4 + size
    pos += 1
    channels, chlist, p = [], attrs["channels"], 0
    while chlist[p] != 0:
        end = chlist.index(b"\0", p)
        channels.append((chlist[p:end].decode(), struct.unpack_from("<i", chlist, end + 1)[0]))
        p = end + 17
    assert attrs["compression"][0] == 0, "uncompressed files only"
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    out = {name: np.zeros((h, w)) for name, _ in channels}
    for offset in struct.unpack_from(f"<{h}Q", raw, pos):
        y, _ = struct.unpack_from("<ii", raw, offset)
        q = offset + 8
        for name, kind in channels:
            dtype, size = ("<f4", 4) if kind == 2 else ("<f2", 2)
            out[name][y - y0] = np.frombuffer(raw, dtype, w, q)
            q += size * w
    return out


@pytest.mark.skipif(shutil.which("blender") is None, reason="needs Blender (Debian's blender)")
def test_blenders_vector_pass_is_the_stated_mapping(cli, tmp_path):
    # Cycles renders the same plane moving right and up; its Vector pass equals
    # blender_vector() of lensrt's flow (measured with Blender 3.4.1: (-2.35, -1.17,
    # -2.35, -1.17) px for 2.35 px right and 1.17 px up per frame).
    vy = SPEED / 2
    scene = plane_scene(tmp_path / "plane.gltf", plane_speed_y=vy)
    cli("render", scene, "--res", f"{RES[0]}x{RES[1]}", "--spp", 1, "--frames", "3:3", "--flo", "on",
        "--aov", "flow", "-q", "-o", tmp_path / "f.####.exr", "--camera", "pinhole", "--shutter", 0)
    script = pathlib.Path(__file__).with_name("blender_vector_pass.py")
    done = subprocess.run(["blender", "-b", "--factory-startup", "-P", script, "--", tmp_path / "b.exr",
                           *map(str, (*RES, YFOV, SPEED, vy, 3))], capture_output=True, text=True)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    exr = read_exr(tmp_path / "b.exr")
    vector = np.stack([exr[f"ViewLayer.Vector.{c}"] for c in "XYZW"], -1)  # a uniform field
    ours = blender_vector(read_flo(tmp_path / "f.0003.forward.flo"), read_flo(tmp_path / "f.0003.backward.flo"))
    np.testing.assert_allclose(ours, vector, atol=0.02)
    assert np.all(vector[..., 0] < -2) and np.all(vector[..., 3] < -1)  # right and up: all negative


def test_bad_input_gets_one_line(cli, tmp_path):
    still = cli("render", SCENES / "cornell.gltf", "--res", "8x6", "--spp", 1, "--aov", "flow",
                "-o", tmp_path / "a.exr", check=False)
    assert still.returncode != 0
    assert still.stderr.count("\n") == 1 and "--aov: flow needs motion" in still.stderr
    plane = plane_scene(tmp_path / "plane.gltf")
    no_shutter = cli("render", plane, "--res", "8x6", "--spp", 1, "--aov", "flow", "--shutter", "0",
                     "-o", tmp_path / "b.exr", check=False)
    assert no_shutter.returncode != 0 and "flow needs motion" in no_shutter.stderr
    for extra, flag in [(["--checkpoint", "60"], "--aov"), (["--resume", tmp_path / "c.exr"], "--aov"),
                        ([], "--flo")]:
        args = ["--aov", "flow"] if flag == "--aov" else ["--flo", "on"]
        done = cli("render", plane, "--res", "8x6", "--spp", 1, *args, *extra, "-o", tmp_path / "c.exr",
                   check=False)
        assert done.returncode != 0 and done.stderr.count("\n") == 1 and flag in done.stderr, done.stderr
    unknown = cli("render", plane, "--aov", "flows", "-o", tmp_path / "d.exr", check=False)
    assert unknown.returncode != 0 and "unknown AOV 'flows'" in unknown.stderr




def test_flow_changes_no_other_channel():
    # With the ID AOVs (whose channels come before flow's) and depth, each channel holds
    # the same bits with and without flow.
    scene = lensrt.Scene(SCENES / "propeller.gltf", time=0.2)
    kwargs = dict(res=(32, 32), spp=2, shutter=0.002)
    both = scene.render(aov=["depth", "crypto_object", "object_id", "flow"], **kwargs).channels
    ids = scene.render(aov=["depth", "crypto_object", "object_id"], **kwargs).channels
    flow = scene.render(aov="flow", **kwargs).channels
    assert set(both) == set(ids) | set(flow)
    for name, values in list(ids.items()) + list(flow.items()):
        np.testing.assert_array_equal(both[name], values, err_msg=name)
    assert np.abs(flow["flow.forward.X"]).max() > 0.5


def test_a_pixel_averages_its_first_samples_that_hit():
    """The flow of a pixel is the mean over its first kFlowSamplesPerPixel (8) samples that
    hit: 8 and 32 spp give the same bits where the propeller's blades (whose samples in a
    pixel move differently: a rotation) cover pixels, where every sample hits the blades or
    the wall. Without the limit, 32 spp averages 32 samples and the edges differ."""
    scene = lensrt.Scene(SCENES / "propeller.gltf", time=0.2)
    kwargs = dict(res=(32, 32), shutter=0.002, seed=4, aov="flow")
    eight = scene.render(spp=8, **kwargs).channels
    more = scene.render(spp=32, **kwargs).channels
    assert (eight["A"] == 1).all()  # the wall is behind everything: every sample hits
    for name in ("flow.forward.X", "flow.forward.Y", "flow.backward.X", "flow.backward.Y"):
        np.testing.assert_array_equal(eight[name], more[name], err_msg=name)
    assert np.abs(more["flow.forward.X"]).max() > 0.5
