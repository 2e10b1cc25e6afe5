#!/usr/bin/env python3
"""`gmcc reproduce` end to end: byte-identical output for a seed and any thread count, the CSV
contract of the reproduction issue, and clear errors (exit 2, nothing written) for bad options.

usage: test_reproduce.py GMCC_BINARY     (ends with a line 'N passed, N failed')
"""
import csv
import io
import os
import subprocess
import sys
import tempfile

from cli_harness import Tally

gmcc = sys.argv[1]


tally = Tally()
check = tally.check


def run(*args):
    return subprocess.run([gmcc, "reproduce", *args], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    a, b, c = (os.path.join(tmp, n) for n in ("a.csv", "b.csv", "c.csv"))
    small = ["--scenes", "4", "--surfaces", "5"]
    r1 = run("synthetic", *small, "--seed", "7", "--threads", "1", "--csv", a)
    r2 = run("synthetic", *small, "--seed", "7", "--threads", "2", "--csv", b)
    r3 = run("synthetic", *small, "--seed", "8", "--csv", c)
    check(r1.returncode == 0 and r2.returncode == 0 and r3.returncode == 0, "synthetic runs")
    check(open(a, "rb").read() == open(b, "rb").read(), "same seed, 1 and 2 threads: identical CSV bytes")
    check(r1.stdout == r2.stdout, "same seed: identical table")
    check(open(a, "rb").read() != open(c, "rb").read(), "another seed: another CSV")

    text = open(a).read()
    check(text.startswith("# gmcc-provenance: "), "the CSV starts with its provenance line")
    rows = list(csv.DictReader(io.StringIO(text.split("\n", 1)[1])))
    required = {"illuminant", "surfaces", "rule", "mean_error_deg", "mean_worst_case_deg", "scenes"}
    check(required <= set(rows[0].keys()), "CSV has the required columns")
    check(len(rows) == 4 * 5 * 3, "one row per (illuminant, surfaces, rule)")
    check({r["illuminant"] for r in rows} == {"D75", "D100", "P2856", "P15000"}, "the paper's lights")
    check({r["rule"] for r in rows} == {"max_area", "mean_2d", "mean_3d"}, "the three rules")
    check(all(r["scenes"] == "4" and r["empty_scenes"] == "0" for r in rows), "every scene has a map")
    check(all(r["truth_in_feasible_set"] == "4" for r in rows), "the true map is in every F")

    plot = os.path.join(tmp, "fig")
    rp = run("synthetic", "--scenes", "2", "--surfaces", "3", "--plot", plot)
    check(rp.returncode == 0 and os.path.exists(os.path.join(plot, "synthetic.gp"))
          and os.path.exists(os.path.join(plot, "synthetic.dat")), "--plot writes data and script")

    for bad, why in [(["synthetic", "--scenes", "-1"], "negative scenes"),
                     (["synthetic", "--scenes", "abc"], "non-number"),
                     (["synthetic", "--lights", "X42"], "unknown light"),
                     (["synthetic", "--expand", "0.1"], "factor without policy"),
                     (["synthetic", "--expand", "1e151", "--expand-policy", "multiplicative", "--scenes", "1"],
                      "expansion beyond 1e150"),
                     (["synthetic", "--expand", "1e400", "--expand-policy", "multiplicative", "--scenes", "1"],
                      "expansion far beyond the doubles"),
                     (["camera", "--expand", "1e200", "--expand-policy", "centroid-clip", "--scenes", "1"],
                      "camera: expansion beyond 1e150"),
                     (["synthetic", "--surfaces", "30"], "more surfaces than allowed"),
                     (["synthetic", "--scenes", "1", "--csv", os.path.join(tmp, "no", "such", "dir", "x.csv")],
                      "unwritable CSV path"),
                     (["camera", "--lights", "no-such-light", "--scenes", "1"], "unknown camera light"),
                     (["synthetic", "--data", os.path.join(tmp, "nodata"), "--scenes", "1"], "missing data folder")]:
        r = run(*bad)
        check(r.returncode == 2 and r.stdout == "" and "gmcc: error:" in r.stderr, f"{why}: exit 2, message, no stdout")
        if "expansion" in why:
            check("--expand" in r.stderr and "1e150" in r.stderr, f"{why}: blames --expand")
    check(not os.path.exists(os.path.join(tmp, "no")), "nothing half-written")

sys.exit(tally.finish())
