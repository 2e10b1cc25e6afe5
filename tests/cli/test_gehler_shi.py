#!/usr/bin/env python3
"""`gmcc reproduce gehler-shi` end to end on the shipped Gehler-Shi charts, reduced: the same
bytes for any thread count, both protocols, the CSV's baseline rows, and bad data or options
refused with exit 2 naming the file and line, nothing written.

usage: test_gehler_shi.py GMCC_BINARY DATA_DIR     (ends with a line 'N passed, N failed')
"""
import csv
import io
import os
import shutil
import subprocess
import sys

import tempfile

from cli_harness import Tally

gmcc, data = sys.argv[1], sys.argv[2]
PATCHES = "gehler_shi_568_colorchecker_patch_rgb_rec2018.csv"
TRUTH = "gehler_shi_568_groundtruth.csv"


tally = Tally()
check = tally.check


def run(*args):
    return subprocess.run([gmcc, "reproduce", "gehler-shi", *args], capture_output=True, text=True)


def without_provenance(text):
    return "\n".join(l for l in text.splitlines() if not l.startswith(("# gmcc-provenance", '{"provenance"')))


with tempfile.TemporaryDirectory() as tmp:
    small = ["--scenes", "2", "--surfaces", "4", "--seed", "3"]
    outs = {}
    for t in ("1", "2"):
        csv_path, rec = os.path.join(tmp, f"t{t}.csv"), os.path.join(tmp, f"t{t}.jsonl")
        r = run(*small, "--threads", t, "--csv", csv_path, "--scenes-out", rec)
        check(r.returncode == 0, f"--threads {t} runs: {r.stderr}")
        outs[t] = (r.stdout, open(csv_path, "rb").read(), open(rec, "rb").read())
    check(outs["1"] == outs["2"], "--threads 1 and 2: identical table, CSV and records (bytes)")
    rows = list(csv.DictReader(io.StringIO(without_provenance(outs["1"][1].decode()))))
    groups = sorted({r["illuminant"] for r in rows})
    check(groups == ["Canon1D", "Canon5D"], f"leave-one-out rows per camera: {groups}")
    rules = sorted({r["rule"] for r in rows})
    check(rules == sorted(["max_area", "mean_2d", "mean_3d", "grey_world", "max_rgb", "grey_world_all",
                           "max_rgb_all"]), f"rules and baselines: {rules}")
    for r in rows:
        if r["rule"] == "grey_world":  # baselines over the rules' scenes: the same count
            rule = next(x for x in rows if x["illuminant"] == r["illuminant"] and x["surfaces"] == r["surfaces"]
                        and x["rule"] == "mean_3d")
            check(r["scenes"] == rule["scenes"] and r["mean_worst_case_deg"] == "", "grey_world row")
        if r["rule"] == "grey_world_all":
            check(int(r["scenes"]) >= int(r["empty_scenes"]), "grey_world_all counts every scene")
    canon1d_n1 = next(x for x in rows if x["illuminant"] == "Canon1D" and x["surfaces"] == "1"
                      and x["rule"] == "grey_world_all")
    check(canon1d_n1["scenes"] == str(86 * 2), "Canon1D, one patch: 2 scenes for each of its 86 images")
    rec = outs["1"][2].decode().splitlines()
    check('"surface_indices":"chart patch numbers 1-24"' in rec[1], "records say what drawn holds")
    check('"baselines":{"grey_world"' in rec[2], "a scene record has its baselines")
    m = subprocess.run([gmcc, "merge", os.path.join(tmp, "t1.jsonl")], capture_output=True, text=True)
    check(m.returncode == 2 and "cannot be merged" in m.stderr and m.stdout == "", f"merge refuses: {m.stderr}")

    r = run(*small, "--protocol", "paper", "--cameras", "Canon5D", "--threads", "2")
    check(r.returncode == 0 and "Canon5D yellowish" in r.stdout and "Canon5D bluish" in r.stdout
          and "Canon1D" not in r.stdout.split("\n", 3)[3], "paper protocol: Canon5D's two groups")
    check("chart of IMG_" in r.stdout, "paper protocol names its canonical chart")

    # Bad data: a malformed ground-truth row; nothing written.
    bad = os.path.join(tmp, "bad")
    os.mkdir(bad)
    shutil.copy(os.path.join(data, PATCHES), bad)
    lines = open(os.path.join(data, TRUTH)).read().splitlines(True)
    lines[5] = lines[5].rsplit(",", 1)[0] + ",0.2x\n"  # rec2018_b malformed
    open(os.path.join(bad, TRUTH), "w").write("".join(lines))
    out_csv = os.path.join(tmp, "bad.csv")
    r = run(*small, "--data", bad, "--csv", out_csv)
    check(r.returncode == 2 and f"{TRUTH}:6" in r.stderr, f"malformed GT row: exit 2 naming file:line: {r.stderr}")
    check(not os.path.exists(out_csv), "nothing written for bad data")
    # A NaN in one channel only.
    plines = open(os.path.join(data, PATCHES)).read().splitlines(True)
    f = plines[10].rstrip("\n").split(",")
    f[4] = "NaN"
    plines[10] = ",".join(f) + "\n"
    open(os.path.join(bad, PATCHES), "w").write("".join(plines))
    shutil.copy(os.path.join(data, TRUTH), bad)
    r = run(*small, "--data", bad)
    check(r.returncode == 2 and f"{PATCHES}:11" in r.stderr, f"partial NaN: exit 2 naming file:line: {r.stderr}")

    # Options that leave a camera no patch blame the options, not the data file (issue 30).
    r = run(*small, "--dark", "0.9", "--clip", "0.95")
    check(r.returncode == 2 and r.stderr.startswith("gmcc: error: --dark/--clip: camera") and "no usable patch" in r.stderr
          and "dark 9/10" in r.stderr, f"dark/clip emptying a camera blame the options: {r.stderr}")

    for args, what in ((["--dark", "0.5", "--clip", "0.4"], "--dark"), (["--cameras", "Nikon"], "--cameras"),
                       (["--clip", "x"], "--clip"), (["--exclude-patches", "0"], "--exclude-patches"),
                       (["--exclude-patches", "1.0"], "--exclude-patches"), (["--exclude-patches", "1,,2"], "--exclude-patches"),
                       (["--exclude-patches", "3,"], "--exclude-patches"), (["--shard", "1/2", "--scenes-out", out_csv], "--shard")):
        r = run(*small, *args)
        check(r.returncode == 2 and what in r.stderr, f"{args}: exit 2 naming {what}: {r.stderr}")

sys.exit(tally.finish())
