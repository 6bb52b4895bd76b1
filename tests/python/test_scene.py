"""lensrt.Scene: the command line's bits, poses, AOVs, progress, Ctrl-C, errors."""

import ast
import os
import pathlib
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import lensrt
from conftest import ROOT, SCENES

DOF = SCENES / "dof_row.gltf"


@pytest.fixture(scope="module")
def dof():
    return lensrt.Scene(DOF)


@pytest.mark.parametrize(
    "flags, kwargs",
    [
        (["--camera", "pinhole"], dict(camera="pinhole")),
        (["--camera", "thin", "--fstop", "2", "--focus", "2"], dict(camera="thin", fstop=2, focus=2.0)),
        (["--camera", "thick", "--lens", "dgauss-50mm"], dict(camera="thick", lens="dgauss-50mm")),
        (["--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "2.8", "--aov", "depth,variance"],
         dict(camera="lens", lens="dgauss-50mm", fstop=2.8, aov=("depth", "variance"))),
    ],
)
def test_same_bits_as_the_command_line(dof, cli, tmp_path, flags, kwargs):
    out = tmp_path / "cli.exr"
    cli("render", DOF, "--res", "96x54", "--spp", "4", "--seed", "11", "-q", "-o", out, *flags)
    result = dof.render(res=(96, 54), spp=4, seed=11, **kwargs)
    report = lensrt.diff(out, result, fail=0, warn=0)
    assert report["overall"]["maxError"] == 0.0 and report["verdict"] == "PASS"
    # And written, the same file but for the call and the time.
    result.write(tmp_path / "py.exr")
    assert lensrt.diff(out, tmp_path / "py.exr", fail=0)["overall"]["maxError"] == 0.0


@pytest.mark.parametrize("camera", [dict(camera="pinhole"), dict(camera="lens", lens="dgauss-50mm", fstop=2)])
def test_adaptive_sampling_has_the_bits_of_the_command_line(dof, cli, tmp_path, camera):
    out = tmp_path / "cli.exr"
    flags = ["--camera", camera["camera"]] + (["--lens", "dgauss-50mm", "--fstop", "2"] if "lens" in camera else [])
    cli("render", DOF, "--res", "48x27", "--spp", "32", "--min-spp", "4", "--noise-threshold", "0.1", "--seed", "11",
        "-q", "-o", out, *flags)
    result = dof.render(res=(48, 27), spp=32, min_spp=4, noise_threshold=0.1, seed=11, **camera)
    assert lensrt.diff(out, result, fail=0, warn=0)["overall"]["maxError"] == 0.0
    spp = result.channels["spp"]
    assert spp.min() == 4 and 4 < spp.max() <= 32 and result.spp == 32
    assert result.metadata["lensrt:spp"].startswith("adaptive min=4 mean=")


def test_arrays_view_the_render_without_copies(dof):
    result = dof.render(res=(64, 36), spp=1, aov="depth")
    rgb, channels = result.rgb, result.channels
    assert rgb.shape == (36, 64, 3) and rgb.dtype == np.float32
    assert list(channels) == ["R", "G", "B", "A", "depth.Z"]
    address = lambda a: a.__array_interface__["data"][0]
    # One interleaved buffer: R, G, B, A, depth.Z of a pixel side by side.
    assert np.shares_memory(rgb, channels["R"]) and address(rgb) == address(channels["R"])
    assert address(channels["depth.Z"]) == address(rgb) + 4 * 4 and rgb.strides == (64 * 5 * 4, 5 * 4, 4)
    assert (rgb[..., 1] == channels["G"]).all()
    del result  # the arrays keep the pixels alive
    assert np.isfinite(rgb).all() and rgb.mean() > 0


def test_position_aov_holds_the_world_point_whatever_the_pose():
    # flat_wall is the plane z = -2 m: every pixel that sees it reads world z
    # -2 wherever the camera stands, and the centre pixel the point on its axis.
    wall = lensrt.Scene(SCENES / "flat_wall.gltf")
    pose = np.eye(4)
    pose[:2, 3] = (0.3, -0.2)
    pose[2, 3] = 1.0
    channels = wall.render(res=(33, 33), spp=16, aov=("position", "uv", "object_coords"),
                           camera_to_world=pose).channels
    assert [c for c in channels if c[:2] in ("po", "uv", "ob")] == [
        "position.X", "position.Y", "position.Z", "uv.U", "uv.V",
        "object_coords.X", "object_coords.Y", "object_coords.Z"]
    seen = channels["A"] > 0
    assert seen.mean() > 0.9
    assert np.abs(channels["position.Z"][seen] + 2.0).max() < 1e-5
    assert channels["position.X"][16, 16] == pytest.approx(0.3, abs=1e-3)
    assert channels["position.Y"][16, 16] == pytest.approx(-0.2, abs=1e-3)


def test_camera_to_world_sets_the_pose():
    # flat_wall: an emitting wall in the plane z = -2 m; a camera at z = c
    # looking down -Z sees it at depth 2 + c on its axis.
    wall = lensrt.Scene(SCENES / "flat_wall.gltf")
    for c in (1.0, -1.5):
        pose = np.eye(4)
        pose[2, 3] = c
        depth = wall.render(res=(33, 33), spp=1, aov="depth", camera_to_world=pose).channels["depth.Z"]
        assert depth[16, 16] == pytest.approx(2.0 + c, rel=1e-4)  # float32 depth
    # Turned to look along +Z (180 degrees about Y), it sees nothing.
    turned = np.diag([-1.0, 1.0, -1.0, 1.0])
    result = wall.render(res=(16, 16), spp=1, camera_to_world=turned, env="none")
    assert result.rgb.max() == 0.0
    with pytest.raises(ValueError, match="camera_to_world: expected a rigid 4 x 4 pose"):
        wall.render(camera_to_world=np.diag([2.0, 2.0, 2.0, 1.0]))
    with pytest.raises(ValueError, match="camera_to_world: expected a 4 x 4 array"):
        wall.render(camera_to_world=np.eye(3))


def test_progress_is_called_between_passes_and_can_stop(dof):
    calls = []
    result = dof.render(res=(32, 18), spp=16, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (16, 16) and [d for d, _ in calls] == sorted(d for d, _ in calls)
    assert result.finished and result.spp == 16
    stopped = dof.render(res=(32, 18), spp=64, progress=lambda done, total: done < 2)
    assert not stopped.finished and 2 <= stopped.spp < 64
    with pytest.raises(ZeroDivisionError):
        dof.render(res=(32, 18), spp=8, progress=lambda done, total: 1 / 0)


def test_the_gil_is_released_while_rendering(dof):
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    thread = threading.Thread(target=tick)
    thread.start()
    start = time.monotonic()
    dof.render(res=(320, 180), spp=16, threads=1)
    seconds = time.monotonic() - start
    done.set()
    thread.join()
    # Held, the other thread would not run at all while the render does.
    assert len(ticks) > 0.2 * seconds / 0.001


def test_ctrl_c_stops_the_render_at_the_end_of_a_pass(tmp_path):
    script = tmp_path / "long.py"
    script.write_text(
        "import lensrt, sys\n"
        f"scene = lensrt.Scene({str(DOF)!r})\n"
        "print('rendering', flush=True)\n"
        "try:\n"
        "    scene.render(res=(320, 180), spp=1 << 20, threads=1)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    sys.exit(3)\n")
    env = dict(os.environ)
    proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=env)
    assert proc.stdout.readline().strip() == "rendering"
    time.sleep(1.0)
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=60)
    # A pass lasts about a second, the one in flight finishes.
    assert proc.returncode == 3 and out.strip() == "interrupted"
    assert time.monotonic() - sent < 10


def test_every_keyword_is_read(dof, tmp_path):
    # Each keyword with a value other than its default: render() refuses a
    # keyword it accepts but never reads, and each changes what it should.
    pose = np.eye(4)
    pose[1, 3] = 1.2
    result = dof.render(camera="lens", lens="dgauss-50mm", fstop=4, focus="auto", focus_pixel=(4, 4),
                        sensor="aps-c", res=(24, 16), spp=2, noise_threshold=0.5, min_spp=1, seed=3, aov=("depth",),
                        env="constant:0.5",
                        env_rotate=10, env_intensity=0.5, max_depth=3, light_sampler="power", camera_node=0, camera_to_world=pose,
                        threads=1, crop=(0, 24, 0, 16), blades=6, blade_rotation=15, aperture_mask=None,
                        focal_length=None, exposure="physical", shutter=1 / 250, iso=400, dispersion=False,
                        coatings="multi", flare=False, flare_bounces=2, barrel_reflectance=0, film="irradiance", spectral=True, sensor_response="cie1931", white_balance=5000,
                        output_space="acescg", noise=True, sensor_params="smartphone",
                        raw=tmp_path / "a.dng", cfa="GRBG", progress=lambda done, total: None)
    m = result.metadata
    assert "f/4" in m["lensrt:camera"] and "physical 0.004s ISO400" in m["lensrt:exposure"]
    assert m["lensrt:coatings"] == "multi" and m["lensrt:dispersion"] == "off"
    assert "smartphone" in m["lensrt:sensor_noise"] and (tmp_path / "a.dng").exists()
    assert "max_depth=3 light_sampler=power" in m["lensrt:settings"] and m["lensrt:seed"] == "3"
    assert "noise_threshold=0.5 min_spp=1" in m["lensrt:settings"]
    assert "transport=spectral:cie1931,wb=5000K,output=acescg" in m["lensrt:settings"]


def test_spectral_takes_auto(dof):
    # The keyword takes "auto" as the flag does; the metadata says what it chose.
    assert dof.render(res=(8, 6), spp=1, spectral="auto").metadata["lensrt:transport"] == \
        "rgb (auto: nothing needs wavelengths)"
    camera = dof.render(res=(8, 6), spp=1, spectral="auto", sensor_response="nikon-d850")
    assert camera.metadata["lensrt:transport"] == "spectral (auto: a camera response)"


def test_render_help_lists_every_keyword_of_the_stub():
    stub = ast.parse((pathlib.Path(lensrt.__file__).parent / "__init__.pyi").read_text())
    scene = next(n for n in stub.body if isinstance(n, ast.ClassDef) and n.name == "Scene")
    render = next(n for n in scene.body if isinstance(n, ast.FunctionDef) and n.name == "render")
    keywords = [a.arg for a in render.args.kwonlyargs]
    assert len(keywords) == 51  # the option table's render keywords, camera_to_world and progress
    doc = lensrt.Scene.render.__doc__
    for k in keywords:
        assert f"{k}=" in doc[doc.index("render(camera="):].split("->")[0], k  # in the signature line
        assert f"{k}:" in doc or f"{k} (" in doc or f" {k}," in doc, k  # and described
    # Every stub keyword is one render() takes: an unknown one is refused.
    with pytest.raises(ValueError, match="unknown option 'spp_count'"):
        lensrt.Scene(DOF).render(spp_count=4)


@pytest.mark.parametrize(
    "kwargs, error",
    [
        (dict(spp="many"), "spp: expected an integer, got str 'many'"),
        (dict(spp=0), "spp: expected a positive integer up to 16777216 (samples per pixel), got '0'"),
        (dict(camera="fisheye"), "camera: fisheye not in {pinhole,thin,thick,lens}"),
        (dict(blades=2), "blades: 2 blades"),
        (dict(camera="lens", lens="dgauss-50mm", coatings="gold"), "coatings: gold not in {none,single,multi}"),
        (dict(res=(0, 10)), "res: width and height must be between 1 and 65536 pixels"),
        (dict(aov="depth,colour"), "aov: unknown AOV 'colour'"),
        (dict(fstop=float("nan")), "fstop: expected a finite number"),
        (dict(env="constant:x"), "env: constant radiance must be"),
        (dict(camera="lens"), "lens: camera='lens' needs a lens"),
        (dict(progress=3), "progress: expected a callable"),
        (dict(crop=(10, 5, 0, 4)), "crop: expected 0 <= X0 < X1"),
        (dict(noise_threshold=0), "noise_threshold: expected a number > 0"),
        (dict(noise_threshold="low"), "noise_threshold: expected a"),
        (dict(noise_threshold=0.01, min_spp=4), "min_spp: 4 is above spp=1"),
        (dict(min_spp=1), "min_spp: needs noise_threshold"),
        (dict(light_sampler="bvh"), "light_sampler: expected tree or power, got 'bvh'"),
    ],
)
def test_bad_options_raise_value_error(dof, kwargs, error):
    with pytest.raises(ValueError) as raised:
        dof.render(**{"res": (32, 18), "spp": 1, **kwargs})
    assert error in str(raised.value)


def test_missing_and_broken_files(tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere.glb"):
        lensrt.Scene(tmp_path / "nowhere.glb")
    broken = tmp_path / "broken.gltf"
    broken.write_text('{"asset": {"version": "2.0"}, "scenes": [{"nodes": [7]}]}')
    with pytest.raises(ValueError, match="broken.gltf"):
        lensrt.Scene(broken)
    with pytest.raises(FileNotFoundError, match="no-such-lens"):
        lensrt.Scene(DOF).render(camera="lens", lens="no-such-lens", res=(8, 8), spp=1)
    with pytest.raises(ValueError, match="scene_index: expected an integer"):
        lensrt.Scene(DOF, scene_index="first")


def test_diff_is_diff_json(cli, cli_json, tmp_path, dof):
    a, b = tmp_path / "a.exr", tmp_path / "b.exr"
    dof.render(res=(48, 27), spp=2, seed=1, aov="variance").write(a)
    dof.render(res=(48, 27), spp=2, seed=2, aov="variance").write(b)
    expected = cli("diff", a, b, "--json", "--noise-aware", check=False)
    import json
    assert lensrt.diff(str(a), str(b), noise_aware=True) == json.loads(expected.stdout)
    assert lensrt.diff(str(a), str(b))["exitStatus"] == cli("diff", a, b, check=False).returncode
    with pytest.raises(FileNotFoundError):
        lensrt.diff(tmp_path / "none.exr", b)
    with pytest.raises(ValueError, match="not comparable"):
        lensrt.diff(a, dof.render(res=(8, 8), spp=1))
    with pytest.raises(ValueError, match="fail_percent: expected a number from 0 to 100"):
        lensrt.diff(a, b, fail_percent=200)


def test_raw_writes_the_mosaic_as_a_dng(dof, tmp_path):
    out = tmp_path / "raw" / "a.dng"
    result = dof.render(res=(40, 30), spp=1, raw=out, cfa="BGGR")
    data = out.read_bytes()
    assert data[:4] == b"II*\x00" and len(data) > 40 * 30 * 2
    # BGGR: the top-left site is blue, the 16-bit value of the image's B there.
    blue = round(min(max(float(result.channels["B"][0, 0]), 0.0), 1.0) * 65535)
    assert blue.to_bytes(2, "little") in data
    with pytest.raises(ValueError, match="cfa: expected RGGB, BGGR, GRBG or GBRG, got 'RGBG'"):
        dof.render(res=(8, 8), spp=1, raw=out, cfa="RGBG")


@pytest.mark.parametrize("name", ["py.tif", "py.dpx", "py.jp2", "py.webp"])
def test_write_goes_through_the_plugin_beside_the_module(dof, cli, tmp_path, name):
    # The OpenImageIO plugin, found beside the module: the file is the command's.
    out = tmp_path / ("cli" + pathlib.Path(name).suffix)
    cli("render", DOF, "--res", "48x32", "--spp", "2", "--seed", "3", "-q", "-o", out)
    dof.render(res=(48, 32), spp=2, seed=3).write(tmp_path / name)
    assert lensrt.diff(out, tmp_path / name, fail=0)["overall"]["maxError"] == 0.0


def test_read_gives_the_channels_and_header_the_command_wrote(dof, cli, tmp_path):
    """lensrt.read: an EXR of `lensrt render` with AOVs, as a RenderResult whose channels hold
    the bits of the same render made in Python, and whose metadata is the file's header."""
    out = tmp_path / "aovs.exr"
    cli("render", DOF, "--res", "40x24", "--spp", "2", "--seed", "5", "--aov", "depth,normal", "-q", "-o", out)
    read = lensrt.read(out)
    made = dof.render(res=(40, 24), spp=2, seed=5, aov=["depth", "normal"])
    assert sorted(read.channels) == sorted(made.channels)
    for name, values in made.channels.items():
        assert np.array_equal(read.channels[name], values), name
    assert read.metadata["lensrt:seed"] == "5" and read.spp == 2 and read.camera == made.camera
    assert "worldToCamera" in read.metadata  # the standard attributes too, not only lensrt:*
    with pytest.raises(FileNotFoundError, match="no such file"):
        lensrt.read(tmp_path / "missing.exr")
    (tmp_path / "junk.exr").write_text("not an image")
    with pytest.raises(ValueError, match="junk.exr"):
        lensrt.read(tmp_path / "junk.exr")


def test_time_poses_the_animated_scene(tmp_path):
    """A black square that glTF animation moves from x = -2 to x = 2 over 2 s:
    seen from the front at time 0 it sits left of centre, at 2 s right of it,
    at 1 s in the middle."""
    import base64
    import json
    import struct

    pos = struct.pack("<12f", -0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0)
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3) + bytes(4)  # padded to 16 bytes
    times = struct.pack("<2f", 0, 2)
    moves = struct.pack("<6f", -2, 0, 0, 2, 0, 0)
    buf = pos + idx + times + moves
    views = [(0, 48), (48, 12), (64, 8), (72, 24)]
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 6]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1.2, "znear": 0.1}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]}}],
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [2]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}],
        "animations": [{"name": "slide", "samplers": [{"input": 2, "output": 3}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}],
    }
    path = tmp_path / "slide.gltf"
    path.write_text(json.dumps(gltf))

    def centre_x(scene):
        lit = scene.render(res=(64, 32), spp=16, env=1).rgb.mean(axis=2)
        cols = np.nonzero(lit.min(axis=0) < 0.5)[0]  # the black square hides the sky
        return cols.mean() / 64

    assert centre_x(lensrt.Scene(path)) < 0.4
    assert centre_x(lensrt.Scene(path, time=2.0)) > 0.6
    assert abs(centre_x(lensrt.Scene(path, time=1.0, animation="slide")) - 0.5) < 0.05
    with pytest.raises(ValueError, match="has no animation 'walk'"):
        lensrt.Scene(path, animation="walk")


def test_at_poses_the_file_again_with_the_bits_of_a_new_scene(cli, tmp_path):
    """Scene.at(t) is the file posed at t: the bits of lensrt.Scene(file, time=t) and of
    `lensrt render --frames`, each pose its own Scene (earlier ones stay usable)."""
    path = SCENES / "propeller.gltf"
    scene = lensrt.Scene(path)
    cli("render", path, "--frames", "1:2", "--fps", "24", "--res", "24x24", "--spp", "2", "-q",
        "-o", tmp_path / "f.#.exr")
    posed = [scene.at(f / 24) for f in (1, 2)]
    for f, at in zip((1, 2), posed):
        a = at.render(res=(24, 24), spp=2)
        b = lensrt.Scene(path, time=f / 24).render(res=(24, 24), spp=2)
        assert np.array_equal(a.rgb, b.rgb)
        assert lensrt.diff(tmp_path / f"f.{f}.exr", a, fail=0, warn=0)["overall"]["maxError"] == 0.0
    first = scene.render(res=(24, 24), spp=2).rgb
    assert np.abs(first - posed[0].render(res=(24, 24), spp=2).rgb).mean() > 0.001  # the propeller turned
    assert np.array_equal(posed[1].at(0.0).render(res=(24, 24), spp=2).rgb, first)
    with pytest.raises(ValueError, match="time"):
        scene.at(float("nan"))


def test_flare_and_keyframed_fstop_are_the_command_lines(dof, cli, tmp_path):
    """flare=, flare_bounces=, barrel_reflectance= and an fstop given as keyframes render the bits
    of `lensrt render` with the same flags."""
    out = tmp_path / "cli.exr"
    cli("render", DOF, "--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "0:4,2:8", "--flare", "on",
        "--flare-bounces", "2", "--barrel-reflectance", "0.25", "--coatings", "single", "--res", "32x18", "--spp", "2",
        "-q", "-o", out)
    result = dof.render(camera="lens", lens="dgauss-50mm", fstop="0:4,2:8", flare=True, flare_bounces=2,
                        barrel_reflectance=0.25,
                        coatings="single", res=(32, 18), spp=2)
    assert "flare=2 barrel=0.25" in result.metadata["lensrt:camera"] and result.metadata["lensrt:f_number"] == "4"
    assert lensrt.diff(out, result, fail=0, warn=0)["overall"]["maxError"] == 0.0


def test_motion_blur_and_rolling_shutter_are_the_command_lines(cli, tmp_path):
    """An animated scene renders with the motion of the shutter it is given: the Scene is
    posed again for a span other than the default shutter's, with the bits of `lensrt render`;
    a shutter of 0 is the still frame, which a rolling shutter bends."""
    path = SCENES / "propeller.gltf"
    scene = lensrt.Scene(path, time=0.1)
    out = tmp_path / "cli.exr"
    flags = ["--res", "32x32", "--spp", "2", "--shutter", "1/2000", "--rolling-shutter", "1/60"]
    cli("render", path, "--time", "0.1", *flags, "-q", "-o", out)
    rolling = scene.render(res=(32, 32), spp=2, shutter="1/2000", rolling_shutter=1 / 60)
    assert lensrt.diff(out, rolling, fail=0, warn=0)["overall"]["maxError"] == 0.0
    assert "rolling top-down" in rolling.metadata["lensrt:settings"]
    still = scene.render(res=(32, 32), spp=2, shutter=0)
    assert np.abs(still.rgb - rolling.rgb).mean() > 0.01
    with pytest.raises(ValueError, match="readout"):
        scene.render(res=(8, 8), spp=1, rolling_shutter=0.01, readout="diagonal")
