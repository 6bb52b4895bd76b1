"""Shared fixtures of the Python module's tests (run by ctest: tests/CMakeLists.txt
sets PYTHONPATH to build/python and LENSRT_CLI to the lensrt command)."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


@pytest.fixture(scope="session")
def cli():
    """Runs the lensrt command; returns its CompletedProcess."""
    exe = os.environ.get("LENSRT_CLI", str(ROOT / "build" / "src" / "app" / "lensrt"))

    def run(*args, check=True):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"lensrt {' '.join(map(str, args))}: {done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    return lambda *args: json.loads(cli(*args).stdout)
