#!/usr/bin/env python3
"""Gamut mapping on photographs from the command line (docs/photographs.md): `gmcc canonical
--space 3d`, `gmcc estimate --space 3d`, the chromaticity-lift trap refused everywhere, and
`gmcc benchmark`, on 16-bit PNGs this test writes, whose every sample it knows.

The scene: integer surfaces S under integer lights e, pixel = s ⊙ e exactly. Then:
- the learned 3-D canonical gamut is the hull of S scaled by its largest channel, exactly (checked
  against the hull's defining property: every learned colour is a surface, each surface in the hull);
- an image showing every surface under a new light has F3 = the segment from 0 to the true map's
  direction, so every 3-D rule recovers the light to rounding (1e-9 deg);
- chromaticity lifts (gmcc canonical's 2-D file, header r/b,g/b,1) fed to the 3-D routes exit 2;
- `gmcc benchmark`: grey world equals an independent implementation of grey world on the same
  pixels (Gijsenij et al.'s rule written here in integers); --folds K and the equivalent folds file
  give the same records; the CSV has one row per method; bad tables exit 2 naming file and line;
  the edge-based methods' feasible sets nest as intersections do (a true light inside a 1-jet or
  2-jet set is inside each of its types' sets), and their bad options exit 2.

    test_photographs.py GMCC_BINARY
"""

import csv
import json
import os
import random
import sys
import tempfile

from cli_harness import Runner, angle, expect, random_triples  # noqa: E402
from png16 import write_grey_png, write_png16  # noqa: E402


def main():
    binary = sys.argv[1]
    rng = random.Random(26)
    surfaces = random_triples(rng, 12, 20, 900)
    lights = random_triples(rng, 9, 3, 40)
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp)
        names = []
        for i, e in enumerate(lights):
            rows = [[tuple(s[k] * e[k] for k in range(3)) for s in surfaces] for _ in range(4)]
            name = f"img{i}.png"
            write_png16(os.path.join(tmp, name), rows)
            names.append(name)
        truths = os.path.join(tmp, "truths.csv")
        with open(truths, "w") as f:
            f.write("\ufeffimage,r,g,b\n")  # a byte-order mark, as spreadsheets write
            for name, e in zip(names, lights):
                f.write(f"{name},{e[0]},{e[1]},{e[2]}\n")
        paths = [os.path.join(tmp, n) for n in names]
        canonical3 = os.path.join(tmp, "c3.csv")
        canonical2 = os.path.join(tmp, "c2.csv")

        def learned_3d_gamut():
            rc, out, err = r.run("canonical", "--from-images", "--space", "3d", "--truths", truths,
                                 "--saturation", "none", "--out", canonical3, *paths[:6], prefix=[])
            expect(rc == 0, err)
            lines = [x for x in open(canonical3).read().splitlines() if not x.startswith("#")]
            expect(lines[0] == "r,g,b", lines[0])
            from fractions import Fraction
            got = [tuple(Fraction(v) for v in x.split(",")) for x in lines[1:]]
            top = max(max(s) for s in surfaces)
            scaled = {tuple(Fraction(c, top) for c in s) for s in surfaces}
            expect(set(got) <= scaled, "every learned vertex is a scaled surface")
            expect(max(max(c) for c in got) == 1, "the largest channel is 1 (--intensity max)")
            expect(len(got) >= 4, got)

        def estimate_3d_recovers_the_light():
            rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--truths", truths,
                                 "--saturation", "none", "--json", *paths[6:], prefix=[])
            expect(rc == 0, err)
            doc = json.loads(out)
            expect(doc["space"] == "3d" and len(doc["images"]) == 3, doc.keys())
            for im in doc["images"]:
                expect(im["feasible_set"]["kind"] == "segment", im["feasible_set"])
                for rule in ("max_volume", "centroid", "max_trace"):
                    e = im["estimates"][rule]
                    expect(e["recovery_error_deg"] < 1e-9, (im["file"], rule, e))
                    expect(e["worst_case_deg"] < 1e-9, (rule, e))
            rc, text, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--rules",
                                  "max-trace", "--saturation", "none", paths[7], prefix=[])
            expect(rc == 0 and "max_trace  light" in text and "centroid" not in text, text)

        def lifts_are_refused():
            rc, out, err = r.run("canonical", "--from-images", "--truths", truths, "--saturation", "none",
                                 "--out", canonical2, *paths[:6], prefix=[])
            expect(rc == 0, err)
            lines = [x for x in open(canonical2).read().splitlines() if not x.startswith("#")]
            expect(lines[0] == "r/b,g/b,1", lines[0])
            for args in (["estimate", "--space", "3d", "--canonical", canonical2, paths[7]],
                         ["select", "--space", "3d", "--canonical", canonical2, "--image", canonical3]):
                rc, out, err = r.run(*args, prefix=[])
                expect(rc == 2 and out == "" and "chromaticity lifts" in err, (args[0], rc, err))
                expect(err.startswith(f"gmcc: error: {canonical2}:"), err)
            rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--colour-set", "hull",
                                 paths[7], prefix=[])
            expect(rc == 2 and "chromaticity lifts" in err, err)
            # The 2-D route takes the lifts file as before.
            rc, out, err = r.run("estimate", "--canonical", canonical2, "--saturation", "none", paths[7], prefix=[])
            expect(rc == 0, err)
            for opt in (["--expand", "0.1", "--expand-policy", "multiplicative"], ["--on-empty", "grow-canonical"]):
                rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, *opt, paths[7], prefix=[])
                expect(rc == 2 and "--space 3d" in err, err)
            rc, out, err = r.run("estimate", "--canonical", canonical2, "--rules", "max-trace", paths[7], prefix=[])
            expect(rc == 2 and "applies to --space 3d" in err, err)

        def corrected_at_scale():
            # 70 images × 3 rules: more files than any fixed table of temporaries; all written.
            many = os.path.join(tmp, "many")
            os.makedirs(many)
            inputs = []
            for i in range(70):
                p = os.path.join(many, f"m{i:02d}.png")
                write_png16(p, [[tuple(s[k] * lights[i % 9][k] for k in range(3)) for s in surfaces[:6]]] * 2)
                inputs.append(p)
            out = os.path.join(tmp, "corrected")
            rc, text, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--saturation", "none",
                                  "--corrected", out, *inputs, prefix=[])
            expect(rc == 0, err)
            expect(sorted(os.listdir(out)) == sorted(f"m{i:02d}_{rule}.png" for i in range(70)
                                                     for rule in ("max_volume", "centroid", "max_trace")),
                   sorted(os.listdir(out))[:5])
            # A bad image last: exit 2 and nothing written, no temporary left.
            bad = os.path.join(tmp, "bad.png")
            with open(bad, "wb") as f:
                f.write(b"not a png")
            out2 = os.path.join(tmp, "corrected2")
            rc, text, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--saturation", "none",
                                  "--corrected", out2, *inputs[:30], bad, prefix=[])
            expect(rc == 2 and os.listdir(out2) == [], (rc, err, os.listdir(out2)[:3]))
            # Two inputs with one stem would write the same names: refused before any work.
            other = os.path.join(tmp, "other")
            os.makedirs(other)
            twin = os.path.join(other, "m00.png")
            write_png16(twin, [[(1, 2, 3)]])
            out3 = os.path.join(tmp, "corrected3")
            rc, text, err = r.run("estimate", "--canonical", canonical2, "--corrected", out3, inputs[0], twin, prefix=[])
            expect(rc == 2 and "same stem" in err and not os.path.exists(out3), (rc, err))

        r.check_all(learned_3d_gamut, estimate_3d_recovers_the_light, lifts_are_refused, corrected_at_scale)

        # A noisy dataset for the benchmark: 12 images of random surfaces, some dark, some bright.
        bench = os.path.join(tmp, "bench")
        os.makedirs(bench)
        table = ["image,r,g,b"]
        pixels_of = {}
        for i in range(12):
            e = (rng.randint(3, 30), rng.randint(3, 30), rng.randint(3, 30))
            rows = [[tuple(min(65535, rng.randint(0, 2000) * e[k] // 10) for k in range(3)) for _ in range(9)]
                    for _ in range(7)]
            name = f"b{i:02d}.png"
            write_png16(os.path.join(bench, name), rows)
            pixels_of[name] = rows
            table.append(f"{name},{e[0]},{e[1]},{e[2]}")
        bench_truths = os.path.join(tmp, "bench_truths.csv")
        with open(bench_truths, "w") as f:
            f.write("\n".join(table) + "\n")
        folds_file = os.path.join(tmp, "folds.csv")
        with open(folds_file, "w") as f:
            f.write("image,fold\n" + "".join(f"b{i:02d}.png,{i % 3}\n" for i in range(12)))
        base = ["benchmark", "--images", bench, "--truths", bench_truths, "--pixel-rule", "gijsenij",
                "--saturation", "none", "--no-progress"]

        def grey_world_independent():
            records = os.path.join(tmp, "records.jsonl")
            rc, out, err = r.run(*base, "--folds", "3", "--methods", "grey-world", "--records", records, prefix=[])
            expect(rc == 0, err)
            lines = [json.loads(x) for x in open(records)]
            expect("provenance" in lines[0], lines[0].keys())
            expect(lines[1] == {"benchmark": {"images": 12, "methods": ["grey-world"], "shard": "1/1"}}, lines[1])
            for rec in lines[2:]:
                rows = pixels_of[rec["image"]]
                m = max(max(p) for row in rows for p in row)
                kept = [p for row in rows for p in row if all(255 * c >= 5 * m and 255 * c <= 245 * m for c in p)]
                mean = [sum(p[k] for p in kept) for k in range(3)]
                expect(angle(mean, rec["light"]) < 1e-12, (rec["image"], mean, rec["light"]))
                e = [int(x) for x in next(t for t in table if t.startswith(rec["image"])).split(",")[1:]]
                expect(abs(angle(mean, e) - rec["error_deg"]) < 1e-9, rec)

        def folds_file_equals_folds_k():
            a, b = os.path.join(tmp, "a.jsonl"), os.path.join(tmp, "b.jsonl")
            rc, out_a, err = r.run(*base, "--folds", "3", "--records", a, "--csv", os.path.join(tmp, "a.csv"), prefix=[])
            expect(rc == 0, err)
            rc, out_b, err = r.run(*base, "--folds-file", folds_file, "--records", b, prefix=[])
            expect(rc == 0, err)
            ra, rb = open(a).read().splitlines()[2:], open(b).read().splitlines()[2:]
            expect(ra == rb and out_a == out_b, "the same records and table")
            expect(len(ra) == 12 * 11, len(ra))
            with open(os.path.join(tmp, "a.csv")) as f:
                rows = list(csv.DictReader(x for x in f if not x.startswith("#")))
            expect([x["method"] for x in rows][:3] == ["gm3d-max-trace", "gm3d-max-volume", "gm3d-centroid"], rows)
            for x in rows:
                expect(int(x["images"]) == 12 and float(x["median_deg"]) >= 0, x)
            # One thread or two: the same bytes.
            c = os.path.join(tmp, "c.jsonl")
            rc, out_c, err = r.run(*base, "--folds", "3", "--records", c, "--threads", "1", prefix=[])
            expect(open(c).read() == open(a).read(), "threads change nothing")

        def bad_tables():
            bad = os.path.join(tmp, "bad.csv")
            for text, where in (("image,r,g,b\nb00.png,1,0,1\n", ":2:"), ("image,r,g,b,colour\n", ":1:"),
                                ("image,r,g,b\nb00.png,1,1,1\nb00.png,1,1,1\n", ":3:")):
                with open(bad, "w") as f:
                    f.write(text)
                rc, out, err = r.run("benchmark", "--images", bench, "--truths", bad, "--folds", "2", prefix=[])
                expect(rc == 2 and f"{bad}{where}" in err and out == "", (text, rc, err))
            rc, out, err = r.run("benchmark", "--images", bench, "--truths", bench_truths, prefix=[])
            expect(rc == 2 and "--folds" in err, err)
            with open(bad, "w") as f:
                f.write("image,fold\nb00.png,0\n")
            rc, out, err = r.run("benchmark", "--images", bench, "--truths", bench_truths, "--folds-file", bad, prefix=[])
            expect(rc == 2 and "no fold for image b01.png" in err, err)

        def shards_merge_to_the_whole_run():
            whole = {k: os.path.join(tmp, f"whole.{k}") for k in ("csv", "json", "jsonl")}
            rc, table, err = r.run(*base, "--folds", "3", "--csv", whole["csv"], "--json", whole["json"],
                                   "--records", whole["jsonl"], prefix=[])
            expect(rc == 0, err)
            parts = []
            for k in (1, 2, 3, 4):
                part = os.path.join(tmp, f"part{k}.jsonl")
                rc, out, err = r.run(*base, "--folds", "3", "--shard", f"{k}/4", "--records", part, prefix=[])
                expect(rc == 0, err)
                parts.append(part)
            merged = {k: os.path.join(tmp, f"merged.{k}") for k in ("csv", "json", "jsonl")}
            rc, merged_table, err = r.run("merge", "--csv", merged["csv"], "--json", merged["json"], "--records",
                                          merged["jsonl"], "--plot", os.path.join(tmp, "merged_plot"),
                                          *reversed(parts), prefix=[])
            expect(rc == 0, err)
            expect(merged_table == table, "the same table")
            for k in whole:
                expect(open(whole[k], "rb").read() == open(merged[k], "rb").read(), f"merged {k} differs")
            # The figure's data: every method's errors, sorted, with the share at or below each.
            dat = open(os.path.join(tmp, "merged_plot", "benchmark.dat")).read()
            blocks = [b for b in dat.split("\n\n\n") if b.strip()]
            expect(len(blocks) == 12, len(blocks))  # 11 methods' curves, then the percentiles
            for block in blocks[:11]:
                rows = [[float(v) for v in x.split()] for x in block.splitlines() if x and not x.startswith("#")]
                expect(len(rows) == 12 and rows[-1][1] == 1.0, rows[-1:])
                expect([x[0] for x in rows] == sorted(x[0] for x in rows), "sorted")
            expect(os.path.exists(os.path.join(tmp, "merged_plot", "benchmark.gp")), "the script")
            rc, out, err = r.run("merge", "--records", merged["jsonl"], *parts[:3], prefix=[])
            expect(rc == 2 and "a shard is missing" in err, err)
            rc, out, err = r.run("merge", "--records", merged["jsonl"], parts[0], parts[0], *parts[1:], prefix=[])
            expect(rc == 2 and "already in another file" in err, err)
            rc, out, err = r.run(*base, "--folds", "3", "--shard", "1/4", prefix=[])
            expect(rc == 2 and "--records" in err, err)
            rc, out, err = r.run(*base, "--folds", "3", "--shard", "5/4", "--records", merged["jsonl"], prefix=[])
            expect(rc == 2 and "--shard" in err, err)

        def per_image_rules_in_the_truth_table():
            # estimate and canonical take each image's black level, saturation and chart from the
            # truth table, the same as the options for that one image.
            own = os.path.join(tmp, "own_rules.csv")
            with open(own, "w") as f:
                f.write("image,r,g,b,black_level,saturation,chart\n")
                for line in table[1:]:
                    name = line.split(",")[0]
                    f.write(f"{line},300,60000,0 0 4 0 4 3 0 3\n" if name == "b03.png" else f"{line},,,\n")
            img = os.path.join(bench, "b03.png")
            rc, a, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--truths", own, "--json", img,
                               prefix=[])
            expect(rc == 0, err)
            rc, b, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--truths", bench_truths,
                               "--black-level", "300", "--saturation", "60000", "--exclude-polygon",
                               "0,0,4,0,4,3,0,3", "--json", img, prefix=[])
            expect(rc == 0, err)
            ja, jb = json.loads(a), json.loads(b)
            expect(ja["images"] == jb["images"], "the same image record")
            expect(ja["images"][0]["pixels"]["masked"] == 12, ja["images"][0]["pixels"])

        def grey_and_one_bit_masks():
            # The usual masks: 1-bit and 8-bit grey PNGs, zero where excluded (9 × 7 images).
            img = os.path.join(bench, "b05.png")
            counts = []
            for depth in (1, 8):
                mask = os.path.join(tmp, f"mask{depth}.png")
                on = 1 if depth == 1 else 255
                write_grey_png(mask, [[0 if (x < 3 and y < 2) else on for x in range(9)] for y in range(7)], depth)
                rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--mask", mask,
                                     "--json", img, prefix=[])
                expect(rc == 0, err)
                counts.append(json.loads(out)["images"][0]["pixels"]["masked"])
            expect(counts == [6, 6], counts)
            rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical3, "--prefilter", "1", img,
                                 prefix=[])
            expect(rc == 0 and "max_trace  light" in out, err)
            rc, out, err = r.run("estimate", "--canonical", canonical2, "--prefilter", "1", "--bin", "2", img, prefix=[])
            expect(rc == 2 and "--prefilter" in err, err)

        def edge_methods_intersect():
            # The 1-jet's feasible set is the pixel one's intersected with the 1st-order edge one's,
            # and the 2-jet's is the 1-jet's intersected with the 2nd-order one's: a true light in
            # a jet's set is in each of its types' sets (each learned from the same fold).
            edge = ["gm3d-max-trace", "gm3d-edge1-max-trace", "gm3d-edge2-max-trace", "gm3d-1jet-max-trace",
                    "gm3d-2jet-max-trace"]
            records = os.path.join(tmp, "edges.jsonl")
            rc, out, err = r.run(*base, "--folds", "3", "--methods", ",".join(edge), "--records", records, prefix=[])
            expect(rc == 0, err)
            by = {}
            for rec in [json.loads(x) for x in open(records)][2:]:
                by.setdefault(rec["image"], {})[rec["method"]] = rec
            expect(len(by) == 12 and all(set(v) == set(edge) for v in by.values()), "every method of every image")
            jets_with_a_set = 0
            for image, m in by.items():
                inside = {k: m[k].get("truth_in_feasible") for k in edge}
                pixel, e1, e2, j1, j2 = (inside[k] for k in edge)
                if j1 is not None:
                    jets_with_a_set += 1
                    expect(pixel is not None and e1 is not None, (image, inside))
                    expect(not j1 or (pixel and e1), (image, inside))
                if j2 is not None:
                    expect(j1 is not None and e2 is not None, (image, inside))
                    expect(not j2 or (j1 and e2), (image, inside))
                for k in edge:  # every record has an error: the method's light or grey world's
                    expect(m[k]["error_deg"] is not None and (m[k]["answered"] or m[k]["fallback"] == "grey_world"),
                           m[k])
            expect(jets_with_a_set >= 3, f"only {jets_with_a_set} images have a 1-jet feasible set")
            # One thread or two: the same bytes.
            again = os.path.join(tmp, "edges1.jsonl")
            rc, out, err = r.run(*base, "--folds", "3", "--methods", ",".join(edge), "--records", again,
                                 "--threads", "1", prefix=[])
            expect(rc == 0 and open(again).read() == open(records).read(), "threads change nothing")
            # Refusals name the option, exit 2 and write nothing.
            for extra, name in ((["--edge-sigma", "0"], "--edge-sigma"), (["--edge-sigma", "65"], "--edge-sigma"),
                                (["--edge-sigma", "x"], "--edge-sigma"), (["--prefilter", "1"], "--prefilter")):
                csv_out = os.path.join(tmp, "refused.csv")
                rc, out, err = r.run(*base, "--folds", "3", "--methods", "gm3d-1jet-max-trace", "--csv", csv_out,
                                     *extra, prefix=[])
                expect(rc == 2 and name in err and out == "" and not os.path.exists(csv_out), (extra, rc, err))

        r.check_all(grey_world_independent, folds_file_equals_folds_k, bad_tables, shards_merge_to_the_whole_run,
                    per_image_rules_in_the_truth_table, grey_and_one_bit_masks, edge_methods_intersect)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
