"""gmcc.read_image on a real camera raw file (data/raw/colorchart.dng, a Canon 550D's 14-bit DNG;
data/SOURCES.md) against an independent decode of its TIFF tags in Python (scripts/verify-datasets'
decode_dng): every quad's pixel is 2·(R − 2056, (G₁ − 2056) + (G₂ − 2056), 2·(B − 2056)) of the
photosites decoded here, bit for bit, with the pattern, levels and camera the tags give."""

import importlib.machinery
import importlib.util
import os

import numpy as np

import gmcc

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def verify_script():
    path = os.path.join(ROOT, "scripts", "verify-datasets")
    loader = importlib.machinery.SourceFileLoader("verify_datasets", path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader("verify_datasets", loader))
    loader.exec_module(module)
    return module


def test_real_dng_quads_equal_an_independent_decode():
    path = os.path.join(ROOT, "data", "raw", "colorchart.dng")
    decoded = verify_script().decode_dng(open(path, "rb").read())
    assert decoded["pattern"] == "RGGB" and decoded["black"] == [2056] and decoded["white"] == 15000
    m = decoded["mosaic"]
    h, w = m.shape[0] // 2, m.shape[1] // 2
    q = np.maximum(m[:2 * h, :2 * w] - 2056, 0).reshape(h, 2, w, 2)
    want = np.stack([2 * q[:, 0, :, 0], q[:, 0, :, 1] + q[:, 1, :, 0], 2 * q[:, 1, :, 1]], axis=2)
    saturated = (m[:2 * h, :2 * w].reshape(h, 2, w, 2) >= 15000).any(axis=(1, 3))
    want[saturated] = 65535
    image, rules, info = gmcc.read_image(path)
    assert image.shape == (578, 867, 3) and np.array_equal(image.astype(np.int64), want)
    assert rules == {"black_level": 0, "saturation": 65535}
    raw = info["raw"]
    assert raw["pattern"] == "RGGB" and raw["black"] == [2056] * 4 and raw["white"] == 15000
    assert raw["camera"] == "Canon EOS Kiss X4" and raw["saturated"] == int(saturated.sum())
