"""The sensor's readout (--noise on) checked by a photon transfer curve of
rendered flat fields, as a sensor is characterised on the bench (EMVA 1288):
pairs of frames at 12 exposures, temporal variance from their difference (the
fixed patterns cancel), electrons from lensrt:sensor_electrons_per_value."""

import json
import warnings

import numpy as np
import pytest

import lensrt
from conftest import SCENES

# 4 um pixels (64 x 43 of them) behind a thin lens, on the uniformly
# emitting flat wall; the sensor's gain is 1 DN/e so that quantisation adds
# only 1/12 e^2 to the read noise's variance.
SENSOR = {
    "name": "ptc",
    "full_well_e": 20000,
    "gain_dn_per_e": 1.0,
    "base_iso": 100,
    "read_noise_e": 3.0,
    "dark_current_e_per_s": 0.0,
    "prnu_percent": 1.0,
    "dsnu_percent": 0.0,
    "adc_bits": 16,
    "black_level_dn": 100,
    "quantum_efficiency": 0.5,
}
SHUTTERS = [0.0, 1e-4, 2e-4, 4e-4, 8e-4, 1.6e-3, 3.2e-3, 6.4e-3, 0.0128, 0.0256, 0.05, 0.1]


@pytest.fixture(scope="module")
def wall():
    return lensrt.Scene(SCENES / "flat_wall.gltf")


def frame(wall, sensor_file, shutter, seed, iso=100, **extra):
    r = wall.render(camera="thin", focal_length=50, fstop=4, sensor=(0.256, 0.172), res=(64, 43), spp=4,
                    exposure="physical", shutter=max(shutter, 1e-12), iso=iso, noise=True,
                    sensor_params=sensor_file, seed=seed, env="none", **extra)
    per_value = float(r.metadata["lensrt:sensor_electrons_per_value"])
    return r.channels["G"] * per_value, r.channels["noiseless.G"] * per_value


@pytest.fixture(scope="module")
def ptc(wall, tmp_path_factory):
    path = tmp_path_factory.mktemp("sensor") / "ptc.json"
    path.write_text(json.dumps(SENSOR))
    points = []
    for t in SHUTTERS:
        a, clean_a = frame(wall, path, t, seed=1)
        b, clean_b = frame(wall, path, t, seed=2)
        # Temporal noise of each frame about its own noiseless signal; the
        # difference of the two frames removes the PRNU's fixed pattern.
        da, db = a - clean_a, b - clean_b
        # The last column: the frames' own difference, which at full well is
        # 0 (each noiseless frame has the render's colour noise, the reading
        # none once clipped).
        points.append((clean_a.mean(), a.mean(), np.var(da - db) / 2, np.var(a - b) / 2))
    return np.array(points), path


def test_shot_noise_has_slope_one(ptc):
    points, _ = ptc
    mean, var = points[:, 0], points[:, 2]
    shot = (mean > 20 * SENSOR["read_noise_e"] ** 2) & (mean < 0.5 * SENSOR["full_well_e"])
    assert shot.sum() >= 5
    slope = np.polyfit(mean[shot], var[shot], 1)[0]
    assert slope == pytest.approx(1.0, rel=0.05)


def test_floor_is_the_read_noise(ptc):
    points, _ = ptc
    floor = np.sqrt(points[0, 2] - 1 / 12)  # less the quantisation of 1 DN = 1 e
    assert points[0, 0] < 1e-3
    assert floor == pytest.approx(SENSOR["read_noise_e"], rel=0.05)


def test_mean_saturates_at_full_well(ptc):
    points, _ = ptc
    assert points[-1, 0] > 2 * SENSOR["full_well_e"]  # the light would give more
    assert points[-1, 1] == pytest.approx(SENSOR["full_well_e"], rel=1e-3)
    assert points[-1, 3] < 1.0  # clipped: no noise left


def test_doubling_the_iso_halves_the_electrons_per_dn(wall, ptc):
    _, path = ptc

    def electrons_per_dn(iso):
        reading, _ = frame(wall, path, 1e-3, seed=3, iso=iso)
        levels = np.unique(np.round(reading.ravel(), 6))
        return np.diff(levels).min()  # one DN apart

    at100, at200 = electrons_per_dn(100), electrons_per_dn(200)
    assert at100 == pytest.approx(1.0, rel=1e-3)  # 1 DN/e at the base ISO
    assert at200 == pytest.approx(at100 / 2, rel=1e-3)


def test_the_readout_is_deterministic_and_the_same_for_a_crop(wall, ptc):
    _, path = ptc
    whole, _ = frame(wall, path, 1e-3, seed=4)
    again, _ = frame(wall, path, 1e-3, seed=4)
    part, _ = frame(wall, path, 1e-3, seed=4, crop=(10, 30, 5, 20))
    assert (whole == again).all()
    assert (part == whole[5:20, 10:30]).all()
    other, _ = frame(wall, path, 1e-3, seed=5)
    assert (other != whole).mean() > 0.9


def test_bad_sensor_files(wall, tmp_path):
    def render(params):
        return wall.render(res=(8, 8), spp=1, noise="on", sensor_params=params)

    missing = dict(SENSOR)
    del missing["read_noise_e"]
    (tmp_path / "missing.json").write_text(json.dumps(missing))
    with pytest.raises(ValueError, match='missing.json: missing field "read_noise_e"'):
        render(tmp_path / "missing.json")
    (tmp_path / "bits.json").write_text(json.dumps(dict(SENSOR, adc_bits=20)))
    with pytest.raises(ValueError, match='field "adc_bits" must be an integer from 1 to 16'):
        render(tmp_path / "bits.json")
    with pytest.raises(ValueError, match="unknown sensor 'nikon' \\(presets: default, full-frame"):
        render("nikon")
    with pytest.raises(FileNotFoundError, match="nowhere.json: no such sensor file"):
        render(tmp_path / "nowhere.json")
    with pytest.raises(ValueError, match="sensor_params: describes the sensor's noise, which needs noise='on'"):
        wall.render(res=(8, 8), spp=1, sensor_params="default")


def test_clipping_most_pixels_is_a_python_warning(wall):
    """As the command line's warning line (tests/cli/sensor_noise_cli_test.cpp):
    400 um pixels (90 x 60 on 36 x 24 mm) collect 2.55e8 electrons at an image
    value of 1 and every pixel of the wall clips; 4 um pixels at 1/500 s hold
    its brightest 0.55 in 14000 e and nothing is said. The way out names the
    keywords, not the flags."""
    def render(**extra):
        return wall.render(res=(90, 60), spp=1, film="irradiance", exposure="physical", noise=True, **extra)

    with pytest.warns(UserWarning) as said:
        render()
    clipping = [str(w.message) for w in said if "of the pixels clip" in str(w.message)]
    assert len(clipping) == 1, clipping
    assert clipping[0].startswith(str(SCENES / "flat_wall.gltf") + ": 100% of the pixels clip")
    assert "its 400 um pixels" in clipping[0]
    assert "(a smaller sensor, or more of them with res) or a lower exposure (iso, shutter, fstop)" in clipping[0]
    assert "--" not in clipping[0]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        render(sensor=(0.36, 0.24), shutter=1 / 500)
