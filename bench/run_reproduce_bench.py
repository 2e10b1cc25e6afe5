#!/usr/bin/python3
"""Time the synthetic reproduction: gmcc (exact) against the plain-double Python baseline.

    bench/run_reproduce_bench.py [--gmcc build/cli/gmcc] [--scenes 500] [--threads 2]

Both run the same experiment size (4 lights x 11 surface counts x SCENES scenes) one after the
other from this one process; wall time and CPU time (user + sys of the child) are measured for
each, and the ratios printed.  gmcc runs with --threads THREADS, the baseline is single-threaded,
so the CPU ratio compares work and the wall ratio what a user waits.  The scenes differ (each
program draws its own), the work per scene does not: exact feasible set, three rules, map-space
worst cases, map, illuminant and reproduction errors (docs/performance.md).
"""

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def timed(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def timed_gmcc(gmcc, scenes, threads):
    """Wall and CPU seconds of `gmcc reproduce synthetic` with SCENES scenes per cell."""
    with tempfile.TemporaryDirectory() as tmp:
        return timed([gmcc, "reproduce", "synthetic", "--scenes", str(scenes),
                      "--threads", str(threads), "--csv", os.path.join(tmp, "g.csv")])


def timed_baseline(scenes):
    """Wall and CPU seconds of the Python plain-double baseline with SCENES scenes per cell."""
    return timed([sys.executable, os.path.join(HERE, "baseline_reproduce.py"),
                  "--scenes", str(scenes), "--quiet"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--gmcc", default=os.path.join(HERE, "..", "build", "cli", "gmcc"))
    ap.add_argument("--scenes", type=int, default=500)
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    total = 4 * 11 * args.scenes
    g_wall, g_cpu = timed_gmcc(args.gmcc, args.scenes, args.threads)
    p_wall, p_cpu = timed_baseline(args.scenes)
    print("synthetic reproduction, %d scenes (%d per light and count)" % (total, args.scenes))
    print("%-44s %9s %9s %12s" % ("", "wall s", "CPU s", "CPU us/scene"))
    print("%-44s %9.3f %9.3f %12.1f" % ("gmcc (certified, %d threads)" % args.threads, g_wall, g_cpu,
                                         1e6 * g_cpu / total))
    print("%-44s %9.3f %9.3f %12.1f" % ("Python plain doubles (baseline_reproduce.py)", p_wall, p_cpu,
                                         1e6 * p_cpu / total))
    print("ratio baseline / gmcc: wall %.2fx, CPU %.2fx" % (p_wall / g_wall, p_cpu / g_cpu))
    print("load average at the end: %.2f %.2f %.2f" % os.getloadavg())


if __name__ == "__main__":
    main()
