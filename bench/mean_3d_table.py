#!/usr/bin/env python3
"""Print the 3-D mean benchmark as a table of times and ratios (one run, same process).

usage: build/bench/bench_mean_3d --benchmark_format=json > out.json
       python3 bench/mean_3d_table.py out.json
"""
import json
import sys

runs = json.load(open(sys.argv[1]))["benchmarks"]
unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
times = {b["name"]: b["real_time"] * unit[b["time_unit"]] for b in runs if b.get("run_type", "iteration") == "iteration"}
labels = {b["name"]: b.get("label", "") for b in runs}
mc = times["monte_carlo/1000000"]
print("| route | time per 3-D mean | Monte Carlo 10^6 / this |")
print("|---|---|---|")
for name, t in times.items():
    shown = f"{t * 1e6:.1f} µs" if t < 1e-3 else f"{t * 1e3:.2f} ms"
    label = f" ({labels[name]})" if labels[name] else ""
    print(f"| `{name}`{label} | {shown} | {mc / t:,.0f}× |")
