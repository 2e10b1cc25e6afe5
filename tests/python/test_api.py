"""The module's API beyond select: the selection rules on a feasible set against select's
answers, worst cases, statistics against an independent numpy computation, the synthetic
experiment's records (seeded: the same seed gives the same records; structured array and
DataFrame the same values), readable reprs and exact types."""

import re
from fractions import Fraction

import numpy as np
import pytest

import gmcc

CANONICAL = [["1", "1", "1"], ["3", "1", "1"], ["1", "3", "1"], ["2", "2", "1"], ["1/2", "1", "1"]]
IMAGE = [["1", "1", "1"], ["6/5", "1", "1"]]


def test_rules_on_a_feasible_set_match_select():
    r = gmcc.select(CANONICAL, IMAGE, canonical_illuminant=(1, 1, 1))
    F = gmcc.feasible_set(CANONICAL, IMAGE)
    assert F == r.feasible_set and F.kind == "polygon"
    assert gmcc.max_area(F).exact == r.max_area.exact
    assert gmcc.mean_2d(F).exact == r.mean_2d.exact == F.centroid
    assert gmcc.mean_3d(F).map == r.mean_3d.map
    s = gmcc.select_maps(F, canonical_illuminant=(1, 1, 1))
    for rule in ("max_area", "mean_2d", "mean_3d"):
        assert s[rule].map == getattr(r, rule).map
        assert s[rule].worst_case_deg == getattr(r, rule).worst_case_deg
        assert s[rule].worst_case_illuminant_deg == getattr(r, rule).worst_case_illuminant_deg
    assert gmcc.worst_case_map_deg(F, r.max_area.exact) == r.max_area.worst_case_deg
    assert gmcc.worst_case_illuminant_deg(F, r.mean_2d.exact) == r.mean_2d.worst_case_illuminant_deg
    # Each route to the 3-D mean: within its stated error of the certified closed form.
    exact = gmcc.mean_3d(F)
    lo, hi = exact.enclosure[0]
    assert lo <= exact.map[0] <= hi
    quad = gmcc.mean_3d(F, method="quadrature", order=16)
    assert abs(quad.map[0] - exact.map[0]) <= quad.error_bounds[0] + exact.error_bounds[0]
    mc = gmcc.mean_3d(F, method="monte-carlo", samples=200000, seed=3)
    assert abs(mc.map[0] - exact.map[0]) < 6 * mc.standard_error[0]
    assert gmcc.mean_3d(F, method="monte-carlo", samples=200000, seed=3).map == mc.map  # seeded
    with pytest.raises(ValueError, match="empty"):
        gmcc.max_area(gmcc.feasible_set([[10, 10, 10], [11, 10, 10], [10, 11, 10]], [[1, 1, 1], [50, 1, 1]]))


def test_rules_named_once_and_per_scene_choices():
    # Every per-rule attribute, dict key and truth report follows gmcc.rules().
    assert gmcc.rules() == ["max_area", "mean_2d", "mean_3d"]
    r = gmcc.select(CANONICAL, IMAGE, truth=(1, 1, 1))
    assert list(r.selections) == gmcc.rules()
    for rule in gmcc.rules():
        assert r.selections[rule].map == getattr(r, rule).map
        e = getattr(r.truth, rule)
        assert isinstance(e, gmcc.RuleErrors)
        assert e.worst_case_deg == getattr(r, rule).worst_case_deg
    # A prepared Canonical takes the 3-D mean's route per call: the same answer as a Canonical
    # prepared with it, without preparing again; canonical-side options are still refused.
    prepared = gmcc.prepare_canonical(CANONICAL)
    for choice in (dict(mean3d="quadrature", order=20), dict(mean3d="monte-carlo", samples=5000, seed=7),
                   dict(illuminant_worst_case=False)):
        per_call = gmcc.select(prepared, IMAGE, **choice)
        baked = gmcc.select(gmcc.prepare_canonical(CANONICAL, **choice), IMAGE)
        for rule in gmcc.rules():
            assert getattr(per_call, rule).map == getattr(baked, rule).map
            assert getattr(per_call, rule).worst_case_illuminant_deg == getattr(baked, rule).worst_case_illuminant_deg
    assert gmcc.select(prepared, IMAGE).mean_3d.estimate.method == "analytic"  # the call changed nothing
    with pytest.raises(TypeError, match="expand"):
        gmcc.select(prepared, IMAGE, expand="0.1", mean3d="quadrature")
    with pytest.raises(ValueError, match="order: must be from 1 to 256"):
        gmcc.select(prepared, IMAGE, mean3d="quadrature", order=0)


def test_exact_types_and_reprs():
    r = gmcc.select(CANONICAL, IMAGE)
    F = r.feasible_set
    assert all(isinstance(x, Fraction) for v in F.vertices for x in v)
    assert isinstance(F.area, Fraction) and F.area > 0
    assert F.vertices_float.dtype == np.float64 and F.vertices_float.shape == (len(F), 2)
    assert F.vertices_float.tolist() == [[float(x), float(y)] for x, y in F.vertices]
    assert F.contains(F.centroid) and not F.contains((100, 100))
    assert re.fullmatch(r"ConvexSet\(polygon, \d+ vertices, area≈[0-9.]+\)", repr(F))
    assert repr(r).startswith("SceneResult(feasible set ConvexSet(polygon")
    assert "max_area (" in repr(r) and "exact" in repr(r.max_area)
    assert "analytic ±" in repr(r.mean_3d)
    assert repr(gmcc.canonical_gamut(CANONICAL)).startswith("ConvexSet(polygon")
    assert r.mean_3d.exact is None and r.mean_3d.enclosure.shape == (2, 2)
    assert set(r.selections) == {"max_area", "mean_2d", "mean_3d"}
    assert gmcc.illuminant_map((2, 1, 4), (1, 1, 1)) == (Fraction(2), Fraction(4))


def test_canonical_gamut_and_constraint():
    G = gmcc.canonical_gamut(CANONICAL)
    assert G.kind == "polygon"
    # (1, 1) and (2, 2) lie on edges: a strictly convex polygon of three vertices, CCW
    assert G.vertices == [(Fraction(1, 2), Fraction(1)), (Fraction(3), Fraction(1)), (Fraction(1), Fraction(3))]
    assert G.area == Fraction(5, 2)
    grown = gmcc.canonical_gamut(CANONICAL, expand="1/10", expand_policy="multiplicative")
    assert grown.area > G.area and all(grown.contains(v) for v in G.vertices)
    C = gmcc.illumination_constraint([[1, 1, 1], [2, 1, 1], [1, 1, 2]])
    assert C.kind == "polygon" and C.contains((1, 1))
    r = gmcc.select(CANONICAL, IMAGE, illuminants=[[1, 1, 1], [2, 1, 1], [1, 1, 2]])
    assert r.constraint.maps == C
    assert r.constraint.unconstrained == gmcc.feasible_set(CANONICAL, IMAGE)


def sorted_quantile(xs, p):
    xs = sorted(xs)
    h = (len(xs) - 1) * p
    i = int(h)
    f = h - i
    return xs[i] if f == 0 or i == len(xs) - 1 else (1 - f) * xs[i] + f * xs[i + 1]


@pytest.mark.parametrize("n", [1, 2, 3, 4, 7, 100])
def test_statistics_against_numpy(n):
    values = np.random.default_rng(n).gamma(2.0, 3.0, n)
    s = gmcc.error_statistics(values)
    xs = sorted(values.tolist())
    q = max(1, -(-n // 4))
    assert s.n == n
    assert s.mean == pytest.approx(np.mean(values), rel=1e-15)
    assert s.median == pytest.approx(np.median(values), rel=1e-15)
    assert s.median == pytest.approx(np.quantile(values, 0.5), rel=1e-15)  # type 7, numpy's default
    trimean = (np.quantile(values, 0.25) + 2 * np.median(values) + np.quantile(values, 0.75)) / 4
    assert s.trimean == pytest.approx(trimean, rel=1e-14)
    assert s.best25 == pytest.approx(np.mean(xs[:q]), rel=1e-15)
    assert s.worst25 == pytest.approx(np.mean(xs[-q:]), rel=1e-15)
    assert s.p95 == pytest.approx(np.quantile(values, 0.95), rel=1e-14)
    assert s.max == xs[-1]
    if n > 1:
        assert s.standard_error == pytest.approx(np.std(values, ddof=1) / np.sqrt(n), rel=1e-12)
    assert s.as_dict()["trimean"] == s.trimean
    with pytest.raises(ValueError, match="element 0 is not finite"):
        gmcc.error_statistics([np.nan, 1.0])


def test_synthetic_records_are_seeded_and_complete():
    a = gmcc.reproduce_synthetic(lights=("D75", "P2856"), max_surfaces=3, scenes=4, seed=11, frame=False)
    b = gmcc.reproduce_synthetic(lights=("D75", "P2856"), max_surfaces=3, scenes=4, seed=11, frame=False, threads=1)
    c = gmcc.reproduce_synthetic(lights=("D75", "P2856"), max_surfaces=3, scenes=4, seed=12, frame=False)
    assert isinstance(a, np.ndarray) and a.dtype.names[:5] == ("light", "surfaces", "scene", "kind", "area")
    assert len(a) == 2 * 3 * 4
    assert a.tobytes() == b.tobytes()  # the same seed, any thread count: the same records
    assert a.tobytes() != c.tobytes()
    # The experiment is exact and noise-free: the true map is in every F, and no F is empty.
    assert set(a["kind"]) <= {"polygon", "segment", "point"}
    assert np.all(np.isfinite(a["mean_3d_error_deg"]))
    assert np.all(a["mean_3d_error_deg"] <= a["mean_3d_worst_case_deg"] + 1e-9)
    df = gmcc.reproduce_synthetic(lights=("D75", "P2856"), max_surfaces=3, scenes=4, seed=11, frame=True)
    assert list(df.columns) == list(a.dtype.names)
    assert np.array_equal(df["mean_2d_error_deg"].to_numpy(), a["mean_2d_error_deg"])
    stats = gmcc.summarise(df, "mean_3d")
    assert set(stats) == {(l, n) for l in ("D75", "P2856") for n in (1, 2, 3)}
    sel = (a["light"] == "D75") & (a["surfaces"] == 2)
    assert stats[("D75", 2)].mean == gmcc.error_statistics(a["mean_3d_error_deg"][sel]).mean
    assert gmcc.summarise(a, "mean_3d")[("D75", 2)].median == stats[("D75", 2)].median


def test_crule_3d_result():
    r = gmcc.crule_3d(CANONICAL, IMAGE)
    assert r.feasible_set.kind == "polytope" and r.volume > 0
    assert r.max_volume.worst_case_deg is not None
    assert all(isinstance(x, Fraction) for x in r.centroid.exact)
    assert gmcc.crule_3d(CANONICAL, IMAGE, black="exclude").volume <= r.volume
    with pytest.raises(ValueError, match="black"):
        gmcc.crule_3d(CANONICAL, IMAGE, black="grey")
