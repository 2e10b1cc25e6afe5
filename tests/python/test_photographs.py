"""Gamut mapping on photographs from Python (docs/photographs.md, docs/python.md "Photographs"):
the chromaticity-lift trap refused at every 3-D entry; CanonicalLearner3 and estimate_3d recover
a light exactly where F3 is a segment; 3-D max-trace agrees with an independent float linear
program (SciPy's HiGHS, written here) to 0.1 degree wherever the LP's maximiser is unique; the
dark and bright rules against their definition; GCIE against an independent float NNLS (SciPy)."""

import json
import os
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import gmcc

scipy_optimize = pytest.importorskip("scipy.optimize")
scipy_spatial = pytest.importorskip("scipy.spatial")


def angle(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v)), u @ v)))


def scene(seed, h=6, w=7, surfaces=30):
    rng = np.random.default_rng(seed)
    s = rng.integers(50, 900, size=(surfaces, 3))
    light = rng.integers(3, 40, size=3)
    idx = rng.integers(0, surfaces, size=(h, w))
    return s, light, (s[idx] * light).astype(np.uint16)


def test_lifts_are_refused_everywhere():
    s, light, img = scene(1)
    lifts = gmcc.image_colours(img)
    assert lifts.colour_set == "hull"
    for read in (lambda: lifts.colours, lambda: lifts.colours_float):
        with pytest.raises(ValueError, match="chromaticity lifts"):
            read()
    assert len(lifts.chromaticity_lifts) == len(lifts)
    canonical = gmcc.prepare_canonical_3d(s)
    with pytest.raises(ValueError, match="chromaticity lifts"):
        gmcc.crule_3d(s, lifts)
    with pytest.raises(ValueError, match="chromaticity lifts"):
        gmcc.estimate_3d(canonical, lifts)
    with pytest.raises(ValueError, match="chromaticity lifts"):
        gmcc.prepare_canonical_3d(lifts)
    with pytest.raises(ValueError, match="hull-3d"):
        gmcc.estimate_3d(canonical, img, colour_set="hull")
    pixels = gmcc.image_colours(img, colour_set="distinct")
    assert pixels.colour_set == "distinct"
    with pytest.raises(ValueError, match="pixel colours"):
        pixels.chromaticity_lifts
    assert {tuple(int(x) for x in c) for c in pixels.colours} == {tuple(int(x) for x in p) for p in img.reshape(-1, 3)}


def test_learner_and_estimate_recover_the_light():
    rng = np.random.default_rng(7)
    s = rng.integers(50, 900, size=(10, 3))
    learner = gmcc.CanonicalLearner3()
    for _ in range(4):
        e = rng.integers(3, 40, size=3)
        learner.add((s * e).reshape(2, 5, 3).astype(np.uint16), e)
    assert learner.images == 4 and learner.contributing == 4
    top = s.max()
    assert {tuple(c) for c in learner.gamut()} <= {tuple(Fraction(int(x), int(top)) for x in row) for row in s}
    canonical = learner.prepare()
    e = np.array([7, 11, 5])
    r = gmcc.estimate_3d(canonical, (s * e).reshape(2, 5, 3).astype(np.uint16), truth=e)
    assert r.kind == "segment"
    for sel in (r.max_volume, r.centroid, r.max_trace):
        assert sel.recovery_error_deg < 1e-9
        assert angle(sel.light, e) < 1e-9
    only = gmcc.estimate_3d(canonical, (s * e).reshape(2, 5, 3).astype(np.uint16), rules=["max_trace"])
    assert only.max_volume is None and only.max_trace.exact == r.max_trace.exact


def lp_max_trace(A, b, q):
    """The independent float LP (tests/support/float_lp.py): its maximiser d, and whether it is
    unique."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "support"))
    import float_lp
    r, unique = float_lp.max_trace(A, b, q)
    assert r.status == 0
    return r.x, unique


@pytest.mark.parametrize("seed", range(12))
def test_max_trace_agrees_with_a_float_lp(seed):
    rng = np.random.default_rng(100 + seed)
    canonical_colours = rng.integers(1, 1000, size=(40, 3))
    light = rng.integers(5, 30, size=3)
    # Surfaces between canonical ones (so that positive maps exist), under the light, rounded.
    w = rng.dirichlet(np.ones(40) * 0.3, size=30)
    image = np.floor((w @ canonical_colours) * light / 10).reshape(5, 6, 3).astype(np.uint16)
    prepared = gmcc.prepare_canonical_3d(canonical_colours)
    r = gmcc.estimate_3d(prepared, image, rules=["max_trace"])
    g = np.vstack([canonical_colours, np.zeros((1, 3))]).astype(float)
    hull = scipy_spatial.ConvexHull(g)
    q = image.reshape(-1, 3).astype(float)
    x, unique = lp_max_trace(hull.equations[:, :3], -hull.equations[:, 3], q)
    if r.max_trace.light is None or min(x) <= 0:
        pytest.skip("no positive map")
    if not unique:
        pytest.skip("the LP's maximiser is not unique")
    assert angle(r.max_trace.map, x) <= 0.1
    assert sum(r.max_trace.map) >= sum(x) * (1 - 1e-6)


def test_dark_and_bright_rules_follow_their_definition():
    rng = np.random.default_rng(3)
    img = rng.integers(0, 60000, size=(20, 30, 3)).astype(np.uint16)
    c = gmcc.image_colours(img, pixel_rule="gijsenij", colour_set="distinct")
    m = int(img.max())
    v = img.astype(np.int64)
    keep = np.all((255 * v >= 5 * m) & (255 * v <= 245 * m), axis=2)
    assert c.counts["kept"] == int(keep.sum())
    assert c.counts["dark"] + c.counts["bright"] + c.counts["kept"] == img.shape[0] * img.shape[1]
    assert {tuple(int(x) for x in col) for col in c.colours} == {tuple(int(x) for x in p) for p in v[keep]}
    f = gmcc.image_colours(img.astype(np.float64), dark_fraction=Fraction(5, 255),
                           bright_fraction=Fraction(245, 255), colour_set="distinct")
    assert f.counts == c.counts
    with pytest.raises(ValueError, match="gijsenij"):
        gmcc.image_colours(img, pixel_rule="gijsenij", dark_fraction=0.1)
    with pytest.raises(ValueError, match="dark_fraction"):
        gmcc.image_colours(img, dark_fraction=2)


def write_dataset(folder, seed, prefix, surface_indices):
    """Nine 16-bit PNGs of 25 random surfaces under random integer lights, and their truth table:
    image i is surfaces[surface_indices(rng)] ⊙ e_i. Returns the truth table's path."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "support"))
    from png16 import write_png16
    rng = np.random.default_rng(seed)
    surfaces = rng.integers(50, 900, size=(25, 3))
    lines = ["image,r,g,b"]
    for i in range(9):
        e = rng.integers(3, 60, size=3)
        img = surfaces[surface_indices(rng)] * e
        write_png16(folder / f"{prefix}{i}.png", [[tuple(int(x) for x in px) for px in row] for row in img])
        lines.append(f"{prefix}{i}.png,{e[0]},{e[1]},{e[2]}")
    truths = folder / "truths.csv"
    truths.write_text("\n".join(lines) + "\n")
    return truths


def test_benchmark_equals_the_command_line(tmp_path):
    truths = write_dataset(tmp_path, 27, "p", lambda rng: rng.integers(0, 25, size=(6, 7)))
    summary, records = gmcc.benchmark(tmp_path, truths, folds=3, pixel_rule="gijsenij", frame=False)
    assert [s["method"] for s in summary][:2] == ["gm3d-max-trace", "gm3d-max-volume"]
    assert len(records) == 9 * len(summary)
    cli = os.environ.get("GMCC_CLI")
    if not cli:
        pytest.skip("GMCC_CLI not set")
    out = tmp_path / "r.jsonl"
    subprocess.run([cli, "benchmark", "--images", str(tmp_path), "--truths", str(truths), "--folds", "3",
                    "--pixel-rule", "gijsenij", "--no-progress", "--records", str(out)], check=True,
                   capture_output=True)
    lines = [json.loads(x) for x in out.read_text().splitlines()[2:]]
    assert len(lines) == len(records)
    for a, b in zip(records, lines):
        assert (a["image"], a["method"], a["fold"], a["answered"]) == (b["image"], b["method"], b["fold"], b["answered"])
        assert (a["error_deg"] is None) == (b["error_deg"] is None)
        if a["error_deg"] is not None:
            assert a["error_deg"] == b["error_deg"]
    with pytest.raises(ValueError, match="folds"):
        gmcc.benchmark(tmp_path, truths)
    with pytest.raises(ValueError, match="not a benchmark method"):
        gmcc.benchmark(tmp_path, truths, folds=3, methods=["grey-sky"])


def test_edge_methods_equal_the_command_line(tmp_path):
    # The edge-based methods (Gijsenij et al. 2010 §4) at a chosen sigma, from Python and from the
    # command line, on images of surface patches under integer lights: the same records.
    truths = write_dataset(tmp_path, 28, "q",
                           lambda rng: np.repeat(np.repeat(rng.integers(0, 25, size=(4, 4)), 4, axis=0), 4, axis=1))
    methods = ["gm3d-edge1-max-trace", "gm3d-edge2-max-trace", "gm3d-1jet-max-trace", "gm3d-2jet-max-trace"]
    summary, records = gmcc.benchmark(tmp_path, truths, folds=3, methods=methods, edge_sigma=1.5, frame=False)
    assert [s["method"] for s in summary] == methods and len(records) == 9 * 4
    assert sum(r["feasible_kind"] is not None for r in records) >= 18
    with pytest.raises(ValueError, match="sigma"):
        gmcc.benchmark(tmp_path, truths, folds=3, methods=methods[:1], edge_sigma=0)
    cli = os.environ.get("GMCC_CLI")
    if not cli:
        pytest.skip("GMCC_CLI not set")
    out = tmp_path / "r.jsonl"
    subprocess.run([cli, "benchmark", "--images", str(tmp_path), "--truths", str(truths), "--folds", "3",
                    "--methods", ",".join(methods), "--edge-sigma", "1.5", "--no-progress", "--records", str(out)],
                   check=True, capture_output=True)
    lines = [json.loads(x) for x in out.read_text().splitlines()[2:]]
    assert [(a["image"], a["method"], a["error_deg"], a["answered"]) for a in records] == \
        [(b["image"], b["method"], b["error_deg"], b["answered"]) for b in lines]


def test_reproduce_refuses_an_expansion_beyond_the_limit():
    # Issue 30 item 4: the 1e150 limit of every command, as a ValueError naming it (not an internal error).
    for expand in ("1e151", "1e400"):
        with pytest.raises(ValueError, match="1e150"):
            gmcc.reproduce_synthetic(scenes=1, expand=expand, expand_policy="multiplicative")


def test_truth_in_f3_and_lights_at_any_scale():
    """Issue 41: with dark pixels (a zero channel) the truth is still decided, the map-space error
    is within its worst case, and an image array and truth scaled by 2^600 (floats far outside
    a light's double range once divided) give the same light and errors as unscaled."""
    rng = np.random.default_rng(41)
    s = rng.integers(0, 900, size=(30, 3))
    s[::3, 0] = 0  # surfaces with a zero channel: F3 reaches the coordinate planes
    s = np.vstack([s, [[400, 300, 200]]])
    canonical = gmcc.prepare_canonical_3d(s)
    e = np.array([7, 11, 5])
    img = (s * e).reshape(1, -1, 3).astype(float)
    r = gmcc.estimate_3d(canonical, img, truth=e)
    assert r.truth_in_feasible is True
    assert gmcc.estimate_3d(canonical, img).truth_in_feasible is None
    for sel in (r.max_volume, r.centroid, r.max_trace):
        assert sel.map_error_deg <= sel.worst_case_deg
    big = gmcc.estimate_3d(canonical, img * 2.0**600, truth=e * 2.0**600)
    assert big.truth_in_feasible is True
    for a, b in ((r.max_volume, big.max_volume), (r.centroid, big.centroid), (r.max_trace, big.max_trace)):
        assert np.all(np.isfinite(b.light))
        assert np.allclose(a.light, b.light, rtol=0, atol=1e-12)
        assert abs(a.recovery_error_deg - b.recovery_error_deg) < 1e-9


def lp_max_trace_in_cone(A, b, q, maps):
    """Independent float LP over F3 ∩ cone(maps): maximise d1 + d2 + d3 over (d, λ) with
    A (d ∘ q) <= b, d = Σ λ_j maps_j, d, λ >= 0; and whether the maximiser d is unique."""
    linprog = scipy_optimize.linprog
    n = len(maps)
    rows = (A[:, None, :] * q[None, :, :]).reshape(-1, 3)
    A_ub = np.hstack([rows, np.zeros((len(rows), n))])
    b_ub = np.repeat(b, len(q))
    A_eq = np.hstack([np.eye(3), -np.asarray(maps, float).T])
    c = np.concatenate([-np.ones(3), np.zeros(n)])
    r = linprog(c, A_ub=A_ub, b_ub=b_ub, A_eq=A_eq, b_eq=np.zeros(3), bounds=[(0, None)] * (3 + n), method="highs")
    assert r.status == 0
    unique = True
    for k in range(3):
        ends = []
        for sign in (1, -1):
            ck = np.zeros(3 + n)
            ck[k] = sign
            t = linprog(ck, A_ub=np.vstack([A_ub, np.concatenate([np.ones(3), np.zeros(n)])[None, :] * -1]),
                        b_ub=np.concatenate([b_ub, [r.fun]]), A_eq=A_eq, b_eq=np.zeros(3),
                        bounds=[(0, None)] * (3 + n), method="highs")
            ends.append(sign * t.fun)
        unique = unique and abs(ends[0] - ends[1]) <= 1e-7 * max(1.0, abs(r.x[k]))
    return r.x[:3], unique


@pytest.mark.parametrize("seed", range(10))
def test_constrained_max_trace_agrees_with_a_float_lp(seed):
    """Issue 45: max-trace over F3 ∩ cone(plausible lights' maps) against an independent float LP
    (SciPy's HiGHS) to 0.1 degree wherever the LP's maximiser is unique."""
    rng = np.random.default_rng(300 + seed)
    canonical_colours = rng.integers(1, 1000, size=(40, 3))
    light = rng.integers(5, 30, size=3)
    w = rng.dirichlet(np.ones(40) * 0.3, size=30)
    image = np.floor((w @ canonical_colours) * light / 10).reshape(5, 6, 3).astype(np.uint16)
    lights = rng.integers(5, 30, size=(6, 3))
    prepared = gmcc.prepare_canonical_3d(canonical_colours)
    r = gmcc.estimate_3d(prepared, image, rules=["max_trace"], illuminants=lights.tolist())
    g = np.vstack([canonical_colours, np.zeros((1, 3))]).astype(float)
    hull = scipy_spatial.ConvexHull(g)
    q = image.reshape(-1, 3).astype(float)
    maps = 1.0 / lights
    x, unique = lp_max_trace_in_cone(hull.equations[:, :3], -hull.equations[:, 3], q, maps)
    if r.max_trace.light is None or min(x) <= 1e-12:
        assert max(x) <= 1e-9 or r.max_trace.light is not None, "the LP finds a positive map gmcc does not"
        pytest.skip("no positive map in F3 ∩ cone")
    if not unique:
        pytest.skip("the LP's maximiser is not unique")
    assert angle(r.max_trace.map, x) <= 0.1
    # The constraint only removes maps: the trace is at most the unconstrained one.
    free = gmcc.estimate_3d(prepared, image, rules=["max_trace"])
    assert sum(r.max_trace.map) <= sum(free.max_trace.map) * (1 + 1e-12)


@pytest.mark.parametrize("seed,palette", [(41, False), (42, False), (43, True), (44, True)])
def test_gcie_agrees_with_an_independent_nnls(tmp_path, seed, palette):
    # GCIE (Finlayson, Hordley & Tastl 2006; docs/math.md §1f) written here in floats with SciPy's
    # NNLS (Lawson & Hanson's active set) and Qhull: each fold's canonical chromaticities, each
    # training light's gamut cone, the sum of squared NNLS residuals of the test image's 3-D hull
    # vertices, the least sum (several lights at 0: the one nearest their mean chromaticity).
    # gmcc's exact choice must be the same light wherever the float decision has no near tie.
    # With `palette`, three lights each light four images, one in every fold: the image's own
    # light is then among the training lights and consistent (score 0, tied with its copies);
    # without, every light differs and no training light is consistent (the scores decide).
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "support"))
    from png16 import write_png16
    rng = np.random.default_rng(seed)
    surfaces = rng.integers(50, 900, size=(25, 3))
    images, lights, lines = [], [], ["image,r,g,b"]
    three = rng.integers(3, 60, size=(3, 3))
    for i in range(12):
        e = three[i // 4] if palette else rng.integers(3, 60, size=3)
        img = surfaces[rng.integers(0, 25, size=(5, 6))] * e
        write_png16(tmp_path / f"g{i}.png", [[tuple(int(x) for x in px) for px in row] for row in img])
        images.append(img.reshape(-1, 3).astype(float))
        lights.append(e.astype(float))
        lines.append(f"g{i}.png,{e[0]},{e[1]},{e[2]}")
    truths = tmp_path / "truths.csv"
    truths.write_text("\n".join(lines) + "\n")
    _, records = gmcc.benchmark(tmp_path, truths, folds=3, methods=["gcie"], frame=False)
    compared = consistent = 0
    for rec in records:
        i = int(rec["image"][1:-4])  # g<i>.png
        training = [j for j in range(12) if j % 3 != i % 3]
        xy = np.vstack([images[j][:, :2] / images[j][:, 2:] * lights[j][2] / lights[j][:2] for j in training])
        hull = xy[scipy_spatial.ConvexHull(xy).vertices]
        colours = np.unique(images[i], axis=0)
        colours = colours[scipy_spatial.ConvexHull(colours).vertices]
        scores, borderline = [], False
        for j in training:
            g = np.column_stack([lights[j][0] * hull[:, 0], lights[j][1] * hull[:, 1], np.full(len(hull), lights[j][2])])
            g /= np.linalg.norm(g, axis=1, keepdims=True)
            rel = [scipy_optimize.nnls(g.T, p)[1] / np.linalg.norm(p) for p in colours]
            borderline |= any(1e-12 < r < 1e-6 for r in rel)
            scores.append(sum((r * np.linalg.norm(p)) ** 2 if r > 1e-9 else 0.0 for r, p in zip(rel, colours)))
        best = min(scores)
        tied = [training[k] for k, s in enumerate(scores) if s == best] if best == 0 else \
            [training[k] for k, s in enumerate(scores) if s <= best * (1 + 1e-9)]
        others = sorted(s for s in scores if s > best * (1 + 1e-9))
        if borderline or (best > 0 and len(tied) > 1) or (others and best > 0 and others[0] < best * (1 + 1e-6)):
            continue
        q = np.array([lights[j][:2] / lights[j].sum() for j in tied])
        chosen = tied[int(np.argmin(((q - q.mean(axis=0)) ** 2).sum(axis=1)))]
        assert angle(rec["light"], lights[chosen]) < 1e-6, (i, chosen, tied, scores)
        compared += 1
        consistent += best == 0
    assert compared >= 9
    assert consistent >= 9 if palette else consistent == 0
