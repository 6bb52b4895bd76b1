"""OpenCV confirms the lens: a checkerboard rendered at 12 poses through the
full lens, found by cv2.findChessboardCorners and cornerSubPix, calibrated by
cv2.calibrateCamera (cv2.fisheye.calibrate for the fisheye), gives the
intrinsics of `lensrt lens calibrate` (fx, fy within 0.5%, k1 within 5% or
0.005 near 0, reprojection RMS at most 0.15 px); the pinhole, as a control,
gives k1 = 0 within 0.002 and fx = f / pitch within 0.2%.

Both sides fit the same model: OpenCV's k1 k2 p1 p2 (CALIB_FIX_K3; lensrt's
"opencv4"), whose k1 does not trade against k3 as the 5-coefficient model's
does on a dozen views, and cv2.fisheye's k1..k4. The board emits its own light
(white squares 1, black 0, max_depth 0, RGB transport): the picture's only
noise is the sampling of pixel and pupil, which a Gaussian blur of 0.8 px
tames (a symmetric blur leaves a saddle point where it is). 480 x 320 pixels,
16 spp: about 10 s a lens on two cores (slow label)."""

import base64
import json
import math

import cv2
import numpy as np
import pytest

import lensrt

RES = (480, 320)
COLS, ROWS = 12, 9  # squares; 11 x 8 inner corners
SPP = 16
BLUR_PX = 0.8


def write_board(path, square):
    """The checkerboard glTF: black squares in the plane z = 0 (no emission),
    a white card 1 mm behind (emitting 1) with a one-square border; facing +z,
    centred on the origin. Returns the inner corners (N x 3, metres) in
    findChessboardCorners' order, row by row."""
    w, h = COLS * square, ROWS * square
    black = [(-w / 2 + i * square, -h / 2 + j * square, square, 0.0)
             for j in range(ROWS) for i in range(COLS) if (i + j) % 2 == 0]
    card = [(-w / 2 - square, -h / 2 - square, None, -0.001)]
    buffer, views, accessors, primitives = b"", [], [], []
    for material, rects in ((0, card), (1, black)):
        positions, indices = [], []
        for x0, y0, size, z in rects:
            x1, y1 = (x0 + size, y0 + size) if size else (-x0, -y0)
            base = len(positions)
            positions += [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        pos, idx = np.array(positions, np.float32), np.array(indices, np.uint32)
        for array, target, component, kind in ((pos, 34962, 5126, "VEC3"), (idx, 34963, 5125, "SCALAR")):
            views.append({"buffer": 0, "byteOffset": len(buffer), "byteLength": array.nbytes, "target": target})
            accessor = {"bufferView": len(views) - 1, "componentType": component, "type": kind,
                        "count": len(array)}
            if kind == "VEC3":
                accessor.update(min=pos.min(0).tolist(), max=pos.max(0).tolist())
            accessors.append(accessor)
            buffer += array.tobytes()
        primitives.append({"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1,
                           "material": material})
    black_material = {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0}}
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": primitives}],
        "materials": [dict(black_material, name="white", emissiveFactor=[1, 1, 1]), dict(black_material, name="black")],
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
        "bufferViews": views, "accessors": accessors,
    }
    path.write_text(json.dumps(gltf))
    return np.array([(-w / 2 + (i + 1) * square, -h / 2 + (j + 1) * square, 0.0)
                     for j in range(ROWS - 1) for i in range(COLS - 1)], np.float32)


def look_at(eye, target, roll):
    """A glTF camera pose (looking down -Z, +Y up) at `eye` toward `target`."""
    back = eye - target
    back /= np.linalg.norm(back)
    right = np.cross([0.0, 1.0, 0.0], back)
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    pose = np.eye(4)
    pose[:3, 0] = math.cos(roll) * right + math.sin(roll) * up
    pose[:3, 1] = -math.sin(roll) * right + math.cos(roll) * up
    pose[:3, 2] = back
    pose[:3, 3] = eye
    return pose


def covering_poses(project, outline, distance, tilt_deg):
    """Twelve views whose board lies wholly inside the frame, spread toward its
    edges and corners where distortion shows: of 600 random candidates
    (tilted up to tilt_deg, rolled up to 25 degrees), the one reaching
    farthest from the centre in each of 8 directions, then the most central.
    project(camera-space points) gives the raster positions and visibility."""
    rng = np.random.default_rng(3)
    candidates = []
    for _ in range(600):
        az, el = np.radians(rng.uniform(-tilt_deg, tilt_deg, 2))
        eye = distance * rng.uniform(0.9, 1.1) * np.array(
            [math.sin(az) * math.cos(el), math.sin(el), math.cos(az) * math.cos(el)])
        target = np.array([*rng.uniform(-0.45, 0.45, 2) * distance, 0.0])
        candidates.append(look_at(eye, target, math.radians(rng.uniform(-25, 25))))
    homogeneous = np.c_[outline, np.ones(len(outline))]
    camera = np.concatenate([(np.linalg.inv(m) @ homogeneous.T).T[:, :3] for m in candidates])
    pixels, visible = project(camera)
    w, h = RES
    good = []
    for k, pose in enumerate(candidates):
        px = pixels[k * len(outline):(k + 1) * len(outline)]
        inside = visible[k * len(outline):(k + 1) * len(outline)].all()
        if not inside or px[:, 0].min() < 0.01 * w or px[:, 0].max() > 0.99 * w \
                or px[:, 1].min() < 0.01 * h or px[:, 1].max() > 0.99 * h:
            continue
        reach = np.hypot((px[:, 0] - w / 2) / (w / 2), (px[:, 1] - h / 2) / (h / 2)).max()
        centre = px.mean(0) - (w / 2, h / 2)
        good.append((reach, math.atan2(centre[1], centre[0]), np.hypot(*centre), k, pose))
    picked = []
    for sector in range(8):
        lo = -math.pi + sector * math.pi / 4
        inside = [g for g in good if lo <= g[1] < lo + math.pi / 4]
        if inside:
            picked.append(max(inside, key=lambda g: g[0]))
    for g in sorted(good, key=lambda g: g[2]):
        if len(picked) == 12:
            break
        if all(g[3] != p[3] for p in picked):
            picked.append(g)
    assert len(picked) == 12
    return [p[4] for p in picked]


def calibrate_renders(tmp_path, render, project, distance, square, tilt_deg, fisheye):
    """Render the board at the covering poses, find its corners and calibrate.
    Also returns how far the corners OpenCV found lie from where project()
    puts them (RMS, pixels): the render against the projection, directly."""
    corners = write_board(tmp_path / "board.gltf", square * distance)
    scene = lensrt.Scene(tmp_path / "board.gltf")
    s = square * distance
    outline = np.array([[x * (COLS / 2 + 1) * s, y * (ROWS / 2 + 1) * s, 0.0] for x in (-1, 1) for y in (-1, 1)])
    objects, images, misses = [], [], []
    for pose in covering_poses(project, outline, distance, tilt_deg):
        rgb = render(scene, pose).rgb.mean(axis=2)
        blurred = cv2.GaussianBlur(rgb, (0, 0), BLUR_PX)
        grey = np.clip(blurred / np.percentile(blurred, 99.5) * 255, 0, 255).astype(np.uint8)
        found, c = cv2.findChessboardCorners(grey, (COLS - 1, ROWS - 1),
                                             flags=cv2.CALIB_CB_ADAPTIVE_THRESH | cv2.CALIB_CB_NORMALIZE_IMAGE)
        assert found, "the board is in the frame at every pose"
        c = cv2.cornerSubPix(grey, c, (5, 5), (-1, -1), (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 100, 1e-4))
        objects.append(corners.reshape(-1, 1, 3))
        images.append(c)
        # OpenCV's pixel centres are at integers, the raster's at + 0.5; the
        # board's rows and columns may be found in either direction.
        homogeneous = np.c_[corners, np.ones(len(corners))]
        expected, _ = project((np.linalg.inv(pose) @ homogeneous.T).T[:, :3])
        grid = expected.reshape(ROWS - 1, COLS - 1, 2)
        found_raster = c.reshape(-1, 2) + 0.5
        misses.append(min((np.linalg.norm(found_raster - e.reshape(-1, 2), axis=1) ** 2).mean()
                          for e in (grid, grid[::-1], grid[:, ::-1], grid[::-1, ::-1])))
    if fisheye:
        rms, K, D, _, _ = cv2.fisheye.calibrate(
            objects, images, RES, np.zeros((3, 3)), np.zeros((4, 1)),
            flags=cv2.fisheye.CALIB_RECOMPUTE_EXTRINSIC | cv2.fisheye.CALIB_FIX_SKEW,
            criteria=(cv2.TERM_CRITERIA_COUNT + cv2.TERM_CRITERIA_EPS, 200, 1e-12))
    else:
        rms, K, D, _, _ = cv2.calibrateCamera(objects, images, RES, None, None, flags=cv2.CALIB_FIX_K3)
    return rms, K, D.ravel(), math.sqrt(np.mean(misses))


CASES = [  # lens, sensor, focus and board distance (m), board square / distance, tilt
    ("dgauss-50mm", "36x24", 1.5, 0.027, 35),
    ("wide-22mm", "36x24", 0.8, 0.06, 30),
    ("fisheye-10mm", "18x12", 0.5, 0.07, 25),  # the 18 x 12 mm frame lies within its image circle
]


@pytest.mark.parametrize("lens_name,sensor,distance,square,tilt", CASES)
def test_opencv_recovers_lensrts_calibration(tmp_path, lens_name, sensor, distance, square, tilt):
    lens = lensrt.Lens(lens_name)
    fisheye = lens_name.startswith("fisheye")
    keywords = dict(res=RES, sensor=sensor, focus=distance, fstop=8)

    def render(scene, pose):
        return scene.render(camera="lens", lens=lens_name, camera_to_world=pose, spp=SPP, seed=1, env=0,
                            max_depth=0, spectral=False, dispersion=False, **keywords)

    def project(points):
        p = lens.project(points, None, **keywords)
        return p.pixels, p.visible

    rms, K, k, miss = calibrate_renders(tmp_path, render, project, distance, square, tilt, fisheye)
    fit = lens.calibrate(model="fisheye" if fisheye else "opencv4", **keywords)
    print(f"{lens_name}: OpenCV rms {rms:.4f} px, fx {K[0, 0]:.3f} fy {K[1, 1]:.3f} k1 {k[0]:.5f}; "
          f"lensrt fx {fit['fx']:.3f} k1 {fit['k1']:.5f} (fit residual max {fit['residual_px']['max']:.4f} px); "
          f"found corners from Lens.project: RMS {miss:.4f} px")
    assert rms <= 0.15
    # The corners found in the renders are where Lens.project puts them.
    assert miss <= 0.15
    assert K[0, 0] == pytest.approx(fit["fx"], rel=0.005)
    assert K[1, 1] == pytest.approx(fit["fy"], rel=0.005)
    near_zero = abs(fit["k1"]) < 0.02
    assert abs(k[0] - fit["k1"]) <= (0.005 if near_zero else 0.05 * abs(fit["k1"]))


def test_pinhole_control(tmp_path):
    """An ideal pinhole of f = 50 mm on 36 x 24 mm: no distortion, fx = f / pitch."""
    f_px = 50.0 / (36.0 / RES[0])

    def render(scene, pose):
        return scene.render(camera="pinhole", focal_length=50, sensor="36x24", res=RES, camera_to_world=pose,
                            spp=SPP, seed=1, env=0, max_depth=0, spectral=False)

    def project(points):  # the closed form, to choose the views
        z = -points[:, 2]
        with np.errstate(divide="ignore", invalid="ignore"):
            px = np.c_[RES[0] / 2 + f_px * points[:, 0] / z, RES[1] / 2 - f_px * points[:, 1] / z]
        return px, (z > 0) & (px[:, 0] >= 0) & (px[:, 0] <= RES[0]) & (px[:, 1] >= 0) & (px[:, 1] <= RES[1])

    rms, K, k, miss = calibrate_renders(tmp_path, render, project, 1.5, 0.027, 35, False)
    print(f"pinhole: OpenCV rms {rms:.4f} px, fx {K[0, 0]:.3f} fy {K[1, 1]:.3f} (f / pitch {f_px:.3f}) k1 {k[0]:.5f}; "
          f"found corners from the closed form: RMS {miss:.4f} px")
    assert rms <= 0.15
    assert abs(k[0]) <= 0.002
    assert K[0, 0] == pytest.approx(f_px, rel=0.002)
    assert K[1, 1] == pytest.approx(f_px, rel=0.002)
