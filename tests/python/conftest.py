"""Shared helpers of the Python module's tests (run by ctest: tests/CMakeLists.txt sets
PYTHONPATH to the build tree's package, GMCC_CLI to the gmcc executable and GMCC_DATA_DIR)."""

import json
import os
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import settings

import gmcc

# Property tests are reproducible (the same examples every run: derandomized) and leave no
# example database behind in the working directory.
settings.register_profile("gmcc", derandomize=True, database=None)
settings.load_profile("gmcc")

REPO = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("GMCC_DATA_DIR", REPO / "data"))
SAMPLES = REPO / "data" / "samples"


def read_colours(path):
    """Rows r,g,b of a gmcc colour file, as text (read exactly by gmcc)."""
    rows = []
    for line in Path(path).read_text().splitlines():
        line = line.strip()
        if not line or line.startswith("#") or line.startswith("r,"):
            continue
        rows.append(line.split(","))
    return rows


def write_colours(path, rows):
    """Rows of exact numbers (Fraction, int, str) as a colour file gmcc reads exactly."""
    with open(path, "w") as f:
        for row in rows:
            f.write(",".join(str(Fraction(x)) if not isinstance(x, str) else x for x in row) + "\n")


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("GMCC_CLI")
    if not exe:
        pytest.skip("GMCC_CLI not set (ctest sets it to the gmcc executable)")

    def run(*args):
        p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        return json.loads(p.stdout) if "--json" in args else p.stdout

    run.exe = exe
    return run


@pytest.fixture(scope="session")
def sample():
    """The shipped worked example: 1269 Munsell chips under D55, 8 under D75 (exact text)."""
    return read_colours(SAMPLES / "canonical_munsell_D55.csv"), read_colours(SAMPLES / "image_munsell_D75.csv")


def fractions_of(pairs):
    return [[str(x) for x in p] for p in pairs]
