#!/usr/bin/env python3
"""The illumination constraint on photographs (issue 45; docs/photographs.md §7a, docs/math.md
§1e), on 16-bit PNGs this test writes:

- `estimate --space 3d --illuminants L.csv` with the true light among the plausible lights
  recovers it (F3 ∩ cone is the truth's ray when the image shows the canonical surfaces), and its
  truth is in the constrained set;
- plausible lights far from the truth leave F3 ∩ cone with no positive map: every rule says so,
  the summary says that F3 itself holds maps ("F3 holds maps, none of a plausible light"), the
  JSON's `constraint` says the same; a plausible light with a channel <= 0 is refused naming the
  file and line;
- the 2-D route takes the same file (Finlayson's constraint in perspective), and so does
  `select --space 3d` (F3 ∩ cone: all of F3 when the truth is plausible, {0} when no light is);
- `benchmark` with the constrained methods: the constrained set is a subset of the unconstrained
  one (a truth in it is in F too), and every method's answered + empty + unanswered_other is the
  number of images;
- `benchmark --methods gcie` (Finlayson, Hordley & Tastl's classification, docs/math.md §1f): on
  images of every canonical surface under one of three lights, each light in every fold, the
  light chosen is the image's own (only it maps the surfaces' extreme chromaticities into the
  canonical gamut), and on the random dataset every light chosen is a training light.

    test_constrained.py GMCC_BINARY
"""

import csv
import json
import os
import random
import sys
import tempfile

from cli_harness import Runner, angle, expect, random_triples  # noqa: E402
from png16 import write_png16  # noqa: E402


def main():
    binary = sys.argv[1]
    rng = random.Random(45)
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp)
        os.mkdir(os.path.join(tmp, "gcie"))
        surfaces = random_triples(rng, 12, 20, 300)
        canonical = r.file("r,g,b\n" + "".join(f"{a},{b},{c}\n" for a, b, c in surfaces))
        e = (30, 40, 50)
        image = os.path.join(tmp, "img.png")
        write_png16(image, [[tuple(s[k] * e[k] for k in range(3)) for s in surfaces[:6]],
                            [tuple(s[k] * e[k] for k in range(3)) for s in surfaces[6:]]])
        near = r.file("r,g,b\n60,80,100\n33,40,50\n30,44,50\n30,40,55\n")  # the truth (doubled) among them
        far = r.file("r,g,b\n90,20,10\n80,25,12\n")  # reddish lights only
        bad = r.file("r,g,b\n1,2,3\n4,0,6\n")

        def constrained_estimate_recovers_the_truth():
            doc = r.json("estimate", "--space", "3d", "--canonical", canonical, "--illuminants", near,
                         "--truth", "30,40,50", image)
            im = doc["images"][0]
            expect(im["truth"]["in_feasible_set"] is True, im["truth"])
            expect(im["constraint"] == {"lights": 4, "plausible_map": True}, im["constraint"])
            for rule, est in im["estimates"].items():
                expect(angle(est["light"], e) < 1e-9, (rule, est["light"]))
            expect(doc["provenance"]["options"]["--illuminants"] == near, doc["provenance"]["options"])

        def implausible_lights_say_so():
            rc, out, err = r.run("estimate", "--space", "3d", "--canonical", canonical, "--illuminants", far, image)
            expect(rc == 0, err)
            expect("F3 holds maps, none of a plausible light" in out, out)
            doc = r.json("estimate", "--space", "3d", "--canonical", canonical, "--illuminants", far,
                         "--truth", "30,40,50", image)
            im = doc["images"][0]
            expect(im["constraint"] == {"lights": 2, "plausible_map": False, "unconstrained_positive_map": True},
                   im["constraint"])
            expect(im["truth"]["in_feasible_set"] is False, im["truth"])
            expect(all("light" not in est for est in im["estimates"].values()), im["estimates"])

        def a_bad_light_names_its_line():
            for space in ("3d", "2d"):
                rc, out, err = r.run("estimate", "--space", space, "--canonical", canonical, "--illuminants", bad, image)
                expect(rc == 2 and out == "" and f"{bad}:3" in err and err.count("\n") == 1, (space, rc, err))

        def the_2d_route_takes_the_file():
            doc = r.json("estimate", "--canonical", canonical, "--illuminants", near, "--truth", "30,40,50", image)
            im = doc["images"][0]
            expect(im["truth"]["in_feasible_set"] is True, im["truth"])
            # C is the hull of the four lights' perspective maps (e3/e1, e3/e2): (5/3, 5/4) (the truth,
            # doubled), (50/33, 5/4), (5/3, 25/22), (11/6, 11/8), the first inside the others' triangle.
            expect(im["constraint"]["illuminants"] == 4 and im["constraint"]["kind"] == "polygon", im["constraint"])
            expect(sorted(map(tuple, im["constraint"]["vertices"])) ==
                   sorted([("50/33", "5/4"), ("5/3", "25/22"), ("11/6", "11/8")]), im["constraint"]["vertices"])

        def benchmark_constrained_methods():
            names, lights = [], []
            for i in range(9):
                light = (rng.randint(20, 60), rng.randint(20, 60), rng.randint(20, 60))
                shown = rng.sample(surfaces, 8)
                rows = [[tuple(s[k] * light[k] for k in range(3)) for s in shown[:4]],
                        [tuple(s[k] * light[k] for k in range(3)) for s in shown[4:]]]
                name = f"b{i}.png"
                write_png16(os.path.join(tmp, name), rows)
                names.append(name)
                lights.append(light)
            truths = os.path.join(tmp, "bench_truths.csv")
            with open(truths, "w") as f:
                f.write("image,r,g,b\n" + "".join(f"{n},{a},{b},{c}\n" for n, (a, b, c) in zip(names, lights)))
            rec, table = os.path.join(tmp, "c.jsonl"), os.path.join(tmp, "c.csv")
            methods = ["gm3d-max-trace", "gm3d-max-trace-constrained", "gm3d-centroid-constrained",
                       "gm2d-mean-2d", "gm2d-mean-2d-constrained"]
            rc, out, err = r.run("benchmark", "--images", tmp, "--truths", truths, "--folds", "3", "--methods",
                                 ",".join(methods), "--records", rec, "--csv", table, "--no-progress")
            expect(rc == 0, err)
            records = [json.loads(x) for x in open(rec)][2:]
            by = {(x["index"], x["method"]): x for x in records}
            for i in range(len(names)):
                for free, con in (("gm3d-max-trace", "gm3d-max-trace-constrained"),
                                  ("gm2d-mean-2d", "gm2d-mean-2d-constrained")):
                    if by[(i, con)]["truth_in_feasible"]:
                        expect(by[(i, free)]["truth_in_feasible"], (i, free))
            for row in csv.DictReader(x for x in open(table) if not x.startswith("#")):
                expect(int(row["answered"]) + int(row["empty"]) + int(row["unanswered_other"]) == 9, row)

        def benchmark_gcie():
            three = [(30, 40, 50), (50, 35, 20), (25, 50, 45)]
            names, lights = [], []
            for i in range(9):
                light = three[i // 3]
                rows = [[tuple(s[k] * light[k] for k in range(3)) for s in surfaces[:6]],
                        [tuple(s[k] * light[k] for k in range(3)) for s in surfaces[6:]]]
                name = f"g{i}.png"
                write_png16(os.path.join(tmp, "gcie", name), rows)
                names.append(name)
                lights.append(light)
            truths = r.file("image,r,g,b\n" + "".join(f"{n},{a},{b},{c}\n" for n, (a, b, c) in zip(names, lights)))
            rec = os.path.join(tmp, "g.jsonl")
            rc, out, err = r.run("benchmark", "--images", os.path.join(tmp, "gcie"), "--truths", truths, "--folds", "3",
                                 "--methods", "gcie,grey-world", "--records", rec, "--no-progress")
            expect(rc == 0, err)
            records = [json.loads(x) for x in open(rec)][2:]
            for x in records:
                if x["method"] == "gcie":
                    expect(x["answered"] and x["error_deg"] < 1e-6, x)
            # The random dataset of benchmark_constrained_methods: each choice is a training light.
            truths_b = [tuple(int(v) for v in line.split(",")[1:]) for line in
                        open(os.path.join(tmp, "bench_truths.csv")).read().splitlines()[1:]]
            rc, out, err = r.run("benchmark", "--images", tmp, "--truths", os.path.join(tmp, "bench_truths.csv"),
                                 "--folds", "3", "--methods", "gcie", "--records", rec, "--no-progress")
            expect(rc == 0, err)
            for x in [json.loads(x) for x in open(rec)][2:]:
                fold = x["index"] % 3
                training = [t for i, t in enumerate(truths_b) if i % 3 != fold]
                expect(any(angle(x["light"], t) < 1e-6 for t in training), x)

        def select_3d_takes_the_constraint():
            image_csv = r.file("r,g,b\n" + "".join(f"{s[0] * e[0]},{s[1] * e[1]},{s[2] * e[2]}\n" for s in surfaces))
            free = r.json("select", "--space", "3d", "--canonical", canonical, "--image", image_csv)
            near_doc = r.json("select", "--space", "3d", "--canonical", canonical, "--image", image_csv,
                              "--illuminants", near)
            # F3 is the segment from 0 towards c ⊘ e, inside the cone: the constraint keeps it all.
            expect(near_doc["feasible_set"]["vertices"] == free["feasible_set"]["vertices"], near_doc["feasible_set"])
            far_doc = r.json("select", "--space", "3d", "--canonical", canonical, "--image", image_csv,
                             "--illuminants", far)
            expect(far_doc["feasible_set"]["kind"] == "point" and
                   far_doc["feasible_set"]["vertices"] == [["0", "0", "0"]], far_doc["feasible_set"])

        r.check_all(select_3d_takes_the_constraint, constrained_estimate_recovers_the_truth, implausible_lights_say_so, a_bad_light_names_its_line,
                    the_2d_route_takes_the_file, benchmark_constrained_methods, benchmark_gcie)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
