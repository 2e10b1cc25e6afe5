"""An image-array round trip: a small synthetic chart image rendered here, in Python, from the
shipped spectral data (Munsell chips, CIE illuminants, the paper's narrow-band sensors at 610,
540 and 450 nm), with a masked-out border and a saturated patch; gmcc estimates its light and is
compared with the light it was rendered under. The pixel route must also give exactly the
feasible set of the chart's colours given as a list (two routes into one computation)."""

import csv
import random
from fractions import Fraction

import numpy as np
import pytest

import gmcc
from conftest import DATA

BANDS = ("610", "540", "450")


def table(name):
    with open(DATA / name) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], {r[0]: r[1:] for r in rows[1:]}
    return header[1:], body


@pytest.fixture(scope="module")
def spectra():
    chips, munsell = table("munsell_matt_1269_joensuu_5nm.csv")
    lights, illum = table("cie_illuminants_A_D50_D55_D65_D75.csv")
    reflect = [[Fraction(munsell[b][i]) for b in BANDS] for i in range(len(chips))]
    light = {name: [Fraction(illum[b][j]) for b in BANDS] for j, name in enumerate(lights)}
    return reflect, light


def render(reflect, light):
    return [[r * e for r, e in zip(chip, light)] for chip in reflect]


def chart(colours, cell=6, cols=6):
    """A chart image: one cell of cell×cell pixels per colour, a 2-pixel border of other colours
    (to be masked out), float64 samples."""
    rows = (len(colours) + cols - 1) // cols
    h, w = rows * cell + 4, cols * cell + 4
    img = np.empty((h, w, 3))
    img[:] = [0.9, 0.05, 0.01]  # a reddish border, far outside any plausible scene
    mask = np.zeros((h, w), bool)
    for k, c in enumerate(colours):
        y, x = 2 + (k // cols) * cell, 2 + (k % cols) * cell
        img[y:y + cell, x:x + cell] = [float(v) for v in c]
        mask[y:y + cell, x:x + cell] = True
    return img, mask


@pytest.mark.parametrize("test_light,seed", [("A", 1), ("D75", 2), ("D65", 3)])
def test_chart_image_estimates_its_light(spectra, test_light, seed):
    reflect, light = spectra
    canonical_light, e = light["D55"], light[test_light]
    prepared = gmcc.prepare_canonical(render(reflect, canonical_light), canonical_illuminant=canonical_light)
    chips = random.Random(seed).sample(range(len(reflect)), 24)
    colours = render([reflect[i] for i in chips], e)
    img, mask = chart(colours)

    r = gmcc.select(prepared, img, truth=e, mask=mask)
    assert r.pixels["masked"] == int((~mask).sum()) and r.pixels["kept"] == int(mask.sum())
    # The pixel route and the colour route agree exactly on the same doubles.
    listed = gmcc.select(prepared, [[float(v) for v in c] for c in colours], truth=e)
    assert r.feasible_set == listed.feasible_set
    assert r.mean_3d.map == listed.mean_3d.map
    # The known light: its map (c ⊘ e, exact) is where the chart puts it. Rounding the rendered
    # colours to doubles moves F by about 1e-16, so the true map is inside or within that of it.
    # (These seeds draw no chip on the canonical hull, so the true map is strictly inside F.)
    true_map = gmcc.illuminant_map(e, canonical_light)
    assert r.truth.map == true_map
    assert r.kind == "polygon" and r.truth.in_feasible_set and r.feasible_set.contains(true_map)
    # Every estimate is within its worst case of the true map (the truth lies in F), and the 3-D
    # mean, the paper's best rule, is close to it.
    for rule in ("max_area", "mean_2d", "mean_3d"):
        assert getattr(r.truth, rule).map_error_deg <= getattr(r, rule).worst_case_deg + 1e-9, rule
    assert r.truth.mean_3d.map_error_deg < 10
    # The unmasked border is not a colour of this scene: it changes (here empties) F.
    assert gmcc.select(prepared, img).feasible_set != r.feasible_set


def test_integer_image_with_black_level_and_saturation(spectra):
    """A 16-bit image: colours scaled, rounded, a black level added and a saturated patch; the
    pixel rules (mask, saturation, black level) must give exactly the list of those rounded
    colours, and the estimate must stay close to the light."""
    reflect, light = spectra
    canonical_light, e = light["D55"], light["A"]
    prepared = gmcc.prepare_canonical(render(reflect, canonical_light), canonical_illuminant=canonical_light)
    chips = random.Random(9).sample(range(len(reflect)), 24)
    colours = render([reflect[i] for i in chips], e)
    top = max(max(c) for c in colours)
    black = 256
    codes = [[int(round(float(v / top) * 50000)) for v in c] for c in colours]
    img, mask = chart([[x + black for x in c] for c in codes])
    img = img.astype(np.uint16)  # border: [0, 0, 0] after the cast: masked anyway
    img[2:5, 2:5] = [65535, 65535, 400]  # clipped pixels inside the first cell, far off in chromaticity
    r = gmcc.select(prepared, img, truth=e, mask=mask, black_level=black, saturation=65535)
    assert r.pixels["saturated"] == 9
    listed = gmcc.select(prepared, codes, truth=e)
    assert r.feasible_set == listed.feasible_set
    assert r.mean_3d.map == listed.mean_3d.map
    # Rounding to 16-bit codes moves the colours by up to 1e-5 relative: the light is still
    # found within the 3-D mean's worst case and near it.
    assert r.truth.mean_3d.map_error_deg <= r.mean_3d.worst_case_deg
    assert r.truth.mean_3d.map_error_deg < 15
    # Without the saturation rule the clipped pixels are colours, and F changes.
    assert gmcc.select(prepared, img, mask=mask, black_level=black).feasible_set != r.feasible_set
    # Without the black level the colours are others, and F changes.
    assert gmcc.select(prepared, img, mask=mask, saturation=65535).feasible_set != r.feasible_set
    # Non-contiguous and other integer dtypes: the same pixels, the same F.
    assert gmcc.select(prepared, np.asfortranarray(img.astype(np.int32)), mask=mask, black_level=black,
                       saturation=65535).feasible_set == r.feasible_set
