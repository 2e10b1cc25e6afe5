#!/usr/bin/python3
"""Independent reference implementation (test oracle) of `gmcc select`.

Written from the contract and the mathematics only (docs/conventions.md, docs/math.md §1-§2,
docs/cli.md "JSON output", docs/derivations.md §1, §2 and §3.1), without looking at the C++
sources, so that it can catch their bugs.  It is meant to be slow and obviously right rather than
fast:

* every geometric quantity is an exact `fractions.Fraction` (docs/conventions.md §1);
* the feasible set is computed by a method deliberately different from the production one
  (docs/math.md §1 clips with Sutherland-Hodgman): the canonical gamut and *every* image
  chromaticity (not only the image-hull vertices) are turned into integer half-planes
  a*m1 + b*m2 <= c, and F is recovered line by line as the exact 1-D intersection
  "F restricted to each constraint line" (an interval), whose end points are the vertices of F;
* the 3-D mean is Arvo's closed form (docs/derivations.md §1.2) evaluated with mpmath at >= 60
  significant digits (more for thin polygons, docs/derivations.md §1.6), checked against a second
  evaluation with 30 more digits;
* worst-case angles (docs/derivations.md §3.1, map space) are evaluated as atan2(|a x b|, a.b) in
  mpmath.

Use it as a module (`select_from_files`, `select_from_chromaticities`) or as a command line:

    /usr/bin/python3 select_oracle.py C.csv I.csv

which prints the JSON object of docs/cli.md "JSON output" on stdout, or
`gmcc: error: FILE:LINE: what` on stderr and exit status 2 for bad input.  Only the Python 3.11
standard library and python3-mpmath.
"""

import json
import math
import re
import sys
from fractions import Fraction

import mpmath

# --------------------------------------------------------------------------------------------
# Errors
# --------------------------------------------------------------------------------------------


class InputError(Exception):
    """Bad user input (docs/cli.md "Input files"): exit status 2, one message naming the file
    and line."""

    def __init__(self, path, line, what):
        super().__init__(what)
        self.path = path
        self.line = line
        self.what = what

    def message(self):
        where = f"{self.path}:{self.line}" if self.line is not None else f"{self.path}"
        return f"gmcc: error: {where}: {self.what}"


class UndefinedResult(Exception):
    """The contract does not define an answer (e.g. unbounded F, non-unique max-area).

    The random test generator avoids such inputs; seeing this means the case is outside the
    specified domain, not that the binary is wrong."""


# --------------------------------------------------------------------------------------------
# Exact CSV reading (docs/cli.md "Input files": one colour per line `r,g,b`, optional header,
# comments, blanks, CRLF, BOM, decimals read exactly as rationals, or p/q)
# --------------------------------------------------------------------------------------------

# An unsigned decimal: "12", "12.5", "12.", ".5", optionally with an exponent ("1.5e-3").
_DECIMAL = re.compile(r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE]([+-]?[0-9]+))?")
# An unsigned rational p/q with integer p and q.
_RATIONAL = re.compile(r"([0-9]+)/([0-9]+)")
# The oracle refuses absurd exponents instead of building a 10**(10**9) integer.  (The contract
# says nothing about exponent range; the tests never use exponents beyond a few hundred.)
_MAX_EXPONENT = 4000


def parse_number(field):
    """Parse one channel value exactly; raise ValueError(reason) when it is not acceptable.

    Accepted: unsigned decimal (exact, `0.1` == 1/10), `p/q` with q != 0, surrounded by spaces or
    tabs.  Rejected: empty, NaN/inf, negative values, anything else."""
    s = field.strip(" \t")
    if s == "":
        raise ValueError("empty field")
    body = s[1:] if s[0] in "+-" else s
    if body.lower() in ("nan", "inf", "infinity"):
        raise ValueError(f"'{s}' is not a finite number")
    m = _DECIMAL.fullmatch(body)
    if m:
        if m.group(1) is not None and abs(int(m.group(1))) > _MAX_EXPONENT:
            raise ValueError(f"exponent out of range in '{s}'")
        value = Fraction(body)
    else:
        m = _RATIONAL.fullmatch(body)
        if not m:
            raise ValueError(f"malformed number '{s}'")
        if int(m.group(2)) == 0:
            raise ValueError(f"zero denominator in '{s}'")
        value = Fraction(int(m.group(1)), int(m.group(2)))
    if s[0] == "-" and value != 0:
        raise ValueError(f"negative value '{s}'")
    return value


def read_colours(path):
    """Read a colour CSV.  Returns [(line_number, (r, g, b))] with Fraction channels."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise InputError(path, None, f"cannot read file ({e.strerror})")
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise InputError(path, data[: e.start].count(b"\n") + 1, "not UTF-8 text")
    colours = []
    seen_content = False
    # Only '\n' ends a line (str.splitlines would also split on \v, \f, U+2028, ...); a '\r'
    # before it is part of a CRLF line end.
    for number, raw in enumerate(text.split("\n"), start=1):
        line = raw[:-1] if raw.endswith("\r") else raw
        s = line.strip(" \t")
        if s == "" or s.startswith("#"):
            continue
        fields = s.split(",")
        first = not seen_content
        seen_content = True
        if first and [x.strip(" \t").lower() for x in fields] == ["r", "g", "b"]:
            continue  # the optional header line
        if len(fields) != 3:
            raise InputError(path, number,
                             f"expected 3 comma-separated values r,g,b, found {len(fields)}")
        values = []
        for name, field in zip("rgb", fields):
            try:
                values.append(parse_number(field))
            except ValueError as e:
                raise InputError(path, number, f"channel {name}: {e}")
        colours.append((number, tuple(values)))
    return colours


def chromaticities(path, colours):
    """Perspective chromaticities q = (r/b, g/b) (docs/conventions.md §2, paper eq. 10).

    Colours with b = 0 have none and are dropped (the default policy); returns (qs, dropped).
    No usable colour at all is bad input (docs/conventions.md §2)."""
    qs = [(r / b, g / b) for _, (r, g, b) in colours if b > 0]
    dropped = len(colours) - len(qs)
    if not qs:
        what = ("no colour in the file" if not colours else
                f"no usable colour: all {len(colours)} colours have b = 0")
        raise InputError(path, None, what)
    return qs, dropped


# --------------------------------------------------------------------------------------------
# Exact planar geometry
# --------------------------------------------------------------------------------------------


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def convex_hull(points):
    """Exact convex hull (Andrew's monotone chain).  Extreme points only, counter-clockwise,
    starting at the lexicographically smallest; 1 point or the 2 end points when degenerate."""
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    if len(hull) == 2 and hull[0] == hull[1]:
        return hull[:1]
    return hull


def halfplanes_of_hull(hull):
    """Half-plane form {x : a.x <= c} of a convex hull given by `convex_hull`.

    A polygon gives one half-plane per edge.  A segment AB has no polygon half-plane form, but
    it is the intersection of the two half-planes n.x <= n.A, -n.x <= -n.A of its line with the
    slab d.A <= d.x <= d.B (d = B - A); a point A is the intersection of x1 <= A1, x1 >= A1,
    x2 <= A2, x2 >= A2.  So every gamut, degenerate or not, is a finite set of half-planes."""
    if len(hull) == 1:
        (x, y), = hull
        return [((1, 0), x), ((-1, 0), -x), ((0, 1), y), ((0, -1), -y)]
    if len(hull) == 2:
        a, b = hull
        d = (b[0] - a[0], b[1] - a[1])
        n = (d[1], -d[0])
        na = n[0] * a[0] + n[1] * a[1]
        return [(n, na), ((-n[0], -n[1]), -na),
                (d, d[0] * b[0] + d[1] * b[1]), ((-d[0], -d[1]), -(d[0] * a[0] + d[1] * a[1]))]
    planes = []
    for i, p in enumerate(hull):
        q = hull[(i + 1) % len(hull)]
        dx, dy = q[0] - p[0], q[1] - p[1]
        # Counter-clockwise polygon: the interior is on the left, the outward normal (dy, -dx).
        planes.append(((dy, -dx), dy * p[0] - dx * p[1]))
    return planes


def _integer_constraint(a, b, c):
    """Scale a*m1 + b*m2 <= c (Fractions) to coprime integers, preserving the inequality."""
    den = math.lcm(Fraction(a).denominator, Fraction(b).denominator, Fraction(c).denominator)
    ia, ib, ic = int(a * den), int(b * den), int(c * den)
    g = math.gcd(ia, ib, ic) or 1
    return ia // g, ib // g, ic // g


def map_constraints(canonical_hull, image_qs):
    """All constraints on the map m (docs/math.md §1): for every image chromaticity q and
    every half-plane n.x <= c of G_c, (m1 q1, m2 q2) in G_c gives (n1 q1) m1 + (n2 q2) m2 <= c.

    Written through the half-plane form it also covers q with a zero component, where "G_c
    divided by q" is undefined.  Returns (constraints, infeasible) with constraints a set of
    coprime integer triples (a, b, c), (a, b) != (0, 0); infeasible is True when some constraint
    reads 0 <= c with c < 0."""
    cons = set()
    infeasible = False
    for (n1, n2), c in halfplanes_of_hull(canonical_hull):
        for q1, q2 in set(image_qs):
            a, b, k = _integer_constraint(n1 * q1, n2 * q2, c)
            if a == 0 and b == 0:
                infeasible |= k < 0
            else:
                cons.add((a, b, k))
    return sorted(cons), infeasible


def feasible_points(constraints):
    """Vertices (as a point set) of the polyhedron {m : a m1 + b m2 <= c for all constraints}.

    Method: for each constraint line L_i, parameterise L_i by s = d_i.m with d_i = (-b_i, a_i);
    every other constraint j bounds s above (D_ij > 0), below (D_ij < 0) or is parallel
    (D_ij = 0: all of L_i is inside it or none is), with D_ij = a_i b_j - a_j b_i and bound
    num_ij / D_ij, num_ij = c_j |n_i|^2 - c_i (n_i.n_j).  The exact interval F n L_i is found in
    integer arithmetic.  A non-empty bounded F has its boundary on the lines, so the interval end
    points include every vertex of F; an unbounded interval means F contains a ray.

    Raises UndefinedResult when F is unbounded."""
    if not constraints:
        raise UndefinedResult("feasible set is unbounded (no constraint)")
    points = set()
    for i, (ai, bi, ci) in enumerate(constraints):
        nn = ai * ai + bi * bi
        lo = hi = None  # (numerator, positive denominator) of the bounds on s
        empty = False
        for j, (aj, bj, cj) in enumerate(constraints):
            if j == i:
                continue
            d = ai * bj - aj * bi
            num = cj * nn - ci * (ai * aj + bi * bj)
            if d == 0:
                if num < 0:  # parallel and L_i entirely outside half-plane j
                    empty = True
                    break
                continue
            if d > 0:
                if hi is None or num * hi[1] < hi[0] * d:
                    hi = (num, d)
            else:
                num, d = -num, -d
                if lo is None or num * lo[1] > lo[0] * d:
                    lo = (num, d)
            if lo is not None and hi is not None and lo[0] * hi[1] > hi[0] * lo[1]:
                empty = True
                break
        if empty:
            continue
        if lo is None or hi is None:
            raise UndefinedResult("feasible set is unbounded")
        for num, d in (lo, hi):
            s = Fraction(num, d)
            points.add(((ci * ai - s * bi) / nn, (ci * bi + s * ai) / nn))
    return points


def feasible_set(canonical_qs, image_qs):
    """F = {m in R^2 : (m1 q1, m2 q2) in G_c for every image chromaticity q}, exactly.

    Returns (kind, vertices) with vertices counter-clockwise (polygon), the two end points
    (segment), one point, or none (empty)."""
    cons, infeasible = map_constraints(convex_hull(canonical_qs), image_qs)
    if infeasible:
        return "empty", []
    hull = convex_hull(feasible_points(cons))
    kind = {0: "empty", 1: "point", 2: "segment"}.get(len(hull), "polygon")
    return kind, hull


def contains(polygon_or_degenerate, x):
    """Exact test x in hull (hull from `convex_hull`, any kind).  Used by the self-tests."""
    return all(n[0] * x[0] + n[1] * x[1] <= c
               for n, c in halfplanes_of_hull(polygon_or_degenerate))


# --------------------------------------------------------------------------------------------
# Selection rules (docs/math.md §2)
# --------------------------------------------------------------------------------------------


def area_and_centroid(vertices):
    """Exact area and area centroid of a CCW polygon (shoelace)."""
    a2 = Fraction(0)
    cx = cy = Fraction(0)
    n = len(vertices)
    for i in range(n):
        (x0, y0), (x1, y1) = vertices[i], vertices[(i + 1) % n]
        w = x0 * y1 - x1 * y0
        a2 += w
        cx += (x0 + x1) * w
        cy += (y0 + y1) * w
    return a2 / 2, (cx / (3 * a2), cy / (3 * a2))


def mean_2d(kind, vertices):
    """Barnard's 2-D mean: area centroid of F; segment: midpoint; point: itself
    (docs/math.md §2)."""
    if kind == "polygon":
        return area_and_centroid(vertices)[1]
    if kind == "segment":
        (a, b) = vertices
        return ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    return vertices[0]


def max_area(kind, vertices):
    """argmax m1*m2 over F by exact candidate enumeration (docs/derivations.md §2.3): every
    vertex, plus on each edge p + t(q - p) with da*db < 0 the stationary point
    t* = -(da*p_b + db*p_a) / (2 da db) when 0 < t* < 1.

    Raises UndefinedResult if the maximiser is not unique (only possible when max = 0, i.e. F on
    an axis, outside the open positive quadrant docs/derivations.md §2.1 assumes)."""
    candidates = list(vertices)
    if kind == "polygon":
        edges = [(vertices[i], vertices[(i + 1) % len(vertices)]) for i in range(len(vertices))]
    elif kind == "segment":
        edges = [tuple(vertices)]
    else:
        edges = []
    for p, q in edges:
        da, db = q[0] - p[0], q[1] - p[1]
        if da * db < 0:
            t = -(da * p[1] + db * p[0]) / (2 * da * db)
            if 0 < t < 1:
                candidates.append((p[0] + t * da, p[1] + t * db))
    best = max(x * y for x, y in candidates)
    winners = {c for c in candidates if c[0] * c[1] == best}
    if len(winners) != 1:
        raise UndefinedResult(f"max-area maximiser not unique ({len(winners)} points, max {best})")
    return winners.pop()


def _lift(v):
    return (Fraction(v[0]), Fraction(v[1]), Fraction(1))


def _cross3(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _dot3(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def _mpf(x):
    """Fraction -> mpf at the current precision (rounded once)."""
    return mpmath.mpf(x.numerator) / x.denominator if isinstance(x, Fraction) else mpmath.mpf(x)


def _arvo_map(vertices, dps):
    """3-D mean of a CCW polygon by Arvo's formula (docs/derivations.md §1.2) at `dps` digits:
    tau = 1/2 sum_i theta_i (u_i x u_{i+1}) / |u_i x u_{i+1}|, theta_i = atan2(|c_i|, u_i.u_{i+1}),
    u_i = (a_i, b_i, 1) unnormalised; c_i and u_i.u_{i+1} are exact rationals fed to mpmath.
    Orientation (docs/derivations.md §1.4): with the lift (a, b, 1) a CCW polygon is CCW from
    outside, so the sum is taken as is; the sign is checked through tau_3 > 0 (tau_3 =
    Omega-weighted > 0)."""
    with mpmath.workdps(dps):
        tau = [mpmath.mpf(0)] * 3
        n = len(vertices)
        for i in range(n):
            u, v = _lift(vertices[i]), _lift(vertices[(i + 1) % n])
            c = _cross3(u, v)
            norm = mpmath.sqrt(_mpf(_dot3(c, c)))
            theta = mpmath.atan2(norm, _mpf(_dot3(u, v)))
            for k in range(3):
                tau[k] += theta * _mpf(c[k]) / norm
        if not tau[2] > 0:
            raise AssertionError("Arvo sum has the wrong orientation")
        return (tau[0] / tau[2], tau[1] / tau[2])


def mean_3d(kind, vertices):
    """Finlayson & Hordley's 3-D mean (docs/math.md §2, docs/derivations.md §1).  Returns
    ((m1, m2) as mpf, error_bound).

    polygon: Arvo's closed form at 60 + guard digits, where the guard grows with the thinness
    perimeter/area (the edge sum cancels like u/width, docs/derivations.md §1.6); the result is
    recomputed with 30 more digits and the difference (plus a margin) is the stated error bound.
    segment: perspective of u1/|u1| + u2/|u2| (bisector of the fan, docs/derivations.md §1.5).
    point: itself (exact, error bound 0)."""
    if kind == "point":
        return (_mpf(vertices[0][0]), _mpf(vertices[0][1])), 0.0
    if kind == "segment":
        with mpmath.workdps(80):
            s = [mpmath.mpf(0)] * 3
            for v in vertices:
                u = [_mpf(x) for x in _lift(v)]
                r = mpmath.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
                s = [s[k] + u[k] / r for k in range(3)]
            return (s[0] / s[2], s[1] / s[2]), 1e-60
    area = area_and_centroid(vertices)[0]
    perimeter = sum(math.hypot(float(vertices[i][0] - vertices[i - 1][0]),
                               float(vertices[i][1] - vertices[i - 1][1]))
                    for i in range(len(vertices)))
    scale = max(1.0, max(abs(float(x)) for v in vertices for x in v))
    # The terms are O(perimeter) and tau is O(area): relative cancellation perimeter/area.
    thin = perimeter / float(area)
    guard = max(0, math.ceil(math.log10(thin))) + max(0, math.ceil(2 * math.log10(scale)))
    dps = 60 + guard
    m = _arvo_map(vertices, dps)
    check = _arvo_map(vertices, dps + 30)
    with mpmath.workdps(dps + 30):
        diff = max(abs(m[k] - check[k]) for k in range(2))
        mag = max(abs(check[k]) for k in range(2))
        if diff > mag * mpmath.mpf(10) ** (-50):
            raise AssertionError(f"3-D mean not stable under more precision (diff {diff})")
    return check, float(diff) + 1e-55 * float(mag)


def angle_deg(m, v):
    """Angle in degrees between (m, 1) and (v, 1) (docs/derivations.md §3.1, map space), atan2
    form (no acos cancellation near 0), evaluated at 60 digits from the exact or mpf inputs."""
    with mpmath.workdps(60):
        a = [_mpf(m[0]), _mpf(m[1]), mpmath.mpf(1)]
        b = [_mpf(v[0]), _mpf(v[1]), mpmath.mpf(1)]
        c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        s = mpmath.sqrt(c[0] ** 2 + c[1] ** 2 + c[2] ** 2)
        return mpmath.degrees(mpmath.atan2(s, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]))


def worst_case_deg(m, vertices):
    """Worst-case map angular error: max over the vertices of F (docs/derivations.md §3.1,
    quasi-convexity)."""
    return max(angle_deg(m, v) for v in vertices)


# --------------------------------------------------------------------------------------------
# The whole `select` computation and its JSON (docs/cli.md "JSON output")
# --------------------------------------------------------------------------------------------


def rational_text(x):
    """Reduced 'p/q', or 'p' for an integer (docs/cli.md "JSON output")."""
    x = Fraction(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def select_from_chromaticities(canonical_qs, image_qs):
    """The `gmcc select` result (a dict shaped like the JSON of docs/cli.md "JSON output") from
    chromaticities.

    Exact values are kept beside the JSON under the key "_exact" (Fractions / mpf) for the
    drivers; `to_json` drops it."""
    kind, verts = feasible_set(canonical_qs, image_qs)
    area = area_and_centroid(verts)[0] if kind == "polygon" else Fraction(0)
    result = {
        "feasible_set": {
            "kind": kind,
            "vertices": [[rational_text(x), rational_text(y)] for x, y in verts],
            "vertices_approx": [[float(x), float(y)] for x, y in verts],
            "area": rational_text(area),
        },
    }
    exact = {"kind": kind, "vertices": verts, "area": area}
    if kind != "empty":
        sel = {}
        for name, rule in (("max_area", max_area), ("mean_2d", mean_2d)):
            m = rule(kind, verts)
            sel[name] = {"map": [float(m[0]), float(m[1])],
                         "map_exact": [rational_text(m[0]), rational_text(m[1])],
                         "worst_case_deg": float(worst_case_deg(m, verts))}
            exact[name] = m
        m3, bound = mean_3d(kind, verts)
        sel["mean_3d"] = {"map": [float(m3[0]), float(m3[1])], "error_bound": bound,
                          "method": "analytic",
                          "worst_case_deg": float(worst_case_deg(m3, verts))}
        exact["mean_3d"] = m3
        result["selections"] = sel
    result["_exact"] = exact
    return result


def select_from_files(canonical_path, image_path):
    """Read both CSVs (InputError on bad input) and run `select_from_chromaticities`."""
    cq, cdrop = chromaticities(canonical_path, read_colours(canonical_path))
    iq, idrop = chromaticities(image_path, read_colours(image_path))
    result = select_from_chromaticities(cq, iq)
    result["dropped"] = {"canonical": cdrop, "image": idrop}
    return result


def to_json(result):
    return json.dumps({k: v for k, v in result.items() if k != "_exact"}, indent=2)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: select_oracle.py CANONICAL.csv IMAGE.csv\n")
        return 2
    try:
        result = select_from_files(argv[1], argv[2])
    except InputError as e:
        sys.stderr.write(e.message() + "\n")
        return 2
    print(to_json(result))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
