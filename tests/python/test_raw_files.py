"""gmcc.read_image on camera raw files (docs/conventions.md §8 "Camera raw files"): a DNG the
test writes (tests/support/dng.py), whose every photosite it knows, read as 2·(r, g, b) per quad
after each photosite's black level; the rules it returns make estimate_3d answer as for the same
pixels in a PNG; given levels replace the file's; unreadable files raise ValueError naming the file."""

import os
import random
import sys

import numpy as np
import pytest

import gmcc

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "support"))
from dng import write_dng  # noqa: E402
from png16 import write_png16  # noqa: E402


def scene(rng, w=16, h=12):
    surfaces = [(rng.randint(20, 900), rng.randint(20, 900), rng.randint(20, 900)) for _ in range(10)]
    light = (5, 3, 7)
    quads = [[tuple(surfaces[(2 * x + y) % 10][k] * light[k] for k in range(3)) for x in range(w)] for y in range(h)]
    return surfaces, light, quads


def mosaic(quads, pattern, blacks, rng):
    rows = [[0] * (2 * len(quads[0])) for _ in range(2 * len(quads))]
    for y, row in enumerate(quads):
        for x, (r, g, b) in enumerate(row):
            d = rng.randint(-3, 3)
            greens = [g + d, g - d]
            for p, c in enumerate(pattern):
                v = r if c == "R" else b if c == "B" else greens.pop()
                rows[2 * y + p // 2][2 * x + p % 2] = v + blacks[p]
    return rows


@pytest.mark.parametrize("pattern", ["RGGB", "BGGR", "GRBG", "GBRG"])
def test_dng_quads_are_twice_the_png_pixels(tmp_path, pattern):
    rng = random.Random(pattern)
    surfaces, light, quads = scene(rng)
    blacks = [rng.randint(50, 80) for _ in range(4)]
    write_dng(tmp_path / "a.dng", mosaic(quads, pattern, blacks, rng), pattern=pattern,
              black_per_channel=blacks, white=16383)
    write_png16(tmp_path / "a.png", quads)
    img, rules, info = gmcc.read_image(tmp_path / "a.dng")
    png, png_rules, png_info = gmcc.read_image(str(tmp_path / "a.png"))
    assert img.dtype == np.uint16 and img.shape == png.shape == (12, 16, 3)
    assert (img.astype(np.int64) == 2 * png.astype(np.int64)).all()
    assert rules == {"black_level": 0, "saturation": 65535} and png_rules == {"black_level": 0, "saturation": None}
    assert info["raw"]["pattern"] == pattern and info["raw"]["white"] == 16383
    assert (info["raw"]["black_min"], info["raw"]["black_max"]) == (min(blacks), max(blacks))
    assert png_info == {"bits": 16, "raw": None}
    # The same light from both, and the true one (every surface seen: F3 is a segment).
    canonical = gmcc.prepare_canonical_3d(surfaces)
    a = gmcc.estimate_3d(canonical, img, **rules)
    b = gmcc.estimate_3d(canonical, png, **png_rules)
    for rule in ("max_volume", "centroid", "max_trace"):
        la, lb = np.array(getattr(a, rule).light, float), np.array(getattr(b, rule).light, float)
        assert np.allclose(la / np.linalg.norm(la), lb / np.linalg.norm(lb), atol=1e-12)
        assert np.allclose(la / np.linalg.norm(la), np.array(light) / np.linalg.norm(light), atol=1e-9)


def test_given_levels_replace_the_files(tmp_path):
    rng = random.Random(5)
    _, _, quads = scene(rng)
    # Metadata: black 0, white 60000 (refused: sums could reach 65535); truth: 100 and 16383.
    write_dng(tmp_path / "w.dng", mosaic(quads, "RGGB", [100] * 4, rng), black=0, white=60000)
    with pytest.raises(ValueError, match=r"w\.dng.*white level 60000 above 32768"):
        gmcc.read_image(tmp_path / "w.dng")
    img, rules, info = gmcc.read_image(tmp_path / "w.dng", black_level=100, saturation=16383)
    assert (img.astype(np.int64) == 2 * np.array(quads, dtype=np.int64)).all()
    assert info["raw"]["black_min"] == 100 and info["raw"]["white"] == 16383


def test_unreadable_files_name_themselves(tmp_path):
    (tmp_path / "x.nef").write_bytes(b"not a raw file at all\n")
    with pytest.raises(ValueError, match=r"x\.nef.*LibRaw"):
        gmcc.read_image(tmp_path / "x.nef")
    with pytest.raises(ValueError, match="missing.png"):
        gmcc.read_image(tmp_path / "missing.png")
