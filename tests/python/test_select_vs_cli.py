"""gmcc.select against `gmcc select --json` on the same exact input: two front ends of one
pipeline, compared field by field (exact vertices and maps as text, doubles bit for bit), on the
shipped sample, every option family, and seeded scenes of every kind (polygon, segment, point,
empty)."""

import random
from fractions import Fraction

import numpy as np
import pytest

import gmcc
from conftest import SAMPLES, write_colours

RULES = ("max_area", "mean_2d", "mean_3d")


def check_convex_set(ours, theirs):
    assert ours.kind == theirs["kind"]
    assert [[str(x), str(y)] for x, y in ours.vertices] == theirs["vertices"]
    assert str(ours.area) == theirs["area"]
    assert ours.vertices_float.tolist() == (theirs["vertices_approx"] or [])


def check_scene(r, j):
    check_convex_set(r.feasible_set, j["feasible_set"])
    check_convex_set(r.canonical_gamut, j["canonical_gamut"])
    assert r.image_colours == j["input"]["image_colours"]
    assert r.image_dropped == j["input"]["image_dropped_nonpositive_blue"]
    sel = j.get("selections") or {}
    for rule in RULES:
        ours, theirs = getattr(r, rule), sel.get(rule)
        if theirs is None:
            assert ours is None
            continue
        assert ours.method == theirs["method"]
        if theirs["map"] is None:
            assert not ours.valid and ours.map is None
            continue
        assert list(ours.map) == theirs["map"]
        assert ours.error_bound == theirs["error_bound"]
        assert list(ours.error_bounds) == theirs["error_bounds"]
        assert list(ours.correctly_rounded) == theirs["correctly_rounded"]
        if "map_exact" in theirs:
            assert [str(x) for x in ours.exact] == theirs["map_exact"]
            assert ours.exact[0] == Fraction(theirs["map_exact"][0])
        else:
            assert ours.exact is None
        if "enclosure" in theirs:
            assert ours.enclosure.tolist() == theirs["enclosure"]
        assert ours.worst_case_deg == theirs.get("worst_case_deg")
        assert ours.worst_case_illuminant_deg == theirs.get("worst_case_illuminant_deg")
    if "truth" in j:
        t = j["truth"]
        assert [str(x) for x in r.truth.map] == t["map_exact"]
        assert r.truth.in_feasible_set == t["in_feasible_set"]
        for rule in RULES:
            ours, theirs = getattr(r.truth, rule), t.get("errors", {}).get(rule)
            if theirs is None:
                assert ours is None
                continue
            assert ours.map_error_deg == theirs["map_error_deg"]
            assert ours.illuminant_error_deg == theirs.get("illuminant_error_deg")
            assert ours.reproduction_error_deg == theirs.get("reproduction_error_deg")
    else:
        assert r.truth is None
    if "constraint" in j:
        check_convex_set(r.constraint.maps, j["constraint"])
        check_convex_set(r.constraint.unconstrained, j["constraint"]["unconstrained_feasible_set"])
    if "recovery" in j:
        rec = j["recovery"]
        assert r.recovery.policy == rec["policy"]
        assert r.recovery.applied == rec["applied"]
        if "factor" in rec:
            assert str(r.recovery.factor) == rec["factor"]
        if "violation" in rec:
            assert str(r.recovery.violation) == rec["violation"]


def run_both(cli, tmp_path, canonical, image, truth=None, cli_args=(), **options):
    write_colours(tmp_path / "c.csv", canonical)
    write_colours(tmp_path / "i.csv", image)
    args = ["select", "--canonical", tmp_path / "c.csv", "--image", tmp_path / "i.csv", "--json", *cli_args]
    if truth is not None:
        args += ["--truth", ",".join(str(Fraction(x)) for x in truth)]
    j = cli(*args)
    r = gmcc.select(canonical, image, truth, **options)
    check_scene(r, j)
    return r, j


def test_sample_all_fields(cli, tmp_path, sample):
    canonical, image = sample
    r, _ = run_both(cli, tmp_path, canonical, image, truth=("1", "1", "1"))
    assert r.kind == "polygon" and len(r.feasible_set) == 5


@pytest.mark.parametrize("options,cli_args", [
    (dict(expand="1/10", expand_policy="multiplicative"), ["--expand", "1/10", "--expand-policy", "multiplicative"]),
    (dict(expand="0.1", expand_policy="centroid-clip"), ["--expand", "0.1", "--expand-policy", "centroid-clip"]),
    (dict(mean3d="quadrature", order=8), ["--mean3d", "quadrature", "--order", "8"]),
    (dict(mean3d="monte-carlo", samples=20000, seed=7), ["--mean3d", "monte-carlo", "--samples", "20000", "--seed", "7"]),
    (dict(mean3d="analytic", precision=200), ["--precision", "200"]),
    (dict(illuminant_worst_case=False), ["--illuminant-worst-case", "off"]),
    (dict(canonical_illuminant=("0.9", "1", "1.1")), ["--canonical-illuminant", "0.9,1,1.1"]),
])
def test_sample_options(cli, tmp_path, sample, options, cli_args):
    canonical, image = sample
    run_both(cli, tmp_path, canonical, image, ("1.2", "1", "0.8"), cli_args, **options)


def test_illumination_constraint(cli, tmp_path, sample):
    canonical, image = sample
    lights = [row for row in (SAMPLES / "plausible_lights_610_540_450.csv").read_text().splitlines()
              if row and row[0].isdigit()]
    lights = [row.split(",") for row in lights]
    write_colours(tmp_path / "l.csv", lights)
    r, _ = run_both(cli, tmp_path, canonical, image, None,
                    ["--illuminants", tmp_path / "l.csv", "--canonical-illuminant", "1,1,1"],
                    illuminants=lights)
    assert r.constraint.illuminants == len(lights)


def random_colour(rng, scale=20):
    return [Fraction(rng.randint(1, scale), rng.randint(1, 5)) for _ in range(3)]


def degenerate_cases(rng):
    """(canonical, image) whose feasible set is a polygon, segment, point or empty."""
    # segment: canonical chromaticities on a line, one image colour
    a, b = Fraction(rng.randint(1, 9), 7), Fraction(rng.randint(1, 9), 5)
    seg = [[t * k, (a * t + b) * k, k] for t in (Fraction(1, 3), Fraction(2), Fraction(5, 2)) for k in (1, 3)]
    yield "segment", seg, [random_colour(rng)]
    # point: one canonical chromaticity, one image colour
    c = random_colour(rng)
    yield "point", [c, [2 * x for x in c]], [random_colour(rng)]
    # empty: image chromaticities far more spread than a narrow canonical gamut
    narrow = [[10 + i % 2, 10 + (i // 2) % 2, 10] for i in range(4)]
    yield "empty", narrow, [[1, 1, 1], [50, 1, 1], [1, 50, 1]]
    # polygon
    yield "polygon", [random_colour(rng) for _ in range(12)], [[1, 1, 1]]


@pytest.mark.parametrize("seed", range(6))
def test_seeded_kinds(cli, tmp_path, seed):
    rng = random.Random(seed)
    kinds = set()
    for expected, canonical, image in degenerate_cases(rng):
        r, _ = run_both(cli, tmp_path, canonical, image, truth=random_colour(rng))
        assert r.kind == expected
        kinds.add(r.kind)
        if expected == "empty":
            assert r.max_area is None and r.empty_reason
    assert kinds == {"polygon", "segment", "point", "empty"}


@pytest.mark.parametrize("seed", range(8))
def test_seeded_random_scenes(cli, tmp_path, seed):
    rng = random.Random(100 + seed)
    canonical = [random_colour(rng) for _ in range(rng.randint(3, 30))]
    image = [random_colour(rng) for _ in range(rng.randint(1, 6))]
    run_both(cli, tmp_path, canonical, image, truth=random_colour(rng))


@pytest.mark.parametrize("policy", ["grow-canonical", "min-violation"])
def test_recovery_policies(cli, tmp_path, policy):
    narrow = [[10 + i % 2, 10 + (i // 2) % 2, 10] for i in range(4)]
    image = [[1, 1, 1], [3, 1, 1], [1, 3, 1]]
    r, j = run_both(cli, tmp_path, narrow, image, None, ["--on-empty", policy], on_empty=policy)
    assert r.recovery.applied and r.kind != "empty"


def test_numpy_input_is_the_exact_value(cli, tmp_path, sample):
    """A float array is read as the exact rationals of its doubles: the CLI given those
    rationals as text agrees."""
    canonical, image = sample
    c = np.array([[float(x) for x in row] for row in canonical])
    i = np.array([[float(x) for x in row] for row in image])
    exact_c = [[Fraction(x) for x in row] for row in c.tolist()]
    exact_i = [[Fraction(x) for x in row] for row in i.tolist()]
    write_colours(tmp_path / "c.csv", exact_c)
    write_colours(tmp_path / "i.csv", exact_i)
    j = cli("select", "--canonical", tmp_path / "c.csv", "--image", tmp_path / "i.csv", "--json")
    check_scene(gmcc.select(c, i), j)
    # and not the decimal text's value: 0.1 as a double is not 1/10
    assert gmcc.select(c, i).feasible_set != gmcc.select(canonical, image).feasible_set


def test_crule_3d_vs_cli(cli, tmp_path, sample):
    canonical, image = sample
    write_colours(tmp_path / "c.csv", canonical)
    write_colours(tmp_path / "i.csv", image)
    j = cli("select", "--space", "3d", "--canonical", tmp_path / "c.csv", "--image", tmp_path / "i.csv", "--json")
    r = gmcc.crule_3d(canonical, image)
    assert r.feasible_set.kind == j["feasible_set"]["kind"]
    assert [[str(x) for x in v] for v in r.feasible_set.vertices] == j["feasible_set"]["vertices"]
    for rule in ("max_volume", "centroid"):
        ours, theirs = getattr(r, rule), j["selections"][rule]
        assert list(ours.map) == theirs["map"]
        if "map_exact" in theirs:
            assert [str(x) for x in ours.exact] == theirs["map_exact"]
        assert ours.worst_case_deg == theirs.get("worst_case_deg")


def test_version_matches_cli(cli):
    out = cli("--version")
    assert out.startswith("gmcc " + gmcc.__version__ + " (commit " + gmcc.__commit__)
