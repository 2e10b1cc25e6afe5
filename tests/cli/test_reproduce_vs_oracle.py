#!/usr/bin/python3
"""Statistical cross-check of `gmcc reproduce synthetic` against the independent
Python oracle (tests/oracle/reproduce_oracle.py).

    test_reproduce_vs_oracle.py GMCC_BINARY [--scenes S] [--oracle-scenes S2]
                                [--seed 11] [--oracle-seed 29] [--z 4.5]

Runs the C++ tool with S scenes per (light, surfaces) and seed 11, and the
oracle with S2 scenes (default: S) and a different seed.  The scenes differ, so
each cell (light, n, rule) is compared through its sampling error: for the mean
error and for the mean worst case separately,

    z = (mean_cpp - mean_oracle) / sqrt(sd^2/S + sd^2/S2),

with sd the oracle's per-cell standard deviation of that measure (the C++ CSV
carries none; both samples come from the same distribution if both programs are
right).  A cell fails if |z| > Z.  Z = 4.5: with 44 x 3 cells x 2 measures = 264
comparisons, the chance of any false alarm under a normal approximation is
about 264 * 6.8e-6 = 0.2 %.

Prints a summary (largest |z| overall and per light), the failing cells, and
`N passed, N failed`; exits 0 iff none failed.
"""

import argparse
import csv
import io
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ORACLE = os.path.normpath(os.path.join(HERE, "..", "oracle", "reproduce_oracle.py"))
MEASURES = (("mean_error_deg", "sd_error_deg", "error"),
            ("mean_worst_case_deg", "sd_worst_case_deg", "worst"))


def read_rows(fh):
    out = {}
    for row in csv.DictReader(line for line in fh if not line.startswith("#")):  # provenance
        out[(row["illuminant"], int(row["surfaces"]), row["rule"])] = row
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("gmcc")
    ap.add_argument("--scenes", type=int, default=300,
                    help="scenes per (light, surfaces) for the C++ tool (default 300)")
    ap.add_argument("--oracle-scenes", type=int, default=None,
                    help="scenes per cell for the oracle (default: --scenes)")
    ap.add_argument("--seed", type=int, default=11, help="C++ seed (default 11)")
    ap.add_argument("--oracle-seed", type=int, default=29, help="oracle seed (default 29)")
    ap.add_argument("--z", type=float, default=4.5, help="|z| threshold (default 4.5)")
    ap.add_argument("--threads", default=None,
                    help="pass --threads to gmcc (default: the tool's own default)")
    ap.add_argument("--verbose", action="store_true", help="print every cell")
    args = ap.parse_args()
    s_cpp = args.scenes
    s_or = args.oracle_scenes or args.scenes

    with tempfile.TemporaryDirectory() as tmp:
        csv_path = os.path.join(tmp, "cpp.csv")
        cmd = [args.gmcc, "reproduce", "synthetic", "--scenes", str(s_cpp),
               "--seed", str(args.seed), "--csv", csv_path]
        if args.threads is not None:
            cmd += ["--threads", str(args.threads)]
        t0 = time.time()
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        t_cpp = time.time() - t0
        if r.returncode != 0:
            print("gmcc failed (exit %d):\n%s%s" % (r.returncode, r.stdout, r.stderr))
            print("0 passed, 1 failed")
            return 1
        with open(csv_path, newline="") as fh:
            cpp = read_rows(fh)

    t0 = time.time()
    r = subprocess.run([sys.executable, ORACLE, "--scenes", str(s_or),
                        "--seed", str(args.oracle_seed), "--quiet"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t_or = time.time() - t0
    if r.returncode != 0:
        print("oracle failed (exit %d):\n%s" % (r.returncode, r.stderr))
        print("0 passed, 1 failed")
        return 1
    oracle = read_rows(io.StringIO(r.stdout))

    print("gmcc reproduce synthetic: %d scenes/cell, seed %d (%.1f s); "
          "oracle: %d scenes/cell, seed %d (%.1f s); threshold |z| <= %.2f"
          % (s_cpp, args.seed, t_cpp, s_or, args.oracle_seed, t_or, args.z))

    passed = failed = 0
    failures = []
    per_light = {}
    overall = (0.0, None)
    for key in sorted(oracle, key=lambda k: (k[0], k[1], k[2])):
        light, n, rule = key
        o = oracle[key]
        c = cpp.get(key)
        if c is None:
            failed += 1
            failures.append("%s n=%d %s: missing from the C++ CSV" % key)
            continue
        nc = int(c["scenes"])
        no = int(o["scenes"])
        if nc != s_cpp or no != s_or:
            failures.append("%s n=%d %s: scene counts cpp %d (expected %d), oracle %d"
                            % (light, n, rule, nc, s_cpp, no))
            failed += 1
            continue
        for mcol, sdcol, label in MEASURES:
            mc = float(c[mcol])
            mo = float(o[mcol])
            sd = float(o[sdcol])
            se = math.sqrt(sd * sd / nc + sd * sd / no)
            z = (mc - mo) / se if se > 0 else (0.0 if mc == mo else math.inf)
            if args.verbose:
                print("  %-6s n=%2d %-8s %-5s cpp %8.3f oracle %8.3f sd %7.3f z %+6.2f"
                      % (light, n, rule, label, mc, mo, sd, z))
            pl = per_light.setdefault(light, {"error": (0.0, None), "worst": (0.0, None),
                                              "sum_z": 0.0, "k": 0})
            if abs(z) > abs(pl[label][0]):
                pl[label] = (z, "n=%d %s" % (n, rule))
            pl["sum_z"] += z
            pl["k"] += 1
            if abs(z) > abs(overall[0]):
                overall = (z, "%s n=%d %s %s" % (light, n, rule, label))
            if abs(z) <= args.z and math.isfinite(z):
                passed += 1
            else:
                failed += 1
                failures.append("%s n=%d %s %s: cpp %.3f vs oracle %.3f (diff %+.3f, se %.3f, z %+.2f)"
                                % (light, n, rule, label, mc, mo, mc - mo, se, z))

    print("largest |z| overall: %+.2f (%s)" % overall)
    for light in sorted(per_light):
        pl = per_light[light]
        print("  %-6s max |z| mean error %+.2f (%s), worst case %+.2f (%s); mean z %+.2f over %d"
              % (light, pl["error"][0], pl["error"][1], pl["worst"][0], pl["worst"][1],
                 pl["sum_z"] / max(pl["k"], 1), pl["k"]))
    if failures:
        print("failing cells:")
        for f in failures:
            print("  " + f)
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
