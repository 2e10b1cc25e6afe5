#!/usr/bin/python3
"""Self-tests of select_oracle.py: the oracle checked against hand-derived answers and against
independent brute-force routes, so that a disagreement with the C++ binary can be trusted.

    /usr/bin/python3 tests/oracle/selftest_oracle.py [--cases N] [--seed S]

Checks (each asserts; the last line is `N passed, N failed`):
* hand-derived cases: the paper's toy example (docs/derivations.md §1.5), axis-aligned boxes,
  points, segments, empty sets, zero chromaticity components;
* feasible set: line-interval method == Sutherland-Hodgman clipping of G_c / q (the production
  method, docs/math.md §1, re-implemented here in Fractions) on random cases with a polygon G_c,
  exactly;
  and, for polygon, segment and point gamuts alike, membership of random rational maps by the
  definition (diag(m) q in G_c for every q) == membership in F;
* max-area: no sampled point of F (boundary and interior) has a larger product
  (docs/derivations.md §2);
* 3-D mean: Arvo closed form == weighted planar centroid with w = (1+a^2+b^2)^-2 integrated by
  mpmath quadrature over a fan triangulation (docs/derivations.md §1.3), and == a thin-polygon
  limit check;
* worst-case angle: the vertex maximum >= a dense boundary sample (docs/derivations.md §3.1).
"""

import argparse
import os
import random
import sys
from fractions import Fraction as Fr

import mpmath

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import select_oracle as so  # noqa: E402

PASSED = 0
FAILED = 0


def check(cond, what):
    global PASSED, FAILED
    if cond:
        PASSED += 1
    else:
        FAILED += 1
        print("FAIL:", what)


# ---------------------------------------------------------------- hand-derived answers

def hand_cases():
    # The paper's toy example: canonical (3,2,1), (1,2,3); image white.  F is the segment
    # (1/3,2/3)-(3,2); max-area (3,2); 2-D mean (5/3,4/3); 3-D mean (1,1)
    # (docs/derivations.md §1.5).
    r = so.select_from_chromaticities([(Fr(3), Fr(2)), (Fr(1, 3), Fr(2, 3))], [(Fr(1), Fr(1))])
    e = r["_exact"]
    check(e["kind"] == "segment" and set(e["vertices"]) == {(3, 2), (Fr(1, 3), Fr(2, 3))},
          f"toy F {e['vertices']}")
    check(e["max_area"] == (3, 2), f"toy max_area {e['max_area']}")
    check(e["mean_2d"] == (Fr(5, 3), Fr(4, 3)), f"toy mean_2d {e['mean_2d']}")
    check(max(abs(e["mean_3d"][0] - 1), abs(e["mean_3d"][1] - 1)) < 1e-50,
          f"toy mean_3d {e['mean_3d']}")

    # G_c = [1,2]^2, image q = (1,1) and (2,2): F = [1,2]^2 n [1/2,1]^2 = the point (1,1).
    sq = [(Fr(1), Fr(1)), (Fr(2), Fr(1)), (Fr(2), Fr(2)), (Fr(1), Fr(2))]
    e = so.select_from_chromaticities(sq, [(Fr(1), Fr(1)), (Fr(2), Fr(2))])["_exact"]
    check(e["kind"] == "point" and e["vertices"] == [(1, 1)], f"box point {e}")
    # q = (1,1) and (3/2,3/2): F = [1,4/3]^2, area 1/9, centroid (7/6,7/6), max-area (4/3,4/3).
    e = so.select_from_chromaticities(sq, [(Fr(1), Fr(1)), (Fr(3, 2), Fr(3, 2))])["_exact"]
    check(e["kind"] == "polygon" and e["area"] == Fr(1, 9), f"box area {e}")
    check(e["vertices"] == [(1, 1), (Fr(4, 3), 1), (Fr(4, 3), Fr(4, 3)), (1, Fr(4, 3))],
          f"box vertices {e['vertices']}")
    check(e["mean_2d"] == (Fr(7, 6), Fr(7, 6)) and e["max_area"] == (Fr(4, 3), Fr(4, 3)),
          f"box selections {e}")
    # q = (1,1) and (2,1): F = [1,1] x [1,2] -> segment (1,1)-(1,2); max-area (1,2).
    e = so.select_from_chromaticities(sq, [(Fr(1), Fr(1)), (Fr(2), Fr(1))])["_exact"]
    check(e["kind"] == "segment" and set(e["vertices"]) == {(1, 1), (1, 2)}, f"box segment {e}")
    check(e["max_area"] == (1, 2) and e["mean_2d"] == (1, Fr(3, 2)), f"box segment sel {e}")
    # q = (1,1) and (3,3): F empty.
    e = so.select_from_chromaticities(sq, [(Fr(1), Fr(1)), (Fr(3), Fr(3))])["_exact"]
    check(e["kind"] == "empty" and e["vertices"] == [], f"box empty {e}")
    # Single canonical and single image chromaticity: F = the point c / q.
    e = so.select_from_chromaticities([(Fr(1, 3), Fr(2, 3))], [(Fr(3, 7), Fr(1, 7))])["_exact"]
    check(e["kind"] == "point" and e["vertices"] == [(Fr(7, 9), Fr(14, 3))], f"point {e}")
    # Canonical point, two different image chromaticities: empty.
    e = so.select_from_chromaticities([(Fr(1), Fr(1))], [(Fr(1), Fr(1)), (Fr(1), Fr(2))])
    check(e["_exact"]["kind"] == "empty", "canonical point, two image q")
    # Max-area in an edge interior: triangle (0,2),(2,0),(0,0)... kept positive:
    # G_c = triangle (1,5),(5,1),(1,1), q = (1,1): F = G_c, max ab on a + b = 6 at (3,3).
    tri = [(Fr(1), Fr(5)), (Fr(5), Fr(1)), (Fr(1), Fr(1))]
    e = so.select_from_chromaticities(tri, [(Fr(1), Fr(1))])["_exact"]
    check(e["max_area"] == (3, 3), f"edge-interior max-area {e['max_area']}")
    check(e["mean_2d"] == (Fr(7, 3), Fr(7, 3)), f"triangle centroid {e['mean_2d']}")
    # Zero components: G_c = triangle (0,1),(2,0),(2,2); q = (0,1) forces m2 = 1 (x1 = 0 only
    # at (0,1)); q = (1,2) then needs (m1, 2) in G_c -> m1 = 2.  F = the point (2,1).
    tri0 = [(Fr(0), Fr(1)), (Fr(2), Fr(0)), (Fr(2), Fr(2))]
    e = so.select_from_chromaticities(tri0, [(Fr(0), Fr(1)), (Fr(1), Fr(2))])["_exact"]
    check(e["kind"] == "point" and e["vertices"] == [(2, 1)], f"zero-component point {e}")
    # Unit square with q = (0,1) and (1,1): F = [0,1]^2, max-area (1,1).
    unit = [(Fr(0), Fr(0)), (Fr(1), Fr(0)), (Fr(1), Fr(1)), (Fr(0), Fr(1))]
    e = so.select_from_chromaticities(unit, [(Fr(0), Fr(1)), (Fr(1), Fr(1))])["_exact"]
    check(e["kind"] == "polygon" and e["area"] == 1 and e["max_area"] == (1, 1),
          f"unit square {e}")
    # ... and q = (0,1) alone leaves m1 free: unbounded, outside the contract.
    try:
        so.select_from_chromaticities(unit, [(Fr(0), Fr(1))])
        check(False, "unbounded F not detected")
    except so.UndefinedResult:
        check(True, "")
    # A 3-D mean on a symmetric polygon: the square centred at (0,0) would be symmetric, but maps
    # are positive; use the square [1,3]x[1,3]: by the a<->b symmetry m1 == m2, and the weight
    # pulls towards the origin, so m1 < 2.
    box = [(Fr(1), Fr(1)), (Fr(3), Fr(1)), (Fr(3), Fr(3)), (Fr(1), Fr(3))]
    e = so.select_from_chromaticities(box, [(Fr(1), Fr(1))])["_exact"]
    m = e["mean_3d"]
    check(abs(m[0] - m[1]) < 1e-50 and 1 < m[0] < 2, f"symmetric 3-D mean {m}")
    # Collinear canonical chromaticities: hull is a segment.
    col = [(Fr(1), Fr(1)), (Fr(2), Fr(2)), (Fr(3), Fr(3)), (Fr(3, 2), Fr(3, 2))]
    check(so.convex_hull(col) == [(1, 1), (3, 3)], "collinear hull")
    e = so.select_from_chromaticities(col, [(Fr(1), Fr(1)), (Fr(2), Fr(2))])["_exact"]
    check(e["kind"] == "segment" and set(e["vertices"]) == {(1, 1), (Fr(3, 2), Fr(3, 2))},
          f"collinear canonical {e}")


# ---------------------------------------------------------------- independent routes

def clip_feasible(canonical_qs, image_qs):
    """Sutherland-Hodgman: G_c / q for each image-hull vertex q, clipped in turn (positive q,
    polygon G_c only).  Returns the exact hull of the result."""
    gc = so.convex_hull(canonical_qs)
    hull_q = so.convex_hull(image_qs)
    poly = [(x / hull_q[0][0], y / hull_q[0][1]) for x, y in gc]
    for q in hull_q[1:]:
        clip = [(x / q[0], y / q[1]) for x, y in gc]  # still CCW (positive diagonal scaling)
        for i in range(len(clip)):
            a, b = clip[i], clip[(i + 1) % len(clip)]
            out = []
            for j in range(len(poly)):
                p, r = poly[j], poly[(j + 1) % len(poly)]
                sp, sr = so._cross(a, b, p), so._cross(a, b, r)
                if sp >= 0:
                    out.append(p)
                if (sp > 0 > sr) or (sp < 0 < sr):
                    t = sp / (sp - sr)
                    out.append((p[0] + t * (r[0] - p[0]), p[1] + t * (r[1] - p[1])))
            poly = out
            if not poly:
                return []
    return so.convex_hull(poly)


def rand_q(rng):
    return (Fr(rng.randint(1, 60), rng.randint(1, 9)), Fr(rng.randint(1, 60), rng.randint(1, 9)))


def random_case(rng):
    u = rng.random()
    if u < 0.15:  # canonical gamut a point (possibly repeated)
        canon = [rand_q(rng)] * rng.randint(1, 3)
    elif u < 0.3:  # canonical gamut a segment
        a, b = rand_q(rng), rand_q(rng)
        canon = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                 for t in (Fr(0), Fr(1), Fr(rng.randint(0, 6), 6))]
    else:
        canon = [rand_q(rng) for _ in range(rng.randint(3, 25))]
    d = (Fr(rng.randint(1, 30), rng.randint(1, 10)), Fr(rng.randint(1, 30), rng.randint(1, 10)))
    image = [(x / d[0], y / d[1]) for x, y in rng.sample(canon, rng.randint(1, min(8, len(canon))))]
    if rng.random() < 0.5:
        image = [(x * Fr(rng.randint(7, 13), 10), y * Fr(rng.randint(7, 13), 10)) for x, y in image]
    return canon, image


def route_checks(rng, ncases):
    kinds = {}
    for _ in range(ncases):
        canon, image = random_case(rng)
        r = so.select_from_chromaticities(canon, image)
        e = r["_exact"]
        kinds[e["kind"]] = kinds.get(e["kind"], 0) + 1
        if len(so.convex_hull(canon)) >= 3:
            clipped = clip_feasible(canon, image)
            check(clipped == e["vertices"], f"clip {clipped} != lines {e['vertices']}")
        gc = so.convex_hull(canon)
        fhull = e["vertices"]

        def in_f_by_definition(m):
            return all(so.contains(gc, (m[0] * q[0], m[1] * q[1])) for q in image)

        # Sample maps: near each vertex, and random maps in F's bounding box (or near d).
        samples = []
        box = fhull if fhull else [(Fr(1), Fr(1))]
        xs, ys = [v[0] for v in box], [v[1] for v in box]
        for _ in range(25):
            samples.append((min(xs) + (max(xs) - min(xs) + Fr(1, 50)) * Fr(rng.randint(-5, 105), 100),
                            min(ys) + (max(ys) - min(ys) + Fr(1, 50)) * Fr(rng.randint(-5, 105), 100)))
        for v in fhull:
            samples.append(v)
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    samples.append((v[0] + Fr(dx, 10**6), v[1] + Fr(dy, 10**6)))
        inside_f = (lambda m: bool(fhull) and so.contains(fhull, m))
        for m in samples:
            check(in_f_by_definition(m) == inside_f(m), f"membership of {m}: F={fhull}")
        if e["kind"] == "empty":
            continue
        # Max-area: no sampled point of F beats the exact maximiser.
        best = e["max_area"][0] * e["max_area"][1]
        check(so.contains(fhull, e["max_area"]), "max-area outside F")
        n = len(fhull)
        for i in range(n):
            p, q = fhull[i], fhull[(i + 1) % n]
            for k in range(0, 201):
                t = Fr(k, 200)
                x = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
                check(x[0] * x[1] <= best, f"max-area beaten at {x}")
        # Worst-case angle: the vertex maximum dominates the boundary.
        for name in ("max_area", "mean_2d", "mean_3d"):
            m = e[name]
            w = so.worst_case_deg(m, fhull)
            ok = True
            mpmath.mp.dps = 60  # compare at the oracle's precision (restored below)
            for i in range(n):
                p, q = fhull[i], fhull[(i + 1) % n]
                for k in range(0, 41):
                    t = Fr(k, 40)
                    if so.angle_deg(m, (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))) > w + 1e-40:
                        ok = False
            mpmath.mp.dps = 15
            check(ok, f"worst-case {name} exceeded on the boundary")
        check(so.contains(fhull, e["mean_2d"]), "mean_2d outside F")
    return kinds


def weighted_centroid_quadrature(vertices, dps=30):
    """docs/derivations.md §1.3: m = int (a,b) w / int w, w = (1+a^2+b^2)^-2, over a fan
    triangulation, each triangle by mpmath.quad on the unit square through the Duffy map."""
    with mpmath.workdps(dps):
        v = [(so._mpf(x), so._mpf(y)) for x, y in vertices]
        num = [mpmath.mpf(0), mpmath.mpf(0)]
        den = mpmath.mpf(0)
        for i in range(1, len(v) - 1):
            a, b, c = v[0], v[i], v[i + 1]
            jac = abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

            def point(u, s):
                t = s * (1 - u)
                return (a[0] + u * (b[0] - a[0]) + t * (c[0] - a[0]),
                        a[1] + u * (b[1] - a[1]) + t * (c[1] - a[1]))

            def f(k):
                def g(u, s):
                    x, y = point(u, s)
                    w = (1 + x * x + y * y) ** -2 * (1 - u) * jac
                    return w if k < 0 else w * (x, y)[k]
                return mpmath.quad(g, [0, 1], [0, 1])

            den += f(-1)
            num[0] += f(0)
            num[1] += f(1)
        return (num[0] / den, num[1] / den)


def mean3d_checks(rng, ncases):
    for _ in range(ncases):
        canon, image = random_case(rng)
        e = so.select_from_chromaticities(canon, image)["_exact"]
        if e["kind"] != "polygon":
            continue
        m = e["mean_3d"]
        mq = weighted_centroid_quadrature(e["vertices"])
        err = max(abs(m[0] - mq[0]), abs(m[1] - mq[1]))
        check(err < 1e-12 * max(1, abs(m[0]), abs(m[1])), f"Arvo vs quadrature: {err}")
    # The (1.1, 0.7) 5-gon family of the conditioning tests (docs/derivations.md §1.6)
    # scaled to width 1e-9: the 3-D mean approaches the 2-D mean of a tiny polygon
    # and Arvo at high precision must match the quadrature written in offsets.
    base = [(Fr(0), Fr(0)), (Fr(3), Fr(-1)), (Fr(5), Fr(2)), (Fr(2), Fr(5)), (Fr(-1), Fr(3))]
    for width in (Fr(1, 100), Fr(1, 10**6), Fr(1, 10**9)):
        poly = so.convex_hull([(Fr(11, 10) + width * x / 5, Fr(7, 10) + width * y / 5)
                               for x, y in base])
        m, bound = so.mean_3d("polygon", poly)
        mq = weighted_centroid_quadrature(poly, dps=50)
        err = max(abs(m[0] - mq[0]), abs(m[1] - mq[1]))
        check(err < 1e-25, f"tiny polygon width {width}: Arvo vs quadrature {err}")
        check(bound < 1e-40, f"tiny polygon bound {bound}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", type=int, default=60)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    hand_cases()
    kinds = route_checks(rng, args.cases)
    print("kinds of random cases:", kinds)
    mean3d_checks(rng, max(3, args.cases // 10))
    print(f"{PASSED} passed, {FAILED} failed")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
