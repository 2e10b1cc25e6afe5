#!/usr/bin/python3
"""Differential test of `gmcc select --json` against the independent oracle
(tests/oracle/select_oracle.py), on seeded random cases plus a fixed list of degenerate ones.

    /usr/bin/python3 tests/cli/test_select_oracle.py GMCC_BINARY [--cases N] [--seed S]
                     [--keep DIR] [--jobs J]

For every case the two CSVs are written to a temporary directory and the binary is run as
`GMCC_BINARY select --canonical C.csv --image I.csv --json`.  Compared (docs/cli.md "JSON output"):
  * feasible_set.kind; vertices exactly (a polygon as a cyclic counter-clockwise sequence, a
    segment as a set of 2 end points, a point as itself, empty as []); area exactly; the strings
    must be reduced "p/q" or "p";
  * vertices_approx and the "map" doubles of the exact rules: within 1e-15 relative of the exact
    values (they should be correctly rounded);
  * max_area and mean_2d map_exact: exactly;
  * mean_3d map: |map - true| (max over components) <= max(error_bound, 1e-300)*(1 + 1e-6)
    + 1e-15*max|true|, true = Arvo's formula at >= 60 digits; method == "analytic";
  * worst_case_deg of each rule: within 1e-9 degrees;
  * kind "empty": "selections" absent or without any rule.
On a mismatch the case (both CSVs) and both answers are printed.  The last line is exactly
`N passed, N failed`; the exit status is 0 iff none failed.
"""

import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from fractions import Fraction as Fr

import mpmath

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "oracle"))
import select_oracle as so  # noqa: E402

TIMEOUT_S = 60
WORST_TOL_DEG = 1e-9
APPROX_REL = 1e-15


# --------------------------------------------------------------------------------------------
# Writing exact numbers as CSV text in the accepted spellings (docs/cli.md "Input files")
# --------------------------------------------------------------------------------------------


def _terminating(x):
    """True when x has a finite decimal expansion (denominator 2^a 5^b)."""
    d = x.denominator
    for p in (2, 5):
        while d % p == 0:
            d //= p
    return d == 1


def _plain_decimal(x):
    """Exact decimal text of a terminating Fraction, e.g. 7/20 -> '0.35'."""
    k = 0
    while (x * 10 ** k).denominator != 1:
        k += 1
    digits = str(int(x * 10 ** k)).rjust(k + 1, "0")
    return digits if k == 0 else digits[:-k] + "." + digits[-k:]


def number_text(x, rng):
    """Some exact spelling of the non-negative rational x."""
    x = Fr(x)
    if _terminating(x):
        style = rng.random()
        plain = _plain_decimal(x)
        if style < 0.55 or x == 0:
            return plain
        if style < 0.7:
            return plain + ("0" if "." in plain else ".0")  # trailing zero: '0.350', '3.0'
        if style < 0.8 and x.denominator == 1:
            return f"{x.numerator}/1"
        # Scientific: mantissa digits with an exponent, e.g. 0.35 -> '35e-2' or '3.5E-1'.
        k = 0
        while (x * 10 ** k).denominator != 1:
            k += 1
        mant = int(x * 10 ** k)
        if rng.random() < 0.5:
            return f"{mant}e-{k}" if k else f"{mant}e0"
        s = str(mant)
        exp = len(s) - 1 - k
        return f"{s[0]}.{s[1:] or '0'}{rng.choice('eE')}{exp:+d}"
    return f"{x.numerator}/{x.denominator}"


def csv_text(colours, rng, dressing=True):
    """CSV text for [(r, g, b)] exact colours; with `dressing`, sometimes a header, comments,
    blank lines, spaces around numbers and CRLF line ends (all valid: docs/cli.md "Input files")."""
    lines = []
    if dressing and rng.random() < 0.3:
        lines.append("r,g,b")
    for c in colours:
        if dressing and rng.random() < 0.05:
            lines.append("# a comment, with commas")
        if dressing and rng.random() < 0.05:
            lines.append("")
        fields = [number_text(v, rng) for v in c]
        if dressing and rng.random() < 0.1:
            fields = [f" {f} " for f in fields]
        lines.append(",".join(fields))
    end = "\r\n" if dressing and rng.random() < 0.15 else "\n"
    return end.join(lines) + end


# --------------------------------------------------------------------------------------------
# Cases
# --------------------------------------------------------------------------------------------


class Case:
    def __init__(self, name, canonical, image, canonical_text=None, image_text=None,
                 expect=None, rng=None):
        """canonical, image: exact colours [(r, g, b)].  Texts default to a random spelling.
        `expect` optionally holds hand-derived exact answers checked against the oracle too."""
        self.name = name
        self.canonical = [tuple(Fr(v) for v in c) for c in canonical]
        self.image = [tuple(Fr(v) for v in c) for c in image]
        rng = rng or random.Random(name)
        self.canonical_text = canonical_text or csv_text(self.canonical, rng)
        self.image_text = image_text or csv_text(self.image, rng)
        self.expect = expect or {}


def chroma(colours):
    return [(r / b, g / b) for r, g, b in colours if b > 0]


def rand_channel(rng):
    """A positive small-denominator rational in [1/2, 12], of one of the kinds users write
    (integer, decimal with 1-3 places, p/q).  The narrow range keeps canonical gamuts of
    realistic spread, so that random images are infeasible often enough."""
    u = rng.random()
    if u < 0.3:
        return Fr(rng.randint(1, 12))
    if u < 0.65:
        k = rng.randint(1, 3)
        return Fr(rng.randint(5 * 10 ** (k - 1), 12 * 10 ** k), 10 ** k)
    q = rng.randint(2, 9)
    return Fr(rng.randint((q + 1) // 2, 12 * q), q)


def rand_colour(rng):
    return (rand_channel(rng), rand_channel(rng), rand_channel(rng))


def random_canonical(rng):
    u = rng.random()
    if u < 0.04:
        cols = [rand_colour(rng)]
    elif u < 0.10:
        # Collinear chromaticities: a canonical segment.
        a, b = rand_colour(rng), rand_colour(rng)
        qa, qb = (a[0] / a[2], a[1] / a[2]), (b[0] / b[2], b[1] / b[2])
        cols = []
        for _ in range(rng.randint(2, 8)):
            t = Fr(rng.randint(0, 12), 12)
            s = rand_channel(rng)
            cols.append((s * (qa[0] + t * (qb[0] - qa[0])), s * (qa[1] + t * (qb[1] - qa[1])), s))
    else:
        cols = [rand_colour(rng) for _ in range(rng.randint(1, 40))]
    if rng.random() < 0.2:
        cols += rng.sample(cols, rng.randint(1, len(cols)))  # duplicates
    return cols


def random_image(rng, canonical):
    """Image colours.  30%: canonical colours (or convex combinations of them) mapped by the
    inverse of a random diagonal map d, so that the perspective map of d lies in F (feasible by
    construction); 30%: the same with each chromaticity perturbed by factors in [0.5, 2];
    40%: unrelated colours.  Overall about 60% of the random cases have a non-empty F."""
    d = rand_colour(rng)
    k = rng.randint(1, 12)
    u = rng.random()
    image = []
    for _ in range(k):
        if u < 0.6:
            c = rng.choice(canonical)
            if rng.random() < 0.25 and len(canonical) > 1:
                c2, t = rng.choice(canonical), Fr(rng.randint(0, 8), 8)
                c = tuple(x + t * (y - x) for x, y in zip(c, c2))
            c = tuple(x / dk for x, dk in zip(c, d))
            if u >= 0.3:  # perturbed: F often empty or small
                c = (c[0] * Fr(rng.randint(50, 200), 100), c[1] * Fr(rng.randint(50, 200), 100), c[2])
            s = rand_channel(rng)  # intensity does not change the chromaticity
            image.append(tuple(s * x for x in c))
        else:
            image.append(rand_colour(rng))
    if rng.random() < 0.15:
        image += rng.sample(image, rng.randint(1, len(image)))  # duplicates
    return image


def random_case(rng, index):
    canonical = random_canonical(rng)
    image = random_image(rng, canonical)
    # Sometimes colours without chromaticity (b = 0), which are dropped by default.
    if rng.random() < 0.1:
        canonical = canonical + [(rand_channel(rng), rand_channel(rng), Fr(0))]
    if rng.random() < 0.1:
        image = image + [(Fr(0), Fr(0), Fr(0))]
    if rng.random() < 0.05:
        # Tiny feasible polygon: the image is G_c shrunk about its centroid
        # (docs/derivations.md §1.6).
        hull = so.convex_hull(chroma(canonical))
        if len(hull) >= 3:
            delta = Fr(1, 10 ** rng.randint(3, 9))
            cx = sum(p[0] for p in hull) / len(hull)
            cy = sum(p[1] for p in hull) / len(hull)
            image = [(cx + (1 - delta) * (x - cx), cy + (1 - delta) * (y - cy), Fr(1))
                     for x, y in hull]
    return Case(f"random-{index}", canonical, image, rng=rng)


def fixed_cases():
    """Degenerate and hand-derived cases (docs/conventions.md §6, docs/derivations.md §1.5, §2)."""
    cases = []
    one = (1, 1, 1)
    square = [(1, 1, 1), (2, 1, 1), (2, 2, 1), (1, 2, 1)]  # chromaticities [1,2]^2
    pentagon = [(11, 7, 10), (14, 6, 10), (16, 9, 10), (13, 12, 10), (10, 10, 10)]

    # The paper's toy example (BMVC'97 text, docs/derivations.md §1.5): feasible maps on the segment
    # (3,2)-(1/3,2/3) when the canonical colours are (3,2,1), (1,2,3) and the image is white.
    cases.append(Case("toy-example", [(3, 2, 1), (1, 2, 3)], [one],
                      canonical_text="r,g,b\n3,2,1\n1,2,3\n", image_text="1,1,1\n",
                      expect={"kind": "segment", "max_area": (Fr(3), Fr(2)),
                              "mean_2d": (Fr(5, 3), Fr(4, 3)), "mean_3d": (1, 1)}))
    cases.append(Case("single-canonical-single-image", [(1, 2, 3)], [(3, 1, 7)],
                      expect={"kind": "point", "max_area": (Fr(7, 9), Fr(14, 3))}))
    cases.append(Case("single-canonical-same-chromaticity", [(1, 2, 3)],
                      [(3, 1, 7), (6, 2, 14), (3, 1, 7)], expect={"kind": "point"}))
    cases.append(Case("single-canonical-two-image", [(1, 2, 3)], [(3, 1, 7), (1, 1, 1)],
                      expect={"kind": "empty"}))
    cases.append(Case("single-image-polygon", pentagon, [(3, 5, 4)], expect={"kind": "polygon"}))
    cases.append(Case("duplicates", pentagon + pentagon[:3], [(1, 1, 1), (1, 1, 1), (2, 2, 2)],
                      expect={"kind": "polygon"}))
    # Collinear image chromaticities (1,1), (5/4,1), (3/2,1): the image hull is a segment.
    cases.append(Case("collinear-image", pentagon, [(10, 10, 10), (5, 4, 4), (3, 2, 2)]))
    # Collinear canonical chromaticities: G_c is the segment (1,1)-(3,3).
    col = [(1, 1, 1), (2, 2, 1), (3, 3, 1), (3, 3, 2)]
    cases.append(Case("canonical-segment-one-image", col, [(1, 1, 1)], expect={"kind": "segment"}))
    cases.append(Case("canonical-segment-two-image", col, [(1, 1, 1), (2, 2, 1)],
                      expect={"kind": "segment"}))
    cases.append(Case("canonical-segment-point", col, [(1, 1, 1), (3, 3, 1)],
                      expect={"kind": "point"}))
    cases.append(Case("canonical-segment-empty", col, [(1, 1, 1), (4, 4, 1)],
                      expect={"kind": "empty"}))
    cases.append(Case("canonical-segment-off-line", col, [(1, 2, 1)],
                      expect={"kind": "segment"}))
    # Canonical segment (1,2)-(3,1) on x1 + 2 x2 = 5; q = (1,1) and (1/2,4/3) give two
    # constraint lines crossing at (2, 3/2).  (A segment through the origin, like `col`, would
    # only ever give lines through the origin.)
    seg = [(1, 2, 1), (3, 1, 1), (4, 3, 2)]
    cases.append(Case("canonical-segment-crossing", seg, [one, (3, 8, 6)],
                      expect={"kind": "point", "max_area": (Fr(2), Fr(3, 2))}))
    cases.append(Case("canonical-segment-lines-through-origin", col, [(1, 2, 1), (2, 1, 1)],
                      expect={"kind": "empty"}))
    # Image colours on the canonical boundary (a vertex and an edge midpoint): m = (1,1) in F.
    cases.append(Case("image-on-boundary", square, [(2, 2, 1), (3, 2, 2), (1, 1, 1)],
                      expect={"kind": "point"}))
    cases.append(Case("image-on-edge", square, [(3, 2, 2), (3, 3, 2)], expect={"kind": "polygon"}))
    cases.append(Case("box-point", square, [one, (2, 2, 1)], expect={"kind": "point"}))
    cases.append(Case("box-polygon", square, [one, (3, 3, 2)],
                      expect={"kind": "polygon", "area": Fr(1, 9), "mean_2d": (Fr(7, 6), Fr(7, 6)),
                              "max_area": (Fr(4, 3), Fr(4, 3))}))
    cases.append(Case("box-segment", square, [one, (2, 1, 1)],
                      expect={"kind": "segment", "max_area": (Fr(1), Fr(2))}))
    cases.append(Case("box-empty", square, [one, (3, 3, 1)], expect={"kind": "empty"}))
    # Max-area in an edge interior: triangle (1,5),(5,1),(1,1) -> (3,3) on a + b = 6
    # (docs/derivations.md §2.2).
    cases.append(Case("max-area-edge-interior", [(1, 5, 1), (5, 1, 1), (1, 1, 1)], [one],
                      expect={"max_area": (Fr(3), Fr(3)), "mean_2d": (Fr(7, 3), Fr(7, 3))}))
    # Tiny feasible sets of width ~1e-9: the box with q = (1,1) and (2-2e-9, 2-2e-9); and the
    # pentagon with an image shrunk about its centroid by 1 - 1e-9 (the conditioning of
    # docs/derivations.md §1.6).
    e = Fr(2, 10 ** 9)
    cases.append(Case("tiny-box", square, [one, (2 - e, 2 - e, 1)], expect={"kind": "polygon"}))
    hull = so.convex_hull(chroma(pentagon))
    cx, cy = sum(p[0] for p in hull) / 5, sum(p[1] for p in hull) / 5
    d = Fr(1, 10 ** 9)
    cases.append(Case("tiny-pentagon", pentagon,
                      [(cx + (1 - d) * (x - cx), cy + (1 - d) * (y - cy), 1) for x, y in hull],
                      expect={"kind": "polygon"}))
    # Far-out maps (large coordinates): image chromaticities much smaller than canonical ones.
    cases.append(Case("far-out-maps", pentagon, [(1, 1, 10 ** 6), (13, 12, 10 ** 7)]))
    # Zero chromaticity components (allowed; constraints through the half-plane form).
    # Triangle (0,1),(2,0),(2,2); q = (0,1) forces m2 = 1, q = (1,2) then m1 = 2.
    cases.append(Case("zero-component-point", [(0, 1, 1), (2, 0, 1), (2, 2, 1)],
                      [(0, 1, 1), (1, 2, 1)], expect={"kind": "point", "max_area": (2, 1)}))
    # Unit square [0,1]^2 with q = (0,1) and (1,1): F = [0,1]^2 (touches the axes).
    cases.append(Case("zero-component-square", [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
                      [(0, 1, 1), (1, 1, 1)],
                      expect={"kind": "polygon", "area": Fr(1), "max_area": (1, 1),
                              "mean_2d": (Fr(1, 2), Fr(1, 2))}))
    # Colours with b = 0 are dropped (and counted), not errors, when others remain.
    cases.append(Case("b-zero-dropped", square + [(1, 1, 0), (0, 0, 0)], [one, (0, 5, 0)],
                      expect={"kind": "polygon", "area": Fr(1)}))
    # Exactness at extreme magnitudes: the same chromaticities written with tiny/huge channels.
    cases.append(Case("extreme-magnitudes", [(Fr(11, 10 ** 31), Fr(7, 10 ** 31), Fr(1, 10 ** 30)),
                                             (14 * 10 ** 20, 6 * 10 ** 20, 10 * 10 ** 20),
                                             (16, 9, 10)], [(Fr(1, 10 ** 40),) * 3]))
    # Largest sizes of the random generator: 40 canonical and 12 image colours.
    rng = random.Random(4012)
    big = [rand_colour(rng) for _ in range(40)]
    d = rand_colour(rng)
    cases.append(Case("largest", big, [tuple(x / dk for x, dk in zip(c, d))
                                        for c in rng.sample(big, 12)]))
    cases.append(Case("largest-single-image", big, [big[0]]))
    return cases


# --------------------------------------------------------------------------------------------
# Comparison
# --------------------------------------------------------------------------------------------

_RATIONAL_OUT = re.compile(r"-?[0-9]+(/[0-9]+)?")


def _parse_out_rational(s, where, problems):
    """Parse an output rational string; note a problem if it is not reduced 'p/q' or 'p'."""
    if not isinstance(s, str) or not _RATIONAL_OUT.fullmatch(s):
        problems.append(f"{where}: {s!r} is not a 'p/q' string")
        return None
    x = Fr(s)
    if s != so.rational_text(x):
        problems.append(f"{where}: {s!r} is not reduced/canonical (expected {so.rational_text(x)!r})")
    return x


def nearest_double(x):
    """The double nearest the mpf x (ties to even), and x's distance to the nearest midpoint
    between doubles, both decided in 80-digit arithmetic."""
    with mpmath.workdps(80):
        d = float(x)
        candidates = [math.nextafter(d, -math.inf), d, math.nextafter(d, math.inf)]
        best = min(candidates, key=lambda c: (abs(mpmath.mpf(c) - x), int(c.hex().split("p")[0][-1], 16) % 2))
        mids = [(mpmath.mpf(best) + mpmath.mpf(c)) / 2 for c in candidates if c != best]
        return best, min(abs(x - mid) for mid in mids)


def per_component_checks(r, m, true_m, eb):
    """Issue 11: error_bounds per component cover the error, error_bound is their maximum, and a
    component flagged correctly_rounded is the double nearest the oracle's value."""
    problems = []
    ebs, cr = r.get("error_bounds"), r.get("correctly_rounded")
    if not (isinstance(ebs, list) and len(ebs) == 2 and all(_is_num(x) and x >= 0 for x in ebs)):
        return [f"mean_3d.error_bounds: malformed {ebs!r}"]
    if not (isinstance(cr, list) and len(cr) == 2 and all(isinstance(x, bool) for x in cr)):
        return [f"mean_3d.correctly_rounded: malformed {cr!r}"]
    if max(ebs) != eb:
        problems.append(f"mean_3d.error_bound {eb!r} is not the larger of error_bounds {ebs!r}")
    with mpmath.workdps(80):
        mag = max(abs(true_m[k]) for k in range(2))
        oracle = mag * mpmath.mpf(10) ** -45  # the oracle's own accuracy, with margin
        for k in range(2):
            diff = abs(mpmath.mpf(m[k]) - true_m[k])
            if diff > mpmath.mpf(ebs[k]) + oracle:
                problems.append(f"mean_3d component {k}: |map - true| = {float(diff):.3e} > "
                                f"error_bounds[{k}] = {ebs[k]!r}")
            nearest, to_midpoint = nearest_double(true_m[k])
            if cr[k] and to_midpoint > oracle and m[k] != nearest:
                problems.append(f"mean_3d component {k}: flagged correctly rounded but {m[k]!r} "
                                f"is not the nearest double {nearest!r} to the true value")
            if r.get("method") == "analytic" and not cr[k]:
                problems.append(f"mean_3d component {k}: the analytic route did not certify "
                                f"correct rounding ({r.get('note')!r})")
    return problems


def _is_num(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _close_rel(approx, exact):
    return _is_num(approx) and abs(Fr(approx) - exact) <= APPROX_REL * abs(exact) + Fr(1, 10 ** 300)


def compare(oracle, got, stats):
    """List of human-readable differences between the oracle result and the binary's JSON."""
    problems = []
    ex = oracle["_exact"]
    if not isinstance(got, dict) or not isinstance(got.get("feasible_set"), dict):
        return ["output has no 'feasible_set' object"]
    fs = got["feasible_set"]
    kind = ex["kind"]
    if fs.get("kind") != kind:
        problems.append(f"kind: got {fs.get('kind')!r}, expected {kind!r}")
    verts = fs.get("vertices")
    got_v = []
    if not isinstance(verts, list) or not all(isinstance(v, list) and len(v) == 2 for v in verts):
        problems.append(f"vertices: malformed {verts!r}")
    else:
        for i, v in enumerate(verts):
            p = (_parse_out_rational(v[0], f"vertices[{i}][0]", problems),
                 _parse_out_rational(v[1], f"vertices[{i}][1]", problems))
            got_v.append(p)
        want = list(ex["vertices"])
        ok = len(got_v) == len(want)
        if ok and kind == "polygon":
            ok = any(got_v[k:] + got_v[:k] == want for k in range(len(want)))
            if not ok and any(list(reversed(got_v))[k:] + list(reversed(got_v))[:k] == want
                              for k in range(len(want))):
                problems.append("vertices: the right polygon but clockwise")
        elif ok:
            ok = set(got_v) == set(want)
        if not ok:
            problems.append("vertices differ: got "
                            + str([[so.rational_text(x) if x is not None else None for x in p]
                                   for p in got_v])
                            + ", expected " + str([[so.rational_text(x) for x in p] for p in want]))
        approx = fs.get("vertices_approx")
        if not isinstance(approx, list) or len(approx) != len(got_v):
            problems.append(f"vertices_approx: malformed or wrong length {approx!r}")
        else:
            for i, (a, p) in enumerate(zip(approx, got_v)):
                if None in p or not (isinstance(a, list) and len(a) == 2 and
                                     _close_rel(a[0], p[0]) and _close_rel(a[1], p[1])):
                    problems.append(f"vertices_approx[{i}] = {a!r} does not round vertices[{i}]")
    area = fs.get("area")
    if area != so.rational_text(ex["area"]):
        problems.append(f"area: got {area!r}, expected {so.rational_text(ex['area'])!r}")

    sel = got.get("selections")
    if kind == "empty":
        if sel not in (None, {}) and (not isinstance(sel, dict) or
                                      any(sel.get(r) is not None for r in
                                          ("max_area", "mean_2d", "mean_3d"))):
            problems.append(f"selections present for an empty feasible set: {sel!r}")
        return problems
    if not isinstance(sel, dict):
        return problems + ["selections: missing"]
    for rule in ("max_area", "mean_2d", "mean_3d"):
        r = sel.get(rule)
        if not isinstance(r, dict):
            problems.append(f"{rule}: missing")
            continue
        true_m = ex[rule]
        m = r.get("map")
        if not (isinstance(m, list) and len(m) == 2 and all(_is_num(x) for x in m)):
            problems.append(f"{rule}.map: malformed {m!r}")
            m = None
        if rule in ("max_area", "mean_2d"):
            me = r.get("map_exact")
            want = [so.rational_text(x) for x in true_m]
            if me != want:
                problems.append(f"{rule}.map_exact: got {me!r}, expected {want!r}")
            if m is not None and not (_close_rel(m[0], true_m[0]) and _close_rel(m[1], true_m[1])):
                problems.append(f"{rule}.map {m!r} is not the double of {want!r}")
        else:
            eb = r.get("error_bound")
            if r.get("method") != "analytic":
                problems.append(f"mean_3d.method: got {r.get('method')!r}, expected 'analytic'")
            if not (_is_num(eb) and eb >= 0):
                problems.append(f"mean_3d.error_bound: malformed {eb!r}")
                eb = 0.0
            if m is not None:
                with mpmath.workdps(60):
                    diff = max(abs(mpmath.mpf(m[k]) - true_m[k]) for k in range(2))
                    mag = max(abs(true_m[k]) for k in range(2))
                    tol = max(eb, 1e-300) * (1 + 1e-6) + 1e-15 * mag
                    rel = diff / mag if mag else diff
                stats["mean3d_max_rel"] = max(stats.get("mean3d_max_rel", 0.0), float(rel))
                stats["mean3d_max_bound_rel"] = max(stats.get("mean3d_max_bound_rel", 0.0),
                                                    eb / float(mag) if mag else eb)
                if diff > tol:
                    problems.append(f"mean_3d.map {m!r}: |map - true| = {float(diff):.3e} > "
                                    f"tolerance {float(tol):.3e} (error_bound {eb!r}); true = "
                                    f"({mpmath.nstr(true_m[0], 20)}, {mpmath.nstr(true_m[1], 20)})")
                problems += per_component_checks(r, m, true_m, eb)
        w = r.get("worst_case_deg")
        want_w = so.worst_case_deg(true_m, ex["vertices"])
        if not _is_num(w):
            problems.append(f"{rule}.worst_case_deg: malformed {w!r}")
        else:
            with mpmath.workdps(60):
                dw = abs(mpmath.mpf(w) - want_w)
            stats["worst_max_diff"] = max(stats.get("worst_max_diff", 0.0), float(dw))
            if dw > WORST_TOL_DEG:
                problems.append(f"{rule}.worst_case_deg: got {w!r}, expected "
                                f"{mpmath.nstr(want_w, 20)} (diff {float(dw):.3e} deg)")
    return problems


def check_expectations(case, oracle):
    """Hand-derived answers must hold for the oracle itself (guards the oracle)."""
    ex = oracle["_exact"]
    for key, want in case.expect.items():
        have = ex[key]
        if key == "mean_3d":
            good = max(abs(have[0] - want[0]), abs(have[1] - want[1])) < 1e-40
        else:
            good = have == want
        if not good:
            raise AssertionError(f"oracle disagrees with the hand-derived {key} of {case.name}: "
                                 f"{have} != {want}")


# --------------------------------------------------------------------------------------------
# Running
# --------------------------------------------------------------------------------------------


def run_binary(binary, cpath, ipath):
    try:
        p = subprocess.run([binary, "select", "--canonical", cpath, "--image", ipath, "--json"],
                           capture_output=True, timeout=TIMEOUT_S)
        return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {TIMEOUT_S} s"
    except OSError as e:
        return None, "", f"cannot run: {e}"


def oracle_for(case):
    """Oracle result from the exact colours; also checks that the written text reads back
    to the same colours (so the oracle parser and the generator agree)."""
    for colours, text in ((case.canonical, case.canonical_text), (case.image, case.image_text)):
        with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False, newline="") as f:
            f.write(text)
        try:
            read = [c for _, c in so.read_colours(f.name)]
        finally:
            os.unlink(f.name)
        assert read == colours, f"{case.name}: CSV text does not read back exactly"
    return so.select_from_chromaticities(chroma(case.canonical), chroma(case.image))


def report_failure(case, oracle, code, out, err, problems):
    print(f"FAIL {case.name}")
    for p in problems:
        print(f"  - {p}")
    for label, text in (("canonical", case.canonical_text), ("image", case.image_text)):
        ends = " (CRLF line ends)" if "\r\n" in text else ""
        print(f"  {label} CSV{ends}:\n" + "".join(f"    |{l}\n" for l in text.splitlines()))
    print("  oracle: " + json.dumps({k: v for k, v in oracle.items() if k != "_exact"}))
    print(f"  binary (exit {code}): {out[:6000]}")
    if err.strip():
        print(f"  binary stderr: {err.strip()[:2000]}")
    sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser(description="gmcc select vs the independent oracle")
    ap.add_argument("binary")
    ap.add_argument("--cases", type=int, default=300, help="random cases (default 300)")
    ap.add_argument("--seed", type=int, default=20240601)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--keep", help="write the CSVs into this directory and keep them")
    args = ap.parse_args()

    rng = random.Random(args.seed)
    cases = fixed_cases() + [random_case(rng, i) for i in range(args.cases)]

    workdir = args.keep or tempfile.mkdtemp(prefix="gmcc-select-oracle-")
    os.makedirs(workdir, exist_ok=True)
    paths = []
    for i, c in enumerate(cases):
        cp = os.path.join(workdir, f"{i:04d}-{c.name}-canonical.csv")
        ip = os.path.join(workdir, f"{i:04d}-{c.name}-image.csv")
        with open(cp, "w", newline="") as f:
            f.write(c.canonical_text)
        with open(ip, "w", newline="") as f:
            f.write(c.image_text)
        paths.append((cp, ip))

    passed = failed = 0
    kinds = {}
    stats = {}
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        runs = [pool.submit(run_binary, args.binary, cp, ip) for cp, ip in paths]
        for case, run in zip(cases, runs):
            try:
                oracle = oracle_for(case)
            except so.UndefinedResult as e:
                # Outside the contract (unbounded F or non-unique max-area): not a test.
                print(f"skip {case.name}: {e}")
                run.result()
                continue
            check_expectations(case, oracle)
            kinds[oracle["_exact"]["kind"]] = kinds.get(oracle["_exact"]["kind"], 0) + 1
            code, out, err = run.result()
            if code != 0:
                problems = [f"exit status {code} on a valid input"]
            else:
                try:
                    got = json.loads(out)
                    problems = compare(oracle, got, stats)
                except json.JSONDecodeError as e:
                    problems = [f"stdout is not one JSON document: {e}"]
            if problems:
                failed += 1
                report_failure(case, oracle, code, out, err, problems)
            else:
                passed += 1
    if not args.keep:
        for cp, ip in paths:
            os.unlink(cp)
            os.unlink(ip)
        os.rmdir(workdir)
    print("kinds:", ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())))
    if stats:
        print(f"mean_3d: max |map - true|/|true| = {stats.get('mean3d_max_rel', 0):.3e}, "
              f"max error_bound/|true| = {stats.get('mean3d_max_bound_rel', 0):.3e} "
              f"(docs/conventions.md §7 asks for 1e-15 relative); worst_case_deg max diff = "
              f"{stats.get('worst_max_diff', 0):.3e} deg")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
