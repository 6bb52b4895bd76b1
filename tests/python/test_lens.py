"""lensrt.Lens against `lensrt lens info --json` and closed-form optics."""

import math

import numpy as np
import pytest

import lensrt


def test_info_is_lens_info_json(cli_json):
    lens = lensrt.Lens("dgauss-50mm")
    assert lens.info() == cli_json("lens", "info", "dgauss-50mm", "--json")
    assert lens.info(fstop=4, focus=2.5, sensor=(23.6, 15.6), coatings="multi") == cli_json(
        "lens", "info", "dgauss-50mm", "--json", "--fstop", "4", "--focus", "2.5", "--sensor", "23.6x15.6",
        "--coatings", "multi")


def test_ghosts_are_lens_ghosts_json(cli_json):
    lens = lensrt.Lens("dgauss-50mm")
    assert lens.ghosts() == cli_json("lens", "ghosts", "dgauss-50mm", "--json")
    single = lens.ghosts(coatings="single")
    assert single == cli_json("lens", "ghosts", "dgauss-50mm", "--coatings", "single", "--json")
    assert len(single["ghosts"]) == 45
    # A quarter-wave of MgF2 cuts every glass-air pair's strength by an order of magnitude or more.
    assert single["ghosts"][0]["strength"] < lens.ghosts()["ghosts"][0]["strength"] / 10


def test_surfaces_list_the_prescription():
    surfaces = lensrt.Lens("dgauss-50mm").surfaces
    assert len(surfaces) == 11
    assert sum(s["stop"] for s in surfaces) == 1
    assert surfaces[0]["radius_mm"] == pytest.approx(29.475)
    # z of each vertex is the sum of the thicknesses before it.
    assert surfaces[3]["z_mm"] == pytest.approx(sum(s["thickness_mm"] for s in surfaces[:3]))


def test_focus_matches_the_film_distance_of_lens_info(cli_json):
    lens = lensrt.Lens("dgauss-50mm")
    for focus in ("inf", 2.0, 0.7):
        expected = cli_json("lens", "info", "dgauss-50mm", "--json", "--focus", str(focus))["film_distance_mm"]
        assert lens.focus(focus) == pytest.approx(expected, rel=1e-12)
    assert lens.focus(math.inf) == lens.focus("inf")


def test_trace_from_the_focal_point_leaves_parallel():
    # A ray from the rear focal point (film at the back focal distance behind
    # the rear vertex) leaves the lens parallel to the axis: near the axis,
    # the paraxial limit, whatever the lens's aberrations.
    lens = lensrt.Lens("dgauss-50mm")
    rear = lens.surfaces[-1]["z_mm"]
    bfl = lens.info()["bfl_mm"]
    n = 200
    angles = np.linspace(-1e-4, 1e-4, n)
    origins = np.tile([0.0, 0.0, rear + bfl], (n, 1))
    directions = np.stack([np.sin(angles), np.zeros(n), -np.cos(angles)], axis=1)
    out = lens.trace(origins, directions)
    assert out.passed.all()
    assert np.abs(out.directions[:, 0]).max() < 1e-6
    assert np.allclose(np.linalg.norm(out.directions, axis=1), 1.0)
    assert (out.weights == 1.0).all()  # no coatings: lossless glass
    # The height in front scales with the angle: h = f tan(u) (f = EFL).
    efl = lens.info()["efl_mm"]
    assert out.points[-1, 0] / math.tan(angles[-1]) == pytest.approx(efl, rel=1e-3)


def test_trace_blocks_rays_outside_the_aperture_and_weighs_coatings():
    lens = lensrt.Lens("dgauss-50mm")
    rear = lens.surfaces[-1]["z_mm"]
    origins = np.array([[0.0, 0.0, rear + 36.0], [30.0, 0.0, rear + 36.0]])
    directions = np.array([[0.0, 0.0, -1.0], [0.0, 0.0, -1.0]])
    out = lens.trace(origins, directions, coatings="none")
    assert out.passed.tolist() == [True, False]
    assert out.points[1].tolist() == [0.0, 0.0, 0.0] and out.weights[1] == 0.0
    # Along the axis every surface is met at normal incidence, where bare
    # glass transmits 1 - ((n1 - n2) / (n1 + n2))^2 (Fresnel).
    expected, n1 = 1.0, 1.0
    for s in lens.surfaces:
        n2 = s["n_d"]
        expected *= 1 - ((n1 - n2) / (n1 + n2)) ** 2
        n1 = n2
    assert out.weights[0] == pytest.approx(expected, rel=1e-9)


def test_trace_at_other_wavelengths_disperses():
    lens = lensrt.Lens("petzval-100mm")
    rear = lens.surfaces[-1]["z_mm"]
    origin = np.array([[0.0, 0.0, rear + lens.focus("inf")]])
    tilted = np.array([[0.02, 0.0, -1.0]])
    red = lens.trace(origin, tilted, wavelength_nm=656.27)
    blue = lens.trace(origin, tilted, wavelength_nm=486.13)
    d = lens.trace(origin, tilted)
    assert red.passed[0] and blue.passed[0]
    assert red.directions[0, 0] != blue.directions[0, 0]
    # The d line is the default and the batched trace's.
    assert (d.directions == lens.trace(origin, tilted, wavelength_nm=587.5618).directions).all()
    with pytest.raises(ValueError, match="wavelength_nm: expected 300 to 1000 nm"):
        lens.trace(origin, tilted, wavelength_nm=100)


def test_relative_illumination_and_distortion_start_at_the_axis():
    lens = lensrt.Lens("dgauss-50mm")
    radius, relative = lens.relative_illumination(fstop=2.8, points=9)
    assert radius[0] == 0.0 and radius[-1] == pytest.approx(math.hypot(36, 24) / 2)
    assert relative[0] == 1.0 and 0.0 < relative[-1] < 1.0
    angle, percent = lens.distortion(points=9)
    assert angle[0] == 0.0 and percent[0] == 0.0
    assert len(angle) == len(percent) == 9
    spot = lens.spot(field_deg=0.0, fstop=8, rays=21)
    assert spot.shape[1] == 2 and len(spot) > 200
    # Stopped down to f/8 the on-axis spot of this lens is tiny (< 10 um RMS).
    assert np.sqrt((spot**2).sum(axis=1).mean()) < 0.01


@pytest.mark.parametrize(
    "call, error",
    [
        (lambda l: l.trace(np.zeros((3, 2)), np.zeros((3, 2))), "origins: expected an N x 3 array"),
        (lambda l: l.trace(np.full((1, 3), np.nan), np.array([[0, 0, -1.0]])), "origins: row 0 holds a NaN"),
        (lambda l: l.trace(np.zeros((2, 3)), np.array([[0, 0, -1.0]])), "directions: expected a 2 x 3 array"),
        (lambda l: l.trace(np.zeros((1, 3)), np.array([[0, 0, 1.0]])), "directions: row 0 does not point"),
        (lambda l: l.trace("abc", np.zeros((1, 3))), "origins: expected an N x 3 array"),
        (lambda l: l.info(fstop=-2), "fstop: must be a positive f-number"),
        (lambda l: l.info(fstop="f/2"), "fstop: expected a number, got str 'f/2'"),
        (lambda l: l.focus(0.01), "dgauss-50mm: "),
        (lambda l: l.focus(-1), "distance_m: expected a distance in metres > 0"),
        (lambda l: l.info(sensor="big"), "sensor: expected WIDTHxHEIGHT in mm"),
        (lambda l: l.trace(np.zeros((1, 3)), np.array([[0, 0, -1.0]]), coatings="gold"), "coatings: expected"),
    ],
)
def test_bad_input_raises_value_error(call, error):
    with pytest.raises(ValueError, match=None) as raised:
        call(lensrt.Lens("dgauss-50mm"))
    assert error in str(raised.value)


def test_missing_lens_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError, match="no-such-lens"):
        lensrt.Lens("no-such-lens")
    broken = tmp_path / "broken.lens"
    broken.write_text("# radius thickness\n50 abc\n")
    with pytest.raises(ValueError, match="broken.lens"):
        lensrt.Lens(broken)


def test_psf_and_mtf_are_lens_psf_and_mtf(cli_json):
    lens = lensrt.Lens("dgauss-50mm")
    psf = lens.psf(fstop=8, wavelengths_nm=[550.0])
    summary = cli_json("lens", "psf", "dgauss-50mm", "--json", "--fstop", "8", "--wavelengths", "550")
    assert psf["summary"] == summary
    size = summary["sampling"]["fft_size"]
    assert psf["psf"].shape == (size, size) and psf["limit"].shape == (size, size)
    # Fractions of the light, the peak at the chief ray's image on the axis.
    assert 0.98 < psf["psf"].sum() <= 1.0
    assert np.unravel_index(psf["limit"].argmax(), psf["limit"].shape) == (size // 2, size // 2)
    assert math.isclose(psf["psf"].max() / psf["limit"].max(), summary["strehl"], rel_tol=1e-12)
    mtf = lens.mtf(fstop=8, wavelengths_nm=[550.0], points=11)
    cli = cli_json("lens", "mtf", "dgauss-50mm", "--json", "--fstop", "8", "--wavelengths", "550")
    assert mtf["frequency_per_mm"].shape == (11,) and mtf["tangential"][0] == 1.0
    assert mtf["frequency_per_mm"][-1] == pytest.approx(cli["mtf"]["frequency_per_mm"][-1])
    assert mtf["tangential"][-1] == pytest.approx(cli["mtf"]["tangential"][-1])
    assert list(mtf["through_focus"]["tangential"]) == pytest.approx(cli["through_focus"]["tangential"])


def test_psf_refuses_a_field_beyond_the_coverage():
    with pytest.raises(ValueError, match="coverage"):
        lensrt.Lens("dgauss-50mm").psf(field_deg=60)
