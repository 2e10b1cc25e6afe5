#!/usr/bin/env python3
"""An independent exact test of `gmcc benchmark`'s truth in F3 (docs/photographs.md §6, issue 41),
image by image, on a dataset of linear PNGs with a truth table and folds.

gmcc decides whether some positive multiple of the true map c ⊘ e lies in F3 on F3's rows
(docs/math.md §1d). This script decides the same question another way, in Python integers: with
black in the canonical gamut, the answer is yes iff every kept colour p of the image, divided by
its light, lies in the cone at black of the fold's canonical gamut — the cone of every training
colour divided by its own light (the scale each training image is given does not move a cone).
Cone membership for colours of the closed positive octant is membership of their central
projections onto r + g + b = 1 in the 2-D hull of the training colours' projections, and the
orientation of three projections is the sign of the 3 × 3 determinant of the colours themselves.
Only the vertices of the image's own projected hull need testing.

Pixels are kept as under gmcc's default rules: black level 0, a pixel dropped when any channel is
at or above the file's largest code (2^bits − 1, `--saturation max`), every other pixel kept (dark
ones included); black pixels add nothing to a cone.

    truth_in_f_check.py GMCC --images DIR --truths T.csv (--folds-file F.csv | --folds K)
                        [--limit N]

Prints each disagreement and `N agree, M disagree`; exit status 1 on any disagreement.
"""

import argparse
import csv
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib
from fractions import Fraction
from math import gcd


def read_png(path):
    """(pixels as (r, g, b) tuples, bits) of an 8- or 16-bit RGB non-interlaced PNG."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, bits, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert colour == 2 and interlace == 0 and bits in (8, 16), f"{path}: not plain RGB"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    bpp = 3 * bits // 8
    stride = width * bpp
    prev, rows, i = bytearray(stride), [], 0
    while i < len(raw):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    fmt = ">" + ("H" if bits == 16 else "B") * (3 * width)
    pixels = []
    for line in rows:
        v = struct.unpack(fmt, line)
        pixels += [v[3 * k:3 * k + 3] for k in range(width)]
    return pixels, bits


def white_balanced(p, e):
    """p ⊘ e as an integer vector on the same ray (times the lights' denominators), reduced."""
    e = [Fraction(x) for x in e]
    q = [Fraction(p[k]) / e[k] for k in range(3)]
    d = 1
    for x in q:
        d = d * x.denominator // gcd(d, x.denominator)
    v = [int(x * d) for x in q]
    g = gcd(gcd(v[0], v[1]), v[2])
    return tuple(x // g for x in v)


def det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def projected_hull(rays):
    """The rays (non-zero, in the closed octant) whose projections are the vertices of the 2-D
    hull of all projections, counter-clockwise (Andrew's monotone chain, orientation by det)."""
    key = {q: (Fraction(q[0], sum(q)), Fraction(q[1], sum(q))) for q in set(rays)}
    p = sorted(key, key=key.get)
    uniq = []
    for q in p:
        if not uniq or key[uniq[-1]] != key[q]:
            uniq.append(q)
    if len(uniq) <= 2:
        return uniq
    lower, upper = [], []
    for q in uniq:
        while len(lower) >= 2 and det(lower[-2], lower[-1], q) <= 0:
            lower.pop()
        lower.append(q)
    for q in reversed(uniq):
        while len(upper) >= 2 and det(upper[-2], upper[-1], q) <= 0:
            upper.pop()
        upper.append(q)
    return lower[:-1] + upper[:-1]


def in_cone(hull, q):
    """q's projection in the closed hull (counter-clockwise; a segment or point when flat)."""
    if len(hull) >= 3:
        return all(det(hull[i], hull[(i + 1) % len(hull)], q) >= 0 for i in range(len(hull)))
    pq = (Fraction(q[0], sum(q)), Fraction(q[1], sum(q)))
    ends = [(Fraction(h[0], sum(h)), Fraction(h[1], sum(h))) for h in hull]
    if len(ends) == 1:
        return pq == ends[0]
    (ax, ay), (bx, by) = ends
    on_line = (bx - ax) * (pq[1] - ay) == (by - ay) * (pq[0] - ax)
    return on_line and min(ax, bx) <= pq[0] <= max(ax, bx) and min(ay, by) <= pq[1] <= max(ay, by)


def kept_rays(pixels, bits, light):
    top = (1 << bits) - 1
    return [white_balanced(p, light) for p in pixels if max(p) < top and sum(p) > 0]


def truth_in_f3(training_hulls, image_rays):
    """training_hulls: each training image's projected hull rays (already white-balanced)."""
    hull = projected_hull([q for h in training_hulls for q in h])
    return all(in_cone(hull, q) for q in projected_hull(image_rays))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("gmcc")
    ap.add_argument("--images", required=True)
    ap.add_argument("--truths", required=True)
    ap.add_argument("--folds-file")
    ap.add_argument("--folds", type=int)
    ap.add_argument("--limit", type=int, help="compare the first N images' records only")
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.truths, encoding="utf-8-sig")))
    if a.folds_file:
        fold_of = {r["image"]: int(r["fold"]) for r in csv.DictReader(open(a.folds_file, encoding="utf-8-sig"))}
    else:
        fold_of = {r["image"]: i % a.folds for i, r in enumerate(rows)}
    lights = [tuple(Fraction(r[k]) for k in "rgb") for r in rows]
    hulls = []
    for r, e in zip(rows, lights):
        pixels, bits = read_png(os.path.join(a.images, r["image"]))
        hulls.append(projected_hull(kept_rays(pixels, bits, e)))
    with tempfile.TemporaryDirectory() as tmp:
        rec_path = os.path.join(tmp, "records.jsonl")
        folds = ["--folds-file", a.folds_file] if a.folds_file else ["--folds", str(a.folds)]
        run = subprocess.run([a.gmcc, "benchmark", "--images", a.images, "--truths", a.truths, *folds,
                              "--methods", "gm3d-max-trace", "--records", rec_path, "--no-progress"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stderr.strip())
            return 2
        records = [json.loads(x) for x in open(rec_path)][2:]
    agree = disagree = inside = 0
    by_fold = {}
    for rec in records:
        i = rec["index"]
        if a.limit is not None and i >= a.limit:
            continue
        fold = fold_of[rows[i]["image"]]
        if fold not in by_fold:
            by_fold[fold] = projected_hull([q for j, h in enumerate(hulls) if fold_of[rows[j]["image"]] != fold for q in h])
        want = all(in_cone(by_fold[fold], q) for q in hulls[i])
        inside += want
        if rec["truth_in_feasible"] == want:
            agree += 1
        else:
            disagree += 1
            print(f"DISAGREE {rows[i]['image']}: gmcc {rec['truth_in_feasible']}, cone test {want}")
    print(f"truth in F3 by the cone test: {inside} of {agree + disagree} images")
    print(f"{agree} agree, {disagree} disagree")
    return 1 if disagree else 0


if __name__ == "__main__":
    sys.exit(main())
