#!/usr/bin/env python3
"""3-D gamut mapping on photographs: gmcc's exact route against a float baseline of the same
method, in one run (issue 26; docs/performance.md "3-D gamut mapping on photographs").

For one camera folder of a NUS-style dataset (16-bit linear PNGs and gt.csv with image,camera,r,g,b),
the canonical gamut is learned from folds 1 and 2 (image index modulo 3 in gt.csv order), and the
images of fold 0 are estimated, each pixel set by Gijsenij et al.'s rule (the image rescaled to a
maximum of 255, a channel below 5 or above 245 dropped), by:

  1. gmcc from Python: gmcc.estimate_3d(prepared, image, pixel_rule='gijsenij') — F3 exactly and
     every 3-D rule (max-volume, centroid certified, max-trace), from the uint16 array;
  2. gmcc from the command line: `gmcc estimate --space 3d --json` on all the fold's images in one
     process (its wall time over the images, process start and reading the PNGs included);
  3. the float baseline, our own, of the same method as a researcher writes it (Gijsenij et al.
     2010): the image's kept pixels (the same rule, in numpy) scaled to a maximum of 1, their qhull
     hull, the constraints A(d∘q) <= b for every canonical facet and hull vertex q, and SciPy's
     HiGHS maximising d1 + d2 + d3 — max-trace only.

Rounds interleave the three; the median time per image of each is reported, and the ratios: wall
times, and CPU times (this process's for 1 and 3, the child's for 2), which other jobs on a shared
machine do not stretch.
Also checked: gmcc's max-trace light agrees with the float LP's to 0.1 deg wherever the LP's
maximiser is unique (a second LP fixes the optimal trace and maximises, then minimises, each
coordinate: a unique maximiser has the two equal to 1e-7 relative).

    PYTHONPATH=build/python /usr/bin/python3 bench/photo_speed.py --camera-dir DIR [--gmcc build/cli/gmcc]
        [--rounds 5] [--json FILE]
"""

import argparse
import csv
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
import zlib
from fractions import Fraction
from pathlib import Path

import numpy as np
from scipy.spatial import ConvexHull

import gmcc

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "support"))
import float_lp  # noqa: E402  (the float baseline, shared with tests/python/test_photographs.py)


def read_png16(path):
    """A 16-bit RGB (or RGBA) non-interlaced PNG as an (H, W, 3) uint16 array (zlib + filters)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = int.from_bytes(body[:4], "big"), int.from_bytes(body[4:8], "big"), body[8], body[9]
            assert depth == 16 and ctype in (2, 6) and body[12] == 0, (path, depth, ctype)
            channels = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    bpp, stride = 2 * channels, 2 * channels * w
    out = np.zeros((h, stride), np.uint8)
    prev = np.zeros(stride, np.int64)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int64)
        cur = np.zeros(stride, np.int64)
        for x in range(stride):
            a = cur[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 0: p = 0
            elif f == 1: p = a
            elif f == 2: p = b
            elif f == 3: p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 255
        out[y] = cur
        prev = cur
    px = out.reshape(h, w, channels, 2).astype(np.uint16)
    return ((px[..., 0] << 8) | px[..., 1])[..., :3]


def kept_pixels(img):
    """Gijsenij et al.'s rule, exactly as gmcc's preset: 255 v < 5 M or 255 v > 245 M dropped."""
    v = img.astype(np.int64)
    m = int(v.max())
    ok = np.all((255 * v >= 5 * m) & (255 * v <= 245 * m), axis=2)
    return v[ok].astype(float)


def float_max_trace(A, b, img, unique_check=False):
    """The float baseline: hull of the kept pixels (scaled to max 1), rows A(d∘q) <= b, HiGHS."""
    p = kept_pixels(img)
    p = p / p.max()
    q = p[ConvexHull(p).vertices]
    return float_lp.max_trace(A, b, q, unique_check)


def angle_deg(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v)), np.dot(u, v))))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--camera-dir", required=True, help="a folder of 16-bit PNGs and gt.csv")
    ap.add_argument("--gmcc", default=str(ROOT / "build" / "cli" / "gmcc"))
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--json", help="also write the medians (seconds per image) to this file")
    args = ap.parse_args()
    d = Path(args.camera_dir)
    rows = list(csv.DictReader(open(d / "gt.csv")))
    images = [read_png16(d / (r["image"] + ".png")) for r in rows]
    lights = [tuple(Fraction(r[k]) for k in "rgb") for r in rows]
    train = [i for i in range(len(rows)) if i % 3 != 0]
    test = [i for i in range(len(rows)) if i % 3 == 0]

    learner = gmcc.CanonicalLearner3(intensity="max")
    for i in train:
        learner.add(images[i], lights[i], pixel_rule="gijsenij")
    prepared = learner.prepare()
    # The float baseline's canonical gamut: the same learned vertices and black, hulled by qhull.
    g = np.vstack([learner.gamut_float(), np.zeros((1, 3))])
    hull = ConvexHull(g)
    A, b = hull.equations[:, :3], -hull.equations[:, 3]

    with tempfile.TemporaryDirectory() as tmp:
        canonical_csv = os.path.join(tmp, "canonical.csv")
        with open(canonical_csv, "w") as f:
            f.write("r,g,b\n")
            for c in learner.gamut():
                f.write(",".join(str(x) for x in c) + "\n")
        truths = os.path.join(tmp, "truths.csv")
        with open(truths, "w") as f:
            f.write("image,r,g,b\n")
            for r in rows:
                f.write(f"{r['image']}.png,{r['r']},{r['g']},{r['b']}\n")
        paths = [str(d / (rows[i]["image"] + ".png")) for i in test]
        cli = [args.gmcc, "estimate", "--space", "3d", "--canonical", canonical_csv, "--truths", truths,
               "--pixel-rule", "gijsenij", "--saturation", "none", "--json", *paths]

        # Wall times, and CPU times (this process's for Python and the float baseline, the child's
        # for the command line): on a machine shared with other jobs the CPU times are the ones
        # that the others' load does not stretch.
        t_py, t_cli, t_float = [], [], []
        c_py, c_cli, c_float = [], [], []

        def child_cpu():
            r = resource.getrusage(resource.RUSAGE_CHILDREN)
            return r.ru_utime + r.ru_stime

        for _ in range(args.rounds):
            t0, c0 = time.perf_counter(), time.process_time()
            results = [gmcc.estimate_3d(prepared, images[i], lights[i], pixel_rule="gijsenij") for i in test]
            t_py.append((time.perf_counter() - t0) / len(test))
            c_py.append((time.process_time() - c0) / len(test))
            t0, c0 = time.perf_counter(), child_cpu()
            out = subprocess.run(cli, check=True, capture_output=True, text=True).stdout
            t_cli.append((time.perf_counter() - t0) / len(test))
            c_cli.append((child_cpu() - c0) / len(test))
            t0, c0 = time.perf_counter(), time.process_time()
            lp = [float_max_trace(A, b, images[i])[0] for i in test]
            t_float.append((time.perf_counter() - t0) / len(test))
            c_float.append((time.process_time() - c0) / len(test))

    # Agreement of max-trace with the float LP where the LP's maximiser is unique.
    agree, unique_n, worst = 0, 0, 0.0
    for k, i in enumerate(test):
        r, unique = float_max_trace(A, b, images[i], unique_check=True)
        mt = results[k].max_trace
        if r.status != 0 or not unique or mt is None or mt.light is None or min(r.x) <= 0:
            continue
        unique_n += 1
        a = angle_deg(mt.light, 1.0 / r.x)
        worst = max(worst, a)
        agree += a <= 0.1
    cli_images = json.loads(out)["images"]
    assert len(cli_images) == len(test)

    py, cl, fl = statistics.median(t_py), statistics.median(t_cli), statistics.median(t_float)
    cpy, ccl, cfl = statistics.median(c_py), statistics.median(c_cli), statistics.median(c_float)
    print(f"camera folder: {d.name}; {len(train)} training images, {len(test)} estimated; canonical gamut "
          f"{prepared.colours} vertices, {prepared.half_spaces} facets (with black)")
    print(f"per image (median of {args.rounds} rounds):")
    print(f"  gmcc.estimate_3d, every 3-D rule (Python)   {py * 1e3:8.3f} ms")
    print(f"  gmcc estimate --space 3d (one process)      {cl * 1e3:8.3f} ms")
    print(f"  float baseline: qhull + HiGHS max-trace     {fl * 1e3:8.3f} ms")
    print(f"  ratio float / Python {fl / py:.1f}x, float / command line {fl / cl:.1f}x")
    print(f"CPU time per image (median of {args.rounds} rounds): Python {cpy * 1e3:.3f} ms, command line "
          f"{ccl * 1e3:.3f} ms, float baseline {cfl * 1e3:.3f} ms")
    print(f"  CPU ratio float / Python {cfl / cpy:.1f}x, float / command line {cfl / ccl:.1f}x")
    print(f"max-trace vs the float LP: {agree} of {unique_n} images with a unique LP maximiser agree to 0.1 deg "
          f"(largest difference {worst:.2e} deg)")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"images": len(test), "rounds": args.rounds,
                       "wall": {"python": py, "command_line": cl, "float": fl},
                       "cpu": {"python": cpy, "command_line": ccl, "float": cfl},
                       "max_trace_unique": unique_n, "max_trace_agree": agree, "max_trace_worst_deg": worst},
                      f, indent=1)
    return 0 if agree == unique_n else 1


if __name__ == "__main__":
    sys.exit(main())
