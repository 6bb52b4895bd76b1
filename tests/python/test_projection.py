"""Lens.project, Lens.unproject and Lens.calibrate (`lensrt lens calibrate`):
the conventions each output keeps, checked against OpenCV's own projection
(cv2.projectPoints, cv2.fisheye.projectPoints, cv2.FileStorage) and against
COLMAP's written out here from its documentation, and the fit's residual."""

import json
import math
import os

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")  # before cv2 loads: the ST maps are EXR

import cv2  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import lensrt  # noqa: E402

RES = (640, 360)


def grid(width, height, n=17):
    xs, ys = np.meshgrid(np.linspace(0.5, width - 0.5, n), np.linspace(0.5, height - 0.5, n))
    return np.c_[xs.ravel(), ys.ravel()]


def test_pinhole_projection_is_the_closed_form_and_raster_starts_top_left():
    lens = lensrt.Lens("dgauss-50mm")
    # The pinhole derived from a lens has its field at that focus; at infinity f = EFL.
    efl = lens.info()["efl_mm"]
    pitch = 36.0 / RES[0]  # full frame cropped to 16:9: 36 x 20.25 mm
    points = np.array([[0.0, 0.0, -3.0], [0.4, 0.25, -3.0], [-0.2, -0.1, -1.0]])
    p = lens.project(points, None, res=RES, focus="inf", camera="pinhole")
    expected_x = RES[0] / 2 + efl / pitch * points[:, 0] / -points[:, 2]
    expected_y = RES[1] / 2 - efl / pitch * points[:, 1] / -points[:, 2]  # +Y up, raster y down
    np.testing.assert_allclose(p.pixels[:, 0], expected_x, rtol=0, atol=1e-9)
    np.testing.assert_allclose(p.pixels[:, 1], expected_y, rtol=0, atol=1e-9)
    assert p.visible.all() and (p.status == 0).all()


def test_thin_lens_projection_is_the_closed_form():
    lens = lensrt.Lens("dgauss-50mm")
    efl = lens.info()["efl_mm"]
    v = efl * 2000.0 / (2000.0 - efl)  # the image distance at 2 m
    pitch = 36.0 / RES[0]
    points = np.array([[0.3, -0.2, -2.0], [0.05, 0.1, -0.8], [-1.0, 0.5, -9.0]])  # in and out of focus
    p = lens.project(points, None, res=RES, focus=2, fstop=4, camera="thin")
    np.testing.assert_allclose(p.pixels[:, 0], RES[0] / 2 + v / pitch * points[:, 0] / -points[:, 2], atol=1e-9)
    np.testing.assert_allclose(p.pixels[:, 1], RES[1] / 2 - v / pitch * points[:, 1] / -points[:, 2], atol=1e-9)


def test_world_points_go_through_the_pose_and_round_trip():
    lens = lensrt.Lens("wide-22mm")
    pose = np.eye(4)
    angle = math.radians(30)
    pose[:3, :3] = [[math.cos(angle), 0, math.sin(angle)], [0, 1, 0], [-math.sin(angle), 0, math.cos(angle)]]
    pose[:3, 3] = [1.0, 0.5, 2.0]
    pixels = grid(*RES)
    rays = lens.unproject(pixels, pose, res=RES, focus=1.5, fstop=4)
    assert rays.visible.all()
    np.testing.assert_allclose(np.linalg.norm(rays.directions, axis=1), 1.0, atol=1e-12)
    for distance in (0.5, 4.0):
        back = lens.project(rays.origins + distance * rays.directions, pose, res=RES, focus=1.5, fstop=4)
        assert back.visible.all()
        np.testing.assert_allclose(back.pixels, pixels, rtol=0, atol=1e-6)
    # Camera-space points: the same through the inverse pose.
    world = rays.origins + 2.0 * rays.directions
    camera = (np.linalg.inv(pose) @ np.c_[world, np.ones(len(world))].T).T[:, :3]
    same = lens.project(camera, None, res=RES, focus=1.5, fstop=4)
    np.testing.assert_allclose(same.pixels, pixels, rtol=0, atol=1e-6)


def test_flags():
    lens = lensrt.Lens("fisheye-10mm")
    p = lens.project([[0, 0, 1.0], [0, 0, -1.0], [0, math.tan(math.radians(50)), -1.0]], None, res=(600, 200),
                     sensor="36x12", focus=2)
    assert p.status.tolist() == [3, 0, 1]  # behind, visible, above the frame
    assert np.isnan(p.pixels[0]).all() and p.pixels[2, 1] < 0
    corner = lens.unproject([[1.0, 1.0]], res=(600, 400), sensor="36x24", focus=2)
    assert corner.status.tolist() == [2]  # beyond the fisheye's image circle
    with pytest.raises(ValueError, match="focus"):
        lens.project([[0, 0, -1.0]], None, res=RES, focus="auto")
    with pytest.raises(ValueError, match="world_points"):
        lens.project([[0, 0]], None, res=RES, focus=2)
    with pytest.raises(ValueError, match="camera_to_world"):
        lens.project([[0, 0, -1.0]], np.ones((4, 4)), res=RES, focus=2)


def normalised_rays(lens, focus, **kw):
    """Exact chief rays of a pixel grid as OpenCV's normalised points (x right,
    y down, z forward) on the focus plane, and their raster positions."""
    pixels = grid(*RES)
    rays = lens.unproject(pixels, res=RES, focus=focus, **kw)
    keep = rays.visible
    o, d = rays.origins[keep], rays.directions[keep]
    t = (-focus - o[:, 2]) / d[:, 2]
    p = o + t[:, None] * d
    cv = np.c_[p[:, 0], -p[:, 1], -p[:, 2]]  # glTF camera space -> OpenCV's frame
    return cv, pixels[keep]


@pytest.mark.parametrize("lens_name,model", [("dgauss-50mm", "opencv"), ("wide-22mm", "full-opencv"),
                                             ("dgauss-50mm", "opencv4"), ("fisheye-10mm", "fisheye")])
def test_opencv_yaml_reprojects_with_cv2(cli, tmp_path, lens_name, model):
    """The YAML, read by cv2.FileStorage and used by OpenCV's own projection,
    puts each exact chief ray's point where lensrt images it, less 0.5 px
    (OpenCV puts the top-left pixel's centre at 0, 0), within the fit's residual."""
    sensor = "18x12" if model == "fisheye" else "36x24"
    yml = tmp_path / "camera.yml"
    out = cli("lens", "calibrate", lens_name, "--res", f"{RES[0]}x{RES[1]}", "--focus", "2", "--fstop", "8",
              "--sensor", sensor, "--model", model, "--opencv", yml, "--json")
    fit = json.loads(out.stdout)
    fs = cv2.FileStorage(str(yml), cv2.FILE_STORAGE_READ)
    K, D = fs.getNode("camera_matrix").mat(), fs.getNode("distortion_coefficients").mat()
    assert (fs.getNode("image_width").real(), fs.getNode("image_height").real()) == RES
    fs.release()
    np.testing.assert_allclose(K, fit["camera_matrix"], rtol=1e-15)
    np.testing.assert_allclose(D.ravel(), fit["dist_coeffs"], rtol=1e-15)
    points, raster = normalised_rays(lensrt.Lens(lens_name), 2.0, fstop=8, sensor=sensor)
    zero = np.zeros(3)
    if model == "fisheye":
        projected, _ = cv2.fisheye.projectPoints(points.reshape(-1, 1, 3), zero, zero, K, D.reshape(4, 1))
    else:
        projected, _ = cv2.projectPoints(points, zero, zero, K, D)
    error = np.linalg.norm(projected.reshape(-1, 2) - (raster - 0.5), axis=1)
    assert error.max() <= fit["residual_px"]["max"] + 1e-6
    assert fit["residual_px"]["max"] < 0.05
    # Dropping the half-pixel would miss by 0.5 px everywhere.
    assert np.linalg.norm(projected.reshape(-1, 2) - raster, axis=1).min() > 0.49


def colmap_project(model, params, x, y):
    """COLMAP's OPENCV / FULL_OPENCV / OPENCV_FISHEYE (src/colmap/sensor/models.h),
    in COLMAP's image coordinates, where the top-left pixel's centre is (0.5, 0.5)."""
    fx, fy, cx, cy, *k = params
    if model == "OPENCV_FISHEYE":
        r = np.maximum(np.hypot(x, y), 1e-300)  # theta_d / r tends to 1 on the axis
        theta = np.arctan(r)
        t2 = theta * theta
        scale = theta * (1 + k[0] * t2 + k[1] * t2**2 + k[2] * t2**3 + k[3] * t2**4) / r
        xd, yd = x * scale, y * scale
    else:
        k1, k2, p1, p2 = k[:4]
        k3, k4, k5, k6 = k[4:] if model == "FULL_OPENCV" else (0, 0, 0, 0)
        r2 = x * x + y * y
        radial = (1 + k1 * r2 + k2 * r2**2 + k3 * r2**3) / (1 + k4 * r2 + k5 * r2**2 + k6 * r2**3)
        xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
        yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    return np.c_[fx * xd + cx, fy * yd + cy]


@pytest.mark.parametrize("model,colmap", [("opencv4", "OPENCV"), ("opencv", "FULL_OPENCV"),
                                          ("full-opencv", "FULL_OPENCV"), ("fisheye", "OPENCV_FISHEYE")])
def test_colmap_line_puts_pixel_centres_at_half(cli, tmp_path, model, colmap):
    sensor = "18x12" if model == "fisheye" else "36x24"
    lens_name = "fisheye-10mm" if model == "fisheye" else "wide-22mm"
    txt = tmp_path / "cameras.txt"
    fit = json.loads(cli("lens", "calibrate", lens_name, "--res", f"{RES[0]}x{RES[1]}", "--focus", "2",
                         "--sensor", sensor, "--model", model, "--colmap", txt, "--json").stdout)
    line = [l for l in txt.read_text().splitlines() if not l.startswith("#")]
    assert len(line) == 1 and line[0] == fit["colmap"]
    camera_id, name, width, height, *params = line[0].split()
    assert (camera_id, name, int(width), int(height)) == ("1", colmap, *RES)
    params = [float(p) for p in params]
    assert params[2] == pytest.approx(fit["cx"] + 0.5, abs=1e-12)
    assert params[3] == pytest.approx(fit["cy"] + 0.5, abs=1e-12)
    points, raster = normalised_rays(lensrt.Lens(lens_name), 2.0, sensor=sensor)
    # COLMAP's image coordinates are lensrt's raster positions.
    projected = colmap_project(colmap, params, points[:, 0] / points[:, 2], points[:, 1] / points[:, 2])
    assert np.linalg.norm(projected - raster, axis=1).max() <= fit["residual_px"]["max"] + 1e-6


def test_calibrate_is_the_cli_json(cli_json):
    lens = lensrt.Lens("dgauss-50mm")
    args = dict(res=RES, focus=3, fstop=4, model="full-opencv")
    assert lens.calibrate(**args) == cli_json("lens", "calibrate", "dgauss-50mm", "--res", "640x360", "--focus", "3",
                                              "--fstop", "4", "--model", "full-opencv", "--json")


def test_fit_residual_dgauss_50mm_full_frame():
    # 1920 x 1280 on the 36 x 24 mm frame (18.75 um pixels), focused at 2 m:
    # RMS 0.0001 px, max 0.0008 px (the issue asks 0.05 px RMS).
    fit = lensrt.Lens("dgauss-50mm").calibrate(res=(1920, 1280), sensor="36x24", focus=2, fstop=8)
    assert fit["residual_px"]["rms"] <= 0.05
    assert fit["residual_px"]["max"] <= 0.01
    assert fit["residual_px"]["blocked"] == 0
    # Barrel distortion, square pixels, the principal point at the frame's centre.
    assert fit["k1"] < 0
    assert fit["fx"] == pytest.approx(fit["fy"], rel=1e-6)
    assert (fit["cx"], fit["cy"]) == pytest.approx((959.5, 639.5), abs=1e-6)


def test_a_fit_over_1px_is_refused_and_nothing_written(cli, tmp_path):
    out = tmp_path / "camera.yml"
    done = cli("lens", "calibrate", "fisheye-10mm", "--res", "640x360", "--focus", "2", "--opencv", out, check=False)
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and "more than 1 px: not written" in done.stderr
    assert not out.exists()
    with pytest.raises(ValueError, match="more than 1 px"):
        lensrt.Lens("fisheye-10mm").calibrate(res=RES, focus=2)
    assert lensrt.Lens("fisheye-10mm").calibrate(res=RES, focus=2, max_residual=100)["residual_px"]["max"] > 1


def test_st_maps_invert_each_other_and_follow_nuke(cli, tmp_path):
    """Nuke's STMap: s = x / W, t = 1 - y / H of the source position. The
    undistort map sends each pixel of the ideal image to where the lens images
    its ray; the distort map back: composed, the identity."""
    und, dis = tmp_path / "undistort.exr", tmp_path / "distort.exr"
    fit = json.loads(cli("lens", "calibrate", "wide-22mm", "--res", f"{RES[0]}x{RES[1]}", "--focus", "2",
                         "--stmap-undistort", und, "--stmap-distort", dis, "--json").stdout)
    u = cv2.imread(str(und), cv2.IMREAD_UNCHANGED)[:, :, ::-1]  # BGRA -> ARGB: u[..., 1] is R
    d = cv2.imread(str(dis), cv2.IMREAD_UNCHANGED)[:, :, ::-1]
    assert u.shape == (RES[1], RES[0], 4)
    # Pixel (100, 50) of the ideal image: its ray through the lens.
    x, y = 100, 50
    n = np.array([(x - fit["cx"]) / fit["fx"], (y - fit["cy"]) / fit["fy"]])
    lens = lensrt.Lens("wide-22mm")
    p = lens.project([[2 * n[0], -2 * n[1], -2.0]], None, res=RES, focus=2)
    s, t = u[y, x, 1], u[y, x, 2]
    assert u[y, x, 0] == 1  # alpha
    assert (s * RES[0], (1 - t) * RES[1]) == pytest.approx(tuple(p.pixels[0]), abs=2e-3)  # float32
    # distort(undistort(q)) = q where both exist, in the frame's interior.
    for x, y in [(320, 180), (40, 30), (600, 330)]:
        sx, sy = u[y, x, 1] * RES[0], (1 - u[y, x, 2]) * RES[1]
        i, j = int(sx), int(sy)  # the pixel of the lens image holding that position
        bx, by = d[j, i, 1] * RES[0], (1 - d[j, i, 2]) * RES[1]
        # The distort map holds pixel centres; the source lay within that pixel.
        assert abs(bx - (x + 0.5)) < 1.0 and abs(by - (y + 0.5)) < 1.0
