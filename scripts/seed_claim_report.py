#!/usr/bin/python3
"""The seed-claim table and figure (docs/reproduction.md §5b) from the --json files that
scripts/seed-claim writes: one `gmcc reproduce synthetic --crule --crule-extended` run per world
condition and per canonical black (include, exclude).

    seed_claim_report.py DIR   # reads DIR/<condition>-<black>.json, writes DIR/seed-claim.md,
                               # DIR/seed-claim.dat and DIR/seed-claim.gp (gnuplot draws the .png/.svg)

Every number is pooled over the run's cells (lights x surface counts): a rule's mean error is
sum(n_cell * mean_cell) / sum(n_cell) over the scenes in which it gave a map, and `scored` says
how many scenes that was. Debian's python3 and its standard library only.
"""
import json
import os
import sys

CONDITIONS = [
    ("none", "world restrictions hold"),
    ("shading", "shading"),
    ("specular", "specular highlights"),
    ("intensity", "scene intensity change"),
]
RULES_2D = ["max_area", "mean_2d", "mean_3d"]
RULES_3D = ["crule_max_volume", "crule_centroid", "crule_max_trace", "crule_cone_mean"]
TITLES = {
    "max_area": "2-D max-area", "mean_2d": "2-D mean", "mean_3d": "3-D mean (perspective)",
    "crule_max_volume": "CRULE max-volume", "crule_centroid": "CRULE centroid",
    "crule_max_trace": "CRULE max-trace", "crule_cone_mean": "CRULE cone mean",
}


def load(directory, condition, black):
    path = os.path.join(directory, "%s-%s.json" % (condition, black))
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def pooled(run, rule, by_surfaces=False):
    """(mean error, scenes scored, truth in F) pooled over cells; per n when by_surfaces."""
    acc = {}
    for cell in run["cells"]:
        stats = cell["rules"].get(rule)
        if stats is None:
            continue
        key = cell["surfaces"] if by_surfaces else 0
        e = stats["error_deg"]
        s = acc.setdefault(key, [0.0, 0, 0, 0, 0.0])
        if e["n"]:
            s[0] += e["n"] * e["mean"]
            # the cells are independent: var(pooled mean) = sum n^2 se^2 / (sum n)^2
            se = e["se"] if e["se"] is not None else 0.0
            s[4] += (e["n"] * se) ** 2
        s[1] += e["n"]
        s[2] += stats["truth_in_feasible_set"]
        s[3] += cell["scenes"]
    out = {k: (v[0] / v[1] if v[1] else float("nan"), v[1], v[2], v[3],
               v[4] ** 0.5 / v[1] if v[1] else float("nan")) for k, v in acc.items()}
    return out if by_surfaces else out.get(0)


def columns(runs):
    """(label, run, rule) for every line of the table, in order."""
    cols = []
    base = runs.get("include") or runs.get("exclude")
    for r in RULES_2D:
        cols.append((TITLES[r], base, r))
    for black, word in (("include", "with black"), ("exclude", "without black")):
        if runs.get(black):
            for r in RULES_3D:
                if r in runs[black]["setup"]["rules"]:
                    cols.append(("%s, %s" % (TITLES[r], word), runs[black], r))
    return cols


def fmt(x):
    if x != x:
        return "–"
    return "%.2f" % (0.0 if abs(x) < 0.005 else x)  # no "-0.00"


def main(argv):
    directory = argv[1] if len(argv) > 1 else "out/seed-claim"
    runs = {c: {b: load(directory, c, b) for b in ("include", "exclude")} for c, _ in CONDITIONS}
    present = [(c, t) for c, t in CONDITIONS if runs[c]["include"] or runs[c]["exclude"]]
    if not present:
        sys.exit("seed_claim_report.py: no <condition>-<black>.json in " + directory)
    first = runs[present[0][0]]["include"] or runs[present[0][0]]["exclude"]
    setup = first["setup"]
    lines = []
    lines.append("Scenes per cell: %d; surface counts %d..%d; lights %s; seed %d. Mean map-space angular "
                 "error in degrees, pooled over every cell, over the scenes where the rule gave a map "
                 "± its standard error (cells independent; a cell of one scene counts 0); scored / drawn "
                 "scenes in brackets when not all." % (
                     setup["scenes"], setup["min_surfaces"], setup["max_surfaces"], ", ".join(setup["lights"]),
                     setup["seed"]))
    lines.append("")
    header = "| rule | " + " | ".join(
        "%s (`%s`)" % (t, options(runs[c])) for c, t in present) + " |"
    lines.append(header)
    lines.append("|---|" + "---|" * len(present))
    labels = [label for label, _, _ in columns(runs[present[0][0]])]
    for i, label in enumerate(labels):
        row = "| " + label + " |"
        for c, _ in present:
            cols = columns(runs[c])
            if i >= len(cols):
                row += " |"
                continue
            m, n, _, total, se = pooled(cols[i][1], cols[i][2])
            row += " " + fmt(m) + " ± " + fmt(se) + ("" if n == total else " (%d/%d)" % (n, total)) + " |"
        lines.append(row)
    lines.append("")
    lines.append("True diagonal map inside CRULE's F3 (share of drawn scenes):")
    lines.append("")
    lines.append("| canonical gamut | " + " | ".join(t for _, t in present) + " |")
    lines.append("|---|" + "---|" * len(present))
    for black, word in (("include", "with black"), ("exclude", "without black")):
        row = "| " + word + " |"
        for c, _ in present:
            run = runs[c][black]
            if not run:
                row += " |"
                continue
            _, _, truth, total, _ = pooled(run, "crule_max_volume")
            row += " %.0f%% |" % (100.0 * truth / total if total else float("nan"))
        lines.append(row)
    paired_rows = paired_table(directory, present)
    if paired_rows:
        lines.append("")
        lines.extend(paired_rows)
        lines.append("")
        lines.extend(paired_by_light(directory, present, setup["lights"]))
    with open(os.path.join(directory, "seed-claim.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    write_figure(directory, runs, present)


def paired(directory, condition, black, rule, against="mean_3d", light=None):
    """Mean and standard error of the per-scene difference error(rule) - error(against), over the
    scenes of the records DIR/<condition>-<black>.jsonl where both gave a map (under `light` only,
    when given); None without them."""
    path = os.path.join(directory, "%s-%s.jsonl" % (condition, black))
    if not os.path.exists(path):
        return None
    d = []
    with open(path) as f:
        for line in f:
            x = json.loads(line)
            rules = x.get("rules")
            if "scene" not in x or not rules or not rules.get(rule) or not rules.get(against):
                continue
            if light is not None and x.get("light") != light:
                continue
            d.append(rules[rule]["error_deg"] - rules[against]["error_deg"])
    if not d:
        return None
    mean = sum(d) / len(d)
    se = (sum((v - mean) ** 2 for v in d) / (len(d) - 1) / len(d)) ** 0.5 if len(d) > 1 else float("nan")
    return mean, se, len(d)


def paired_by_light(directory, present, lights, rule="crule_max_volume", black="include"):
    """Rows of the paired-difference table of one CRULE rule per test light."""
    rows = ["The same paired difference for %s, %s, per test light:" % (
                TITLES[rule], "with black" if black == "include" else "without black"), "",
            "| light | " + " | ".join(t for _, t in present) + " |", "|---|" + "---|" * len(present)]
    any_records = False
    for light in lights:
        row = "| %s |" % light
        for c, _ in present:
            p = paired(directory, c, black, rule, light=light)
            any_records = any_records or p is not None
            row += " |" if p is None else " %s ± %s (%d) |" % (fmt(p[0]), fmt(p[1]), p[2])
        rows.append(row)
    return rows if any_records else []


def paired_table(directory, present):
    """Rows of the paired-difference table (CRULE rule minus the 3-D mean, scene by scene)."""
    rows = ["Paired per-scene difference, CRULE rule minus the perspective 3-D mean, in degrees "
            "(negative: CRULE better), ± its standard error, over the scenes where both gave a map "
            "(their number in brackets):", "",
            "| rule | " + " | ".join(t for _, t in present) + " |", "|---|" + "---|" * len(present)]
    any_records = False
    for black, word in (("include", "with black"), ("exclude", "without black")):
        for r in RULES_3D:
            row = "| %s, %s |" % (TITLES[r], word)
            for c, _ in present:
                p = paired(directory, c, black, r)
                any_records = any_records or p is not None
                row += " |" if p is None else " %s ± %s (%d) |" % (fmt(p[0]), fmt(p[1]), p[2])
            rows.append(row)
    return rows if any_records else []


def options(pair):
    run = pair["include"] or pair["exclude"]
    s = run["setup"]
    for key in ("shading", "specular", "intensity"):
        if s.get(key):
            return "--%s %g" % (key, s[key])
    return "no option"


def write_figure(directory, runs, present):
    """seed-claim.dat: per condition (gnuplot index), per n, each column's pooled mean error."""
    with open(os.path.join(directory, "seed-claim.dat"), "w") as dat:
        labels = None
        for c, t in present:
            cols = columns(runs[c])
            labels = labels or [label for label, _, _ in cols]
            dat.write("# %s: surfaces, mean error of: %s\n" % (t, "; ".join(l for l, _, _ in cols)))
            per = [pooled(run, rule, True) for _, run, rule in cols]
            for n in sorted(per[0]):
                dat.write("%d %s\n" % (n, " ".join("%.6g" % p[n][0] if n in p and p[n][0] == p[n][0] else "NaN"
                                                    for p in per)))
            dat.write("\n\n")
    styles = ["lc rgb '#d62728' lw 2 pt 7", "lc rgb '#1f77b4' lw 2 pt 5", "lc rgb '#2ca02c' lw 3 pt 9",
              "lc rgb '#9467bd' lw 2 pt 11", "lc rgb '#8c564b' lw 2 pt 13", "lc rgb '#e377c2' lw 2 pt 15",
              "lc rgb '#7f7f7f' lw 2 pt 4",
              "lc rgb '#9467bd' lw 2 pt 11 dt 2", "lc rgb '#8c564b' lw 2 pt 13 dt 2",
              "lc rgb '#e377c2' lw 2 pt 15 dt 2", "lc rgb '#7f7f7f' lw 2 pt 4 dt 2"]
    g = ["# the seed's claim (docs/reproduction.md §5b): mean error against the number of surfaces",
         "set datafile missing 'NaN'", "set xlabel 'number of surfaces'", "set ylabel 'mean error (deg)'",
         "set xrange [0.5:%d.5]" % max(c["surfaces"] for c in (runs[present[0][0]]["include"] or runs[present[0][0]]["exclude"])["cells"]),
         "set yrange [0:*]", "set grid lc rgb '#dddddd'", "set key outside right top font ',8'"]
    g.append("do for [term = 1:2] {")
    g.append("  if (term == 1) { set terminal pngcairo size 1300,%d font ',9'; set output 'seed-claim.png' }"
             % (300 * len(present)))
    g.append("  if (term == 2) { set terminal svg size 1300,%d font 'sans,9'; set output 'seed-claim.svg' }"
             % (300 * len(present)))
    g.append("  set multiplot layout %d,1" % len(present))
    for i, (c, t) in enumerate(present):
        cols = columns(runs[c])
        g.append("  set title '%s (%s)'" % (t, options(runs[c])))
        parts = []
        for k, (label, _, _) in enumerate(cols):
            parts.append("%s index %d using 1:%d with linespoints %s title '%s'" % (
                "'seed-claim.dat'" if k == 0 else "''", i, k + 2, styles[k % len(styles)], label))
        g.append("  plot " + ", ".join(parts))
    g.append("  unset multiplot\n  set output\n}")
    with open(os.path.join(directory, "seed-claim.gp"), "w") as f:
        f.write("\n".join(g) + "\n")


if __name__ == "__main__":
    main(sys.argv)
