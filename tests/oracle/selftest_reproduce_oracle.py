#!/usr/bin/python3
"""Brute-force self-test of reproduce_oracle.py's geometry (standard library only).

For random scenes of the synthetic experiment it rasterises the feasible set on a
fine grid, straight from the definition (m is feasible iff (m1 q1, m2 q2) lies in
the canonical hull for every image chromaticity q), and compares with the
oracle's clipped polygon: area, area centroid (mean_2d), the centroid weighted by
(1 + a^2 + b^2)^-2 (docs/derivations.md §1.3, = mean_3d), max of m1 m2 (max_area) and the
worst-case angle.  Also checks the computed daylights against the CIE table and
that the true map is feasible.  Exit 0 iff all checks pass.

    selftest_reproduce_oracle.py [--scenes 12] [--grid 400]
"""

import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reproduce_oracle as ro  # noqa: E402


def inside_convex(poly, x, y):
    k = len(poly)
    for i in range(k):
        a, b = poly[i], poly[(i + 1) % k]
        if (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) < 0:
            return False
    return True


def brute(exp, qs, poly, grid):
    xs = [p[0] for p in poly]
    ys = [p[1] for p in poly]
    pad = 0.02
    x0, x1 = min(xs), max(xs)
    y0, y1 = min(ys), max(ys)
    dx0, dy0 = (x1 - x0) * pad + 1e-9, (y1 - y0) * pad + 1e-9
    x0, x1, y0, y1 = x0 - dx0, x1 + dx0, y0 - dy0, y1 + dy0
    hx, hy = (x1 - x0) / grid, (y1 - y0) / grid
    g = exp.gamut.verts
    n = 0
    sx = sy = 0.0
    w = wx = wy = 0.0
    best = -1.0
    for i in range(grid):
        x = x0 + (i + 0.5) * hx
        for j in range(grid):
            y = y0 + (j + 0.5) * hy
            ok = True
            for q in qs:
                if not inside_convex(g, x * q[0], y * q[1]):
                    ok = False
                    break
            if not ok:
                continue
            n += 1
            sx += x
            sy += y
            ww = (1.0 + x * x + y * y) ** -2
            w += ww
            wx += ww * x
            wy += ww * y
            best = max(best, x * y)
    cell = hx * hy
    return {"area": n * cell, "mean_2d": (sx / n, sy / n), "mean_3d": (wx / w, wy / w),
            "maxprod": best, "h": max(hx, hy)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", type=int, default=12)
    ap.add_argument("--grid", type=int, default=400)
    ap.add_argument("--seed", type=int, default=5)
    args = ap.parse_args()
    failures = 0
    worst = ro.check_illuminants(ro.DEFAULT_DATA, sys.stdout)
    if worst > 0.01:
        print("FAIL daylight vs CIE table: %g" % worst)
        failures += 1
    exp = ro.Experiment(ro.DEFAULT_DATA)
    if len(exp.gamut.verts) < 3:
        print("FAIL canonical gamut degenerate")
        return 1
    rng = random.Random(args.seed)
    for s in range(args.scenes):
        light = ro.LIGHTS[s % 4]
        n = rng.randint(1, 11)
        picks = rng.sample(range(exp.nchips), n)
        qs = [exp.image_q[light][i] for i in picks]
        poly = ro.feasible_set(exp.gamut, ro.convex_hull(qs))
        truth = exp.truth[light]
        if not inside_convex_tol(poly, truth):
            print("FAIL scene %d: true map outside F" % s)
            failures += 1
        maps = ro.select_rules(poly)
        area2, _, _, _ = ro.shoelace(poly)
        b = brute(exp, qs, poly, args.grid)
        ext = max(max(p[0] for p in poly) - min(p[0] for p in poly),
                  max(p[1] for p in poly) - min(p[1] for p in poly))
        rel_area = abs(area2 / 2 - b["area"]) / (area2 / 2)
        e2 = math.dist(maps["mean_2d"], b["mean_2d"]) / ext
        e3 = math.dist(maps["mean_3d"], b["mean_3d"]) / ext
        ma = maps["max_area"]
        ep = (ma[0] * ma[1] - b["maxprod"]) / b["maxprod"]
        ok = rel_area < 0.02 and e2 < 2e-3 and e3 < 2e-3 and -1e-12 < ep < 0.02
        print("%s scene %2d %-6s n=%2d verts=%2d area rel %.1e  mean_2d %.1e  mean_3d %.1e  "
              "max_area %.1e  (3d-2d %.3f)" % ("ok  " if ok else "FAIL", s, light, n, len(poly),
                                                rel_area, e2, e3, ep,
                                                math.dist(maps["mean_3d"], maps["mean_2d"]) / ext))
        failures += 0 if ok else 1
    print("%d failures" % failures)
    return 1 if failures else 0


def inside_convex_tol(poly, p, tol=1e-9):
    k = len(poly)
    for i in range(k):
        a, b = poly[i], poly[(i + 1) % k]
        cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        if cr < -tol * (1 + abs(a[0]) + abs(a[1])) ** 2:
            return False
    return True


if __name__ == "__main__":
    sys.exit(main())
