#!/usr/bin/env python3
"""scripts/seed-claim and its report (docs/reproduction.md §5b) on a small run: every number of
the report's tables recomputed here from the runs' per-scene records and JSON cells.

1. The pooled table: each rule's mean error over the scenes where it gave a map, and the
   scored/drawn count where not all, from the records.
2. The share of scenes whose true map is in CRULE's F3, from the records.
3. The paired tables: CRULE rule minus the 3-D mean scene by scene, its standard error and count,
   pooled and per test light (for max-volume with black), from the records.
4. The shading and intensity conditions leave every 2-D rule's map unchanged, scene by scene.

usage: test_seed_claim_report.py GMCC_BINARY SOURCE_DIR   (ends with a line 'N passed, N failed')
"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Tally  # noqa: E402

CONDITIONS = ["none", "shading", "specular", "intensity"]


def records(path):
    with open(path) as f:
        return [r for r in (json.loads(line) for line in f) if "scene" in r]


def fmt(x):
    return "%.2f" % (0.0 if abs(x) < 0.005 else x)


def paired(recs, rule, light=None):
    d = [r["rules"][rule]["error_deg"] - r["rules"]["mean_3d"]["error_deg"] for r in recs
         if r["rules"].get(rule) and r["rules"].get("mean_3d") and (light is None or r["light"] == light)]
    mean = sum(d) / len(d)
    se = math.sqrt(sum((x - mean) ** 2 for x in d) / (len(d) - 1) / len(d))
    return "%s ± %s (%d)" % (fmt(mean), fmt(se), len(d))


def main(binary, source):
    with tempfile.TemporaryDirectory(prefix="gmcc-seed-claim-") as out:
        return check(binary, source, out)


def check(binary, source, out):
    t = Tally()
    build = os.path.join(out, "build")
    os.makedirs(os.path.join(build, "cli"))
    os.symlink(os.path.abspath(binary), os.path.join(build, "cli", "gmcc"))
    env = dict(os.environ, GMCC_BUILD_DIR=build, OUT=os.path.join(out, "sc"), SCENES="4", SURFACES="3",
               LIGHTS="D75,P2856", THREADS="2")
    p = subprocess.run([os.path.join(source, "scripts", "seed-claim")], env=env, capture_output=True,
                       text=True, timeout=600)
    t.check(p.returncode == 0, "scripts/seed-claim runs", p.stderr[-2000:])
    if p.returncode:
        return t.finish()
    sc = os.path.join(out, "sc")
    report = open(os.path.join(sc, "seed-claim.md")).read()
    recs = {(c, b): records(os.path.join(sc, "%s-%s.jsonl" % (c, b))) for c in CONDITIONS
            for b in ("include", "exclude")}
    t.check(all(len(v) == 2 * 3 * 4 for v in recs.values()), "every run has 2 lights x 3 counts x 4 scenes")

    # The report's tables, in order: pooled means, truth in F3, paired, paired per light.
    lines = report.splitlines()
    starts = [lines.index(next(l for l in lines if l.startswith(head)))
              for head in ("True diagonal map", "Paired per-scene", "The same paired difference")]

    def table(k):
        part = lines[([0] + starts)[k]:(starts + [len(lines)])[k]]
        return {l.split(" | ")[0].lstrip("| "): l for l in part if l.startswith("| ")}

    # 1. Pooled means: the 3-D mean's, CRULE max-volume's with black, the centroid's without.
    rows = table(0)
    for label, rule, black in (("3-D mean (perspective)", "mean_3d", "include"),
                               ("CRULE max-volume, with black", "crule_max_volume", "include"),
                               ("CRULE centroid, without black", "crule_centroid", "exclude")):
        cells = rows[label].strip("| ").split(" | ")[1:]
        for c, cell in zip(CONDITIONS, cells):
            scored = [r["rules"][rule]["error_deg"] for r in recs[(c, black)] if r["rules"].get(rule)]
            mean = fmt(sum(scored) / len(scored))
            t.check(cell.startswith(mean + " ± "), "%s under %s: mean %s" % (label, c, mean), cell)
            drawn = len(recs[(c, black)])
            t.check(("(%d/%d)" % (len(scored), drawn) in cell) == (len(scored) != drawn),
                    "%s under %s: scored/drawn shown exactly when not all" % (label, c), cell)

    # 2. True map in F3.
    rows = table(1)
    for word, black in (("with black", "include"), ("without black", "exclude")):
        cells = rows[word].strip("| ").split(" | ")[1:]
        for c, cell in zip(CONDITIONS, cells):
            inside = sum(1 for r in recs[(c, black)] if r["rules"]["crule_max_volume"]["truth_in_feasible_set"]) \
                if all(r["rules"].get("crule_max_volume") for r in recs[(c, black)]) else None
            if inside is not None:
                t.check(cell == "%.0f%%" % (100.0 * inside / len(recs[(c, black)])), "truth in F3, %s, %s" % (word, c), cell)

    # 3. Paired tables, pooled and per light.
    pooled_rows = table(2)
    for rule, label in (("crule_max_volume", "CRULE max-volume"), ("crule_cone_mean", "CRULE cone mean")):
        for black, word in (("include", "with black"), ("exclude", "without black")):
            row = pooled_rows["%s, %s" % (label, word)]
            cells = row.strip("| ").split(" | ")[1:]
            for c, cell in zip(CONDITIONS, cells):
                want = paired(recs[(c, black)], rule)
                t.check(cell == want, "paired %s, %s, %s" % (label, word, c), "%s != %s" % (cell, want))
    light_rows = table(3)
    for light in ("D75", "P2856"):
        cells = light_rows[light].strip("| ").split(" | ")[1:]
        for c, cell in zip(CONDITIONS, cells):
            want = paired(recs[(c, "include")], "crule_max_volume", light)
            t.check(cell == want, "paired per light %s, %s" % (light, c), "%s != %s" % (cell, want))

    # 4. Shading and intensity move no 2-D rule's map.
    for c in ("shading", "intensity"):
        same = all(a["rules"][k]["map"] == b["rules"][k]["map"]
                   for a, b in zip(recs[("none", "include")], recs[(c, "include")])
                   for k in ("max_area", "mean_2d", "mean_3d"))
        t.check(same, "%s leaves the 2-D rules' maps unchanged" % c)
    t.check(os.path.exists(os.path.join(sc, "seed-claim.dat")), "the figure's data is written")
    return t.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
