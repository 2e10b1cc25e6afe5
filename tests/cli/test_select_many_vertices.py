#!/usr/bin/python3
"""`gmcc select` on a many-vertex canonical gamut (issue 13): the parabola reproducer, small.

    /usr/bin/python3 tests/cli/test_select_many_vertices.py GMCC_BINARY [N]

The canonical colours are (1 + i/N, 1 + (i/N)^2, 1), i = 0 .. N-1 (every chromaticity a vertex of
the canonical gamut), the image colours (1, 1, 1), (1.001, 1, 1), (1, 1.001, 1). The feasible
set's kind and exact vertices must equal an independent computation: the perspective
chromaticities' hull by Andrew's monotone chain and the intersection of the half-planes
(n_e * q) . m <= k_e by the angle-sorted deque method, in exact rational arithmetic (gmcc clips
a cycle line by line instead). It asserts the answer, not the time. The last line is
`N passed, N failed`; the exit status is 0 iff none failed.
"""

import collections
import functools
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as Fr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Tally  # noqa: E402


def decimal(fr):
    """The exact decimal of a fraction whose denominator divides a power of 10."""
    k = 0
    while (fr * 10**k).denominator != 1:
        k += 1
    digits = str(fr.numerator * 10**k // fr.denominator).rjust(k + 1, "0")
    return digits if k == 0 else digits[:-k] + "." + digits[-k:]


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def hull(points):
    """Strictly convex hull, counter-clockwise (Andrew's monotone chain)."""
    p = sorted(set(points))
    if len(p) < 3:
        return p
    lower, upper = [], []
    for q in p:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], q) <= 0:
            lower.pop()
        lower.append(q)
    for q in reversed(p):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], q) <= 0:
            upper.pop()
        upper.append(q)
    return lower[:-1] + upper[:-1]


def meet(l1, l2):
    (a1, b1, c1), (a2, b2, c2) = l1, l2
    w = a1 * b2 - a2 * b1
    if w == 0:
        raise AssertionError("parallel neighbours in the deque")
    return ((c1 * b2 - c2 * b1) / w, (a1 * c2 - a2 * c1) / w)


def outside(line, p):
    a, b, c = line
    return a * p[0] + b * p[1] > c


def half_plane_intersection(lines):
    """Vertices (counter-clockwise) of the bounded intersection of a*x + b*y <= c."""
    def upper(line):
        a, b, _ = line
        return 0 if b > 0 or (b == 0 and a > 0) else 1

    def by_angle(l1, l2):
        if upper(l1) != upper(l2):
            return upper(l1) - upper(l2)
        w = l1[0] * l2[1] - l2[0] * l1[1]
        return -1 if w > 0 else (1 if w < 0 else 0)

    # One line per normal direction: the tightest (c over the normal's L1 length, smallest).
    tight = {}
    for a, b, c in lines:
        n = abs(a) + abs(b)
        key = (Fr(a, 1) / n, Fr(b, 1) / n)
        if key not in tight or c / n < tight[key][2] / n:
            tight[key] = (a, b, c)
    ordered = sorted(tight.values(), key=functools.cmp_to_key(by_angle))
    dq = collections.deque()
    for line in ordered:
        while len(dq) >= 2 and outside(line, meet(dq[-1], dq[-2])):
            dq.pop()
        while len(dq) >= 2 and outside(line, meet(dq[0], dq[1])):
            dq.popleft()
        dq.append(line)
    while len(dq) >= 3 and outside(dq[0], meet(dq[-1], dq[-2])):
        dq.pop()
    while len(dq) >= 3 and outside(dq[-1], meet(dq[0], dq[1])):
        dq.popleft()
    ring = list(dq)
    points = [meet(ring[i], ring[(i + 1) % len(ring)]) for i in range(len(ring))]
    # Lines through a vertex of F leave repeats; keep the strict vertices.
    out = []
    for p in points:
        if not out or out[-1] != p:
            out.append(p)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    n = len(out)
    return [out[i] for i in range(n) if cross(out[i - 1], out[i], out[(i + 1) % n]) != 0]


def expected_feasible_set(canonical, image):
    g = hull([(r / b, g / b) for r, g, b in canonical])
    q = hull([(r / b, g / b) for r, g, b in image])
    lines = []
    for i, p in enumerate(g):
        s = g[(i + 1) % len(g)]
        a, b = s[1] - p[1], p[0] - s[0]  # outward normal of the CCW edge p -> s
        c = a * p[0] + b * p[1]
        lines += [(a * q1, b * q2, c) for q1, q2 in q]
    v = half_plane_intersection(lines)
    start = min(range(len(v)), key=lambda i: v[i])
    return len(g), v[start:] + v[:start]


def main():
    binary = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
    canonical = [(1 + Fr(i, n), 1 + Fr(i, n) ** 2, Fr(1)) for i in range(n)]
    image = [(Fr(1), Fr(1), Fr(1)), (Fr(1001, 1000), Fr(1), Fr(1)), (Fr(1), Fr(1001, 1000), Fr(1))]
    tally = Tally()

    def check(name, cond, what=""):
        tally.check(cond, name, what)

    with tempfile.TemporaryDirectory() as tmp:
        paths = []
        for name, colours in (("canonical.csv", canonical), ("image.csv", image)):
            path = os.path.join(tmp, name)
            with open(path, "w") as f:
                f.write("".join(",".join(decimal(x) for x in c) + "\n" for c in colours))
            paths.append(path)
        p = subprocess.run([binary, "select", "--canonical", paths[0], "--image", paths[1], "--json"],
                           capture_output=True, text=True, timeout=120)
        check("exit status", p.returncode == 0, p.stderr.strip())
        if p.returncode == 0:
            gamut_vertices, vertices = expected_feasible_set(canonical, image)
            check("every canonical chromaticity is a gamut vertex", gamut_vertices == n, gamut_vertices)
            fs = json.loads(p.stdout)["feasible_set"]
            check("kind", fs["kind"] == "polygon", fs["kind"])
            got = [(Fr(x), Fr(y)) for x, y in fs["vertices"]]
            check("vertex count", len(got) == len(vertices), f"{len(got)} != {len(vertices)}")
            check("exact vertices", got == vertices,
                  next((f"vertex {i}: {a} != {b}" for i, (a, b) in enumerate(zip(got, vertices)) if a != b), ""))
    return tally.finish()


if __name__ == "__main__":
    sys.exit(main())
