#!/usr/bin/python3
"""Independent oracle for the synthetic colour-constancy experiment of
Finlayson & Hordley (1999), section 4, Fig. 3.

Written from the experiment's description only (paper section 4, docs/reproduction.md §1,
docs/math.md §1-§2, docs/derivations.md §1); it shares no code with the C++ tool.  Standard library
only, double precision throughout, its own random generator.  It is meant for a
*statistical* cross-check: the scenes differ from the C++ tool's, so only the
cell means can be compared, within their sampling error.

Usage:
    reproduce_oracle.py [--scenes S] [--seed X] [--data DIR] [--lights D75,P2856]
                        [--surfaces 1-11] [--check-illuminants]

Prints a CSV on stdout with the columns
    illuminant,surfaces,rule,mean_error_deg,mean_worst_case_deg,scenes,
    sd_error_deg,sd_worst_case_deg,empty_scenes
(sd_* are sample standard deviations over the cell's scenes).  A short summary
goes to stderr.

Pipeline
  * sensors: perfectly narrow-band at 610, 540, 450 nm (r, g, b);
    colour = reflectance(lambda_k) * SPD(lambda_k);
  * canonical light D55 from the CIE daylight basis (CIE 15 method, M1 and M2
    rounded to 3 decimals) at 5500 * 1.4388/1.438 K; tests D75, D100 (same
    method), P2856, P15000 (Planck, c2 = 1.4388e-2 m K);
  * chromaticity q = (r/b, g/b); canonical gamut G = convex hull of the 1269
    chips under D55 (no expansion);
  * a scene: n distinct chips drawn uniformly (random.sample); feasible set
    F = intersection over the image-hull vertices q of G (/) q, computed by
    clipping with the half-planes of G rewritten in map coordinates:
    m in G (/) q  <=>  (m1 q1, m2 q2) in G;
  * rules: max_area (argmax m1 m2 over F: vertices and edge stationary
    points), mean_2d (area centroid), mean_3d (Arvo's closed form for the
    first moment of the cone over F cut by the unit ball, projected back to
    z = 1);
  * error: angle between (m, 1) and (m*, 1), m* = (d1/d3, d2/d3),
    d_k = D55(lambda_k)/E_test(lambda_k); worst case: largest such angle
    between m and a vertex of F.
"""

import argparse
import csv
import math
import os
import random
import statistics
import sys
from decimal import Decimal, ROUND_HALF_UP

WAVELENGTHS = (610, 540, 450)           # r, g, b
C2 = 1.4388e-2                           # m K
LIGHTS = ("D75", "D100", "P2856", "P15000")
RULES = ("max_area", "mean_2d", "mean_3d")
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DATA = os.path.normpath(os.path.join(HERE, "..", "..", "data"))


# --------------------------------------------------------------------------
# Spectral data
# --------------------------------------------------------------------------

def read_spectral_csv(path):
    """Return (column names without the wavelength, {wavelength: [values]})."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    header = rows[0][1:]
    table = {}
    for row in rows[1:]:
        if not row:
            continue
        table[int(round(float(row[0])))] = [float(v) for v in row[1:]]
    return header, table


def round3(x):
    """CIE 15 rounding of M1, M2 to three decimals (half away from zero)."""
    d = Decimal(repr(x)).quantize(Decimal("0.001"), rounding=ROUND_HALF_UP)
    return float(d)


def daylight_coefficients(cct):
    t = float(cct)
    if 4000.0 <= t <= 7000.0:
        x = -4.6070e9 / t ** 3 + 2.9678e6 / t ** 2 + 0.09911e3 / t + 0.244063
    elif 7000.0 < t <= 25000.0:
        x = -2.0064e9 / t ** 3 + 1.9018e6 / t ** 2 + 0.24748e3 / t + 0.237040
    else:
        raise ValueError("CCT out of the CIE daylight range: %r" % cct)
    y = -3.0 * x * x + 2.87 * x - 0.275
    m = 0.0241 + 0.2562 * x - 0.7341 * y
    m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m
    m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m
    return round3(m1), round3(m2)


def daylight_spd(basis, nominal):
    """CIE daylight D<nominal/100> over every wavelength of the basis table."""
    m1, m2 = daylight_coefficients(nominal * 1.4388 / 1.438)
    return {wl: s[0] + m1 * s[1] + m2 * s[2] for wl, s in basis.items()}


def planck_spd(temperature, wavelengths):
    out = {}
    for wl in wavelengths:
        lam = wl * 1e-9
        out[wl] = lam ** -5 / math.expm1(C2 / (lam * temperature))
    return out


def check_illuminants(data_dir, out=sys.stderr):
    """Compare computed D55/D65/D75 with the tabulated CIE SPDs (both scaled
    to 100 at 560 nm).  Returns the largest absolute difference."""
    _, basis = read_spectral_csv(os.path.join(data_dir, "cie_daylight_basis_S0_S1_S2.csv"))
    names, tab = read_spectral_csv(os.path.join(data_dir, "cie_illuminants_A_D50_D55_D65_D75.csv"))
    worst = 0.0
    for name, nominal in (("D50", 5000), ("D55", 5500), ("D65", 6500), ("D75", 7500)):
        col = names.index(name)
        spd = daylight_spd(basis, nominal)
        s560 = spd[560]
        t560 = tab[560][col]
        diff = 0.0
        for wl, row in tab.items():
            if wl in spd:
                diff = max(diff, abs(spd[wl] * 100.0 / s560 - row[col] * 100.0 / t560))
        at = max(abs(spd[wl] * 100.0 / s560 - tab[wl][col] * 100.0 / t560) for wl in WAVELENGTHS)
        print("# %s: max |computed - CIE table| = %.4g over 300-780 nm, %.4g at 450/540/610 nm"
              % (name, diff, at), file=out)
        worst = max(worst, diff)
    return worst


def light_rgb(name, basis):
    if name.startswith("D"):
        spd = daylight_spd(basis, int(name[1:]) * 100)
    elif name.startswith("P"):
        spd = planck_spd(float(name[1:]), WAVELENGTHS)
    else:
        raise ValueError(name)
    return tuple(spd[w] for w in WAVELENGTHS)


# --------------------------------------------------------------------------
# Planar geometry (doubles)
# --------------------------------------------------------------------------

def cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def convex_hull(points):
    """Andrew's monotone chain; counter-clockwise, collinear points dropped."""
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts
    lower = []
    for p in pts:
        while len(lower) >= 2 and cross2(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross2(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


class Gamut:
    """Canonical gamut as a CCW polygon plus its edge half-planes.

    Edge j from g_j to g_{j+1} (e = g_{j+1} - g_j): a point x is inside iff
    e1 (x2 - g_j2) - e2 (x1 - g_j1) >= 0.  For x = m (.) q this reads
        A m1 + B m2 + C >= 0,  A = -e2 q1, B = e1 q2, C = e2 g_j1 - e1 g_j2.
    """

    def __init__(self, verts):
        self.verts = verts
        self.edges = []
        k = len(verts)
        for j in range(k):
            g = verts[j]
            h = verts[(j + 1) % k]
            e1, e2 = h[0] - g[0], h[1] - g[1]
            self.edges.append((e1, e2, e2 * g[0] - e1 * g[1],
                               abs(e1 * g[1]) + abs(e2 * g[0])))


REL_EPS = 1e-12   # tolerance of a half-plane test, relative to its scale


def clip(poly, a, b, c, scale):
    """Keep the part of the convex polygon with a x + b y + c >= -eps."""
    eps = REL_EPS * scale
    out = []
    k = len(poly)
    if k == 0:
        return out
    vals = [a * p[0] + b * p[1] + c + eps for p in poly]
    if min(vals) >= 0.0:
        return poly
    if max(vals) < 0.0:
        return []
    for i in range(k):
        p, fp = poly[i], vals[i]
        j = (i + 1) % k
        qq, fq = poly[j], vals[j]
        if fp >= 0.0:
            out.append(p)
            if fq < 0.0:
                t = fp / (fp - fq)
                out.append((p[0] + t * (qq[0] - p[0]), p[1] + t * (qq[1] - p[1])))
        elif fq >= 0.0:
            t = fp / (fp - fq)
            out.append((p[0] + t * (qq[0] - p[0]), p[1] + t * (qq[1] - p[1])))
    return dedupe(out)


def dedupe(poly):
    out = []
    for p in poly:
        if out and abs(p[0] - out[-1][0]) <= 1e-15 * (abs(p[0]) + 1e-300) \
                and abs(p[1] - out[-1][1]) <= 1e-15 * (abs(p[1]) + 1e-300):
            continue
        out.append(p)
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
    return out


def feasible_set(gamut, image_qs):
    """F = intersection over q of G (/) q, as a CCW vertex list (may be [])."""
    q0 = image_qs[0]
    poly = [(g[0] / q0[0], g[1] / q0[1]) for g in gamut.verts]
    for q in image_qs[1:]:
        q1, q2 = q
        for (e1, e2, c, scale) in gamut.edges:
            poly = clip(poly, -e2 * q1, e1 * q2, c, scale)
            if not poly:
                return []
    return poly


def shoelace(poly):
    area2 = 0.0
    cx = cy = 0.0
    k = len(poly)
    x0, y0 = poly[0]
    for i in range(1, k - 1):   # fan from vertex 0, in offsets (less cancellation)
        ax, ay = poly[i][0] - x0, poly[i][1] - y0
        bx, by = poly[i + 1][0] - x0, poly[i + 1][1] - y0
        cr = ax * by - ay * bx
        area2 += cr
        cx += cr * (ax + bx)
        cy += cr * (ay + by)
    return area2, cx, cy, (x0, y0)


def diameter_pair(poly):
    best = (-1.0, poly[0], poly[0])
    for i in range(len(poly)):
        for j in range(i + 1, len(poly)):
            d = math.hypot(poly[i][0] - poly[j][0], poly[i][1] - poly[j][1])
            if d > best[0]:
                best = (d, poly[i], poly[j])
    return best


def max_area_rule(poly):
    """argmax m1 m2 over the polygon (vertices + edge stationary points)."""
    best = None
    bestv = -math.inf
    k = len(poly)
    for i in range(k):
        p = poly[i]
        v = p[0] * p[1]
        if v > bestv:
            bestv, best = v, p
        if k < 2:
            continue
        qq = poly[(i + 1) % k]
        d1, d2 = qq[0] - p[0], qq[1] - p[1]
        if d1 * d2 < 0.0:   # f(t) concave along the edge
            t = -(p[0] * d2 + p[1] * d1) / (2.0 * d1 * d2)
            if 0.0 < t < 1.0:
                s = (p[0] + t * d1, p[1] + t * d2)
                v = s[0] * s[1]
                if v > bestv:
                    bestv, best = v, s
    return best


def arvo_map(poly):
    """3-D mean by the closed form tau = 1/2 sum theta_i c_i/|c_i|."""
    t1 = t2 = t3 = 0.0
    k = len(poly)
    for i in range(k):
        a = poly[i]
        b = poly[(i + 1) % k]
        # u = (a0, a1, 1), v = (b0, b1, 1); c = u x v
        c1 = a[1] - b[1]
        c2 = b[0] - a[0]
        c3 = a[0] * b[1] - a[1] * b[0]
        cn = math.sqrt(c1 * c1 + c2 * c2 + c3 * c3)
        if cn == 0.0:
            continue
        dot = a[0] * b[0] + a[1] * b[1] + 1.0
        th = math.atan2(cn, dot)
        f = th / cn
        t1 += f * c1
        t2 += f * c2
        t3 += f * c3
    return (t1 / t3, t2 / t3)


def unit3(m):
    n = math.sqrt(m[0] * m[0] + m[1] * m[1] + 1.0)
    return (m[0] / n, m[1] / n, 1.0 / n)


def angle_deg(m, w):
    """Angle between (m, 1) and (w, 1), degrees, atan2 form."""
    a = (m[0], m[1], 1.0)
    b = (w[0], w[1], 1.0)
    cx = a[1] * b[2] - a[2] * b[1]
    cy = a[2] * b[0] - a[0] * b[2]
    cz = a[0] * b[1] - a[1] * b[0]
    return math.degrees(math.atan2(math.sqrt(cx * cx + cy * cy + cz * cz),
                                   a[0] * b[0] + a[1] * b[1] + a[2] * b[2]))


def select_rules(poly):
    """Return {rule: map} for a non-empty feasible polygon (CCW list)."""
    if len(poly) == 1:
        p = poly[0]
        return {"max_area": p, "mean_2d": p, "mean_3d": p}
    diam, pa, pb = diameter_pair(poly)
    scale = max(abs(pa[0]), abs(pa[1]), abs(pb[0]), abs(pb[1]), 1e-300)
    area2, cx, cy, o = (shoelace(poly) if len(poly) >= 3 else (0.0, 0.0, 0.0, poly[0]))
    degenerate = diam <= 1e-13 * scale or abs(area2) <= 1e-12 * diam * diam
    if degenerate:
        # point or segment (only reached through rounding, see REL_EPS)
        if diam <= 1e-13 * scale:
            p = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
            return {"max_area": p, "mean_2d": p, "mean_3d": p}
        mid = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
        ua, ub = unit3(pa), unit3(pb)
        s = (ua[0] + ub[0], ua[1] + ub[1], ua[2] + ub[2])
        return {"max_area": max_area_rule([pa, pb]), "mean_2d": mid,
                "mean_3d": (s[0] / s[2], s[1] / s[2])}
    m2d = (o[0] + cx / (3.0 * area2), o[1] + cy / (3.0 * area2))
    if diam <= 1e-3 * max(1.0, scale):
        # Arvo's sum cancels for tiny polygons (docs/derivations.md §1.6); there the weighted
        # and plain centroids differ by O(diam^2), far below what matters here.
        m3d = m2d
    else:
        m3d = arvo_map(poly)
    return {"max_area": max_area_rule(poly), "mean_2d": m2d, "mean_3d": m3d}


# --------------------------------------------------------------------------
# Experiment
# --------------------------------------------------------------------------

class Experiment:
    def __init__(self, data_dir):
        _, basis = read_spectral_csv(os.path.join(data_dir, "cie_daylight_basis_S0_S1_S2.csv"))
        chips, refl = read_spectral_csv(os.path.join(data_dir, "munsell_matt_1269_joensuu_5nm.csv"))
        self.nchips = len(chips)
        self.refl = [tuple(refl[w][i] for w in WAVELENGTHS) for i in range(self.nchips)]
        self.canon = light_rgb("D55", basis)
        self.lights = {name: light_rgb(name, basis) for name in LIGHTS}
        cq = [self.chroma(r, self.canon) for r in self.refl]
        self.gamut = Gamut(convex_hull(cq))
        self.image_q = {}
        self.truth = {}
        for name, e in self.lights.items():
            self.image_q[name] = [self.chroma(r, e) for r in self.refl]
            d = [self.canon[k] / e[k] for k in range(3)]
            self.truth[name] = (d[0] / d[2], d[1] / d[2])

    @staticmethod
    def chroma(refl, e):
        r, g, b = (refl[k] * e[k] for k in range(3))
        return (r / b, g / b)

    def scene(self, light, picks):
        """{rule: (error, worst case, *extras)} for one scene, None if F is empty."""
        qs = [self.image_q[light][i] for i in picks]
        hull = convex_hull(qs)
        poly = feasible_set(self.gamut, hull)
        if not poly:
            return None
        truth = self.truth[light]
        maps = select_rules(poly)
        out = {}
        for rule, m in maps.items():
            err = angle_deg(m, truth)
            worst = max(angle_deg(m, v) for v in poly)
            out[rule] = (err, worst)
        self.scene_extras(poly, truth, maps, out)
        return out

    def scene_extras(self, poly, truth, maps, out):
        """Hook: a subclass may append further per-rule results to out[rule]
        (bench/baseline_reproduce.py does).  The oracle itself adds none."""

    def run(self, scenes, seed, lights=LIGHTS, surfaces=range(1, 12)):
        rows = []
        for light in lights:
            for n in surfaces:
                rng = random.Random("%d|%s|%d" % (seed, light, n))
                errs = {r: [] for r in RULES}
                worsts = {r: [] for r in RULES}
                empty = 0
                for _ in range(scenes):
                    picks = rng.sample(range(self.nchips), n)
                    res = self.scene(light, picks)
                    if res is None:
                        empty += 1
                        continue
                    for r in RULES:
                        errs[r].append(res[r][0])
                        worsts[r].append(res[r][1])
                for r in RULES:
                    e, w = errs[r], worsts[r]
                    k = len(e)
                    rows.append({
                        "illuminant": light, "surfaces": n, "rule": r,
                        "mean_error_deg": statistics.fmean(e) if k else float("nan"),
                        "mean_worst_case_deg": statistics.fmean(w) if k else float("nan"),
                        "scenes": k,
                        "sd_error_deg": statistics.stdev(e) if k > 1 else float("nan"),
                        "sd_worst_case_deg": statistics.stdev(w) if k > 1 else float("nan"),
                        "empty_scenes": empty,
                    })
        return rows


COLUMNS = ("illuminant", "surfaces", "rule", "mean_error_deg", "mean_worst_case_deg",
           "scenes", "sd_error_deg", "sd_worst_case_deg", "empty_scenes")


def write_csv(rows, fh):
    w = csv.writer(fh, lineterminator="\n")
    w.writerow(COLUMNS)
    for row in rows:
        w.writerow([("%.6f" % row[c]) if isinstance(row[c], float) else row[c]
                    for c in COLUMNS])


def parse_range(text):
    out = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def main(argv=None, experiment=Experiment, doc=__doc__):
    """The command line; experiment and doc let bench/baseline_reproduce.py reuse it."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    ap.add_argument("--scenes", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--data", default=DEFAULT_DATA)
    ap.add_argument("--lights", default=",".join(LIGHTS))
    ap.add_argument("--surfaces", default="1-11")
    ap.add_argument("--check-illuminants", action="store_true",
                    help="only compare computed daylights with the CIE table")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)

    if args.check_illuminants:
        worst = check_illuminants(args.data, sys.stdout)
        return 0 if worst < 0.01 else 1

    exp = experiment(args.data)
    if not args.quiet:
        check_illuminants(args.data)
        print("# canonical gamut: %d vertices; true maps: %s" % (
            len(exp.gamut.verts),
            ", ".join("%s=(%.4f, %.4f)" % (k, v[0], v[1]) for k, v in exp.truth.items())),
            file=sys.stderr)
    lights = [s for s in args.lights.split(",") if s]
    rows = exp.run(args.scenes, args.seed, lights, parse_range(args.surfaces))
    write_csv(rows, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
