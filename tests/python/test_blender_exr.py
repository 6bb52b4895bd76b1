"""Blender 3.4 (Debian's) reads lensrt's EXR with AOVs as it reads its own multilayer
renders: RGBA is the Combined pass and each AOV a pass of its own, with the same numbers,
and its Cryptomatte node finds lensrt's layers and extracts the mattes that the
specification's formula gives from the file. (bpy.data.images.load reports any multilayer
EXR as 0 x 0, Blender's own included: the compositor is where its passes are read.)"""

import json
import pathlib
import os
import shutil
import subprocess

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")  # before cv2 loads

import cv2  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import lensrt  # noqa: E402
from conftest import SCENES  # noqa: E402

HERE = pathlib.Path(__file__).parent
BLENDER = shutil.which("blender")
pytestmark = pytest.mark.skipif(BLENDER is None, reason="Blender is not installed (tools/setup installs it)")
RES = (64, 48)
AOVS = "depth,z,normal,albedo,variance,crypto_object,crypto_material,object_id"


def read(path):
    """A Blender output (float RGBA EXR) as H x W x 4, R first."""
    bgra = cv2.imread(str(path), cv2.IMREAD_UNCHANGED)
    assert bgra is not None, path
    return bgra[:, :, [2, 1, 0, 3]]


def murmur3(name):
    """MurmurHash3_x86_32, seed 0, as the Cryptomatte specification hashes names."""
    data = name.encode()
    h, c1, c2 = 0, 0xCC9E2D51, 0x1B873593
    mask = 0xFFFFFFFF

    def rotl(x, r):
        return ((x << r) | (x >> (32 - r))) & mask

    for i in range(0, len(data) // 4 * 4, 4):
        k = int.from_bytes(data[i:i + 4], "little")
        k = rotl(k * c1 & mask, 15) * c2 & mask
        h = (rotl(h ^ k, 13) * 5 + 0xE6546B64) & mask
    tail = data[len(data) // 4 * 4:]
    if tail:
        k = int.from_bytes(tail, "little")
        h ^= rotl(k * c1 & mask, 15) * c2 & mask
    h ^= len(data)
    for shift, mul in ((16, 0x85EBCA6B), (13, 0xC2B2AE35), (16, None)):
        h ^= h >> shift
        if mul:
            h = h * mul & mask
    return h


def id_float(name):
    """The hash as the specification turns it into a float32 id (exponent kept in [1, 254])."""
    bits = murmur3(name)
    exponent = bits >> 23 & 0xFF
    if exponent in (0, 255):
        bits ^= 1 << 23
    return np.frombuffer(np.uint32(bits).tobytes(), np.float32)[0]


def matte(channels, layer, name):
    """The specification's matte: the coverages of every rank whose id is the name's."""
    want = id_float(name)
    total = np.zeros(channels["A"].shape, np.float32)
    for rank in ("00", "01", "02"):
        for i, c in (("R", "G"), ("B", "A")):
            total += np.where(channels[f"{layer}{rank}.{i}"] == want, channels[f"{layer}{rank}.{c}"], 0)
    return total


def test_blender_reads_rgba_as_combined_and_each_aov_as_a_pass(tmp_path):
    result = lensrt.Scene(SCENES / "cornell.gltf").render(res=RES, spp=16, aov=AOVS.split(","))
    exr = tmp_path / "ids.exr"
    result.write(exr)
    ch = result.channels
    mattes = ["CryptoObject:tall_block", "CryptoMaterial:red"]
    done = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "-noaudio", "--python", HERE / "blender_read_exr.py", "--", exr, tmp_path,
         *mattes], capture_output=True, text=True, timeout=240,
        env={**os.environ, "LENSRT_EXR_SIZE": f"{RES[0]}x{RES[1]}"})
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    assert "unknown channel token" not in done.stdout and "bad channel name" not in done.stdout, done.stdout
    found = json.loads((tmp_path / "passes.json").read_text())
    assert found["type"] == "MULTILAYER"
    # The passes in Blender's names: R, G, B, A are Combined (and Alpha), Z is Depth.
    expected = {"Combined": ["R", "G", "B", "A"], "Depth": ["Z"], "depth": ["depth.Z"],
                "normal": ["normal.X", "normal.Y", "normal.Z"], "albedo": ["albedo.R", "albedo.G", "albedo.B"],
                "variance": ["variance.R", "variance.G", "variance.B"], "object_id": ["object_id.X"]}
    for rank in ("00", "01", "02"):
        for layer in ("CryptoObject", "CryptoMaterial"):
            expected[layer + rank] = [f"{layer}{rank}.{c}" for c in "RGBA"]
    assert set(expected) <= set(found["passes"]), found["passes"]
    for name, channels in expected.items():
        got = read(tmp_path / f"{name}.exr")
        for k, channel in enumerate(channels):
            np.testing.assert_array_equal(got[:, :, k], ch[channel], err_msg=f"{name} {channel}")
    # The Cryptomatte node: lensrt's layers, read by their header, give the specification's mattes.
    for i, spec in enumerate(mattes):
        layer, name = spec.split(":")
        want = matte(ch, layer, name)
        assert want.max() > 0.99 and (want > 0).sum() > 20, spec  # the object is in the frame
        np.testing.assert_allclose(read(tmp_path / f"matte_{i}.exr")[:, :, 0], want, atol=1e-6, err_msg=spec)
