#!/usr/bin/env python3
"""The Python module's cost against the library's, in one run (issue 17; docs/performance-history.md
"Python module"):

  1. per call, 11-colour scenes: gmcc.select(prepared, float array) from Python against
     select_scene on the same exact colours in a C++ loop (gmcc._core._time_select_scene, the
     inputs converted outside its clock), interleaved rounds, the median of each; the overhead is
     their ratio minus one;
  2. a 10^6-pixel 16-bit image (a noisy Mondrian: 8 × 6 cells of Munsell chips, ±100 codes of
     uniform noise per sample, seeded) to its feasible set with gmcc.feasible_set, and for scale
     the same image's pixel rules alone (gmcc.image_colours).

Scenes: 11 distinct chips drawn (numpy default_rng, --seed) from the shipped canonical sample
(1269 Munsell chips under D55), under the light (4/5, 9/10, 11/10), as doubles.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--scenes N] [--rounds R]
"""

import argparse
import statistics
import time
from pathlib import Path

import numpy as np

import gmcc

ROOT = Path(__file__).resolve().parents[1]


def read_rgb(path):
    return np.array([line.strip().split(",") for line in open(path) if line[:1].isdigit()], dtype=float)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    chips = read_rgb(ROOT / "data/samples/canonical_munsell_D55.csv")
    prepared = gmcc.prepare_canonical(chips)
    light = np.array([0.8, 0.9, 1.1])
    scenes = [np.ascontiguousarray(chips[rng.choice(len(chips), 11, replace=False)] * light)
              for _ in range(args.scenes)]

    py_times, cpp_times = [], []
    for _ in range(args.rounds):
        cpp_times.append(gmcc._core._time_select_scene(prepared, scenes, 1))
        start = time.perf_counter()
        for s in scenes:
            gmcc.select(prepared, s)
        py_times.append((time.perf_counter() - start) / len(scenes))
    cpp, py = statistics.median(cpp_times), statistics.median(py_times)
    print(f"11-colour scenes ({args.scenes} scenes, {args.rounds} interleaved rounds, medians):")
    print(f"  C++ select_scene        {cpp * 1e6:9.1f} us per call")
    print(f"  Python gmcc.select      {py * 1e6:9.1f} us per call")
    print(f"  ratio Python / C++      {py / cpp:9.3f}   (overhead {100 * (py / cpp - 1):.1f}%)")

    # A 1000 x 1000 noisy Mondrian of chips seen as 16-bit codes.
    cells = chips[rng.choice(len(chips), 48, replace=False)] * light
    cells = np.round(cells / cells.max() * 60000).reshape(6, 8, 3)
    image = np.repeat(np.repeat(cells, 167, axis=0), 125, axis=1)[:1000, :1000]
    image = np.clip(image + rng.integers(-100, 101, image.shape), 0, 65535).astype(np.uint16)
    f_times, c_times = [], []
    for _ in range(args.rounds):
        start = time.perf_counter()
        F = gmcc.feasible_set(prepared, image)
        f_times.append(time.perf_counter() - start)
        start = time.perf_counter()
        colours = gmcc.image_colours(image)
        c_times.append(time.perf_counter() - start)
    f, c = statistics.median(f_times), statistics.median(c_times)
    print(f"10^6-pixel 16-bit image ({colours.counts['colours']} distinct colours, "
          f"{colours.counts['hull_vertices']} on the chromaticity hull; F: {F.kind}, {len(F)} vertices):")
    print(f"  image to F              {f * 1e3:9.1f} ms   (target < 100 ms)")
    print(f"  pixel rules alone       {c * 1e3:9.1f} ms   ({100 * c / f:.0f}% of it)")


if __name__ == "__main__":
    main()
