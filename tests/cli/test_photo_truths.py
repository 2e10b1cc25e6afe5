#!/usr/bin/env python3
"""The numbers gmcc prints beside a photograph's estimate (issue 41), on 16-bit PNGs this test
writes with dark pixels kept (a zero channel, as under the default pixel rules on real photographs):

- `gmcc benchmark`'s truth in F3 for every 3-D gamut record equals an independent exact test
  (scripts/truth_in_f_check.py, in integers): the true map c ⊘ e has a positive multiple in F3 iff
  every kept colour divided by the true light lies in the cone at black of the fold's canonical
  gamut, i.e. its central projection onto r + g + b = 1 lies in the 2-D hull of the training
  colours' projections (the scale each training image is given does not move a cone);
- no record has the truth in F and an error above its certified worst case in the worst case's
  own space (3-D: map space, `map_error_deg`);
- every method's answered + empty + unanswered_other = images, with a constant image among them
  (the grey-edge baselines and the edge-based methods then have no light, not round-off);
- a method named twice is refused; `canonical --space 3d` refuses black-only pixels and gives
  collinear pixels' two ends only;
- `estimate --space 3d --truth` says whether the truth is in F3, and its provenance lists the
  options in effect (no 2-D-only option, the colour set actually used);
- lights at any scale: a canonical gamut scaled by 10^±140 (the documented input limits allow
  coordinates up to 1e150) and a canonical light scaled the same give the light the unscaled ones give, with and
  without a truth; `benchmark --intensity none` with every truth scaled by 10^-170 gives the same
  records as unscaled.

    test_photo_truths.py GMCC_BINARY
"""

import csv
import json
import os
import random
import sys
import tempfile
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
from cli_harness import Runner, expect, random_triples  # noqa: E402
from png16 import write_png16  # noqa: E402

# The independent exact test of truth in F3 (central projections, integer determinants).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "scripts"))
from truth_in_f_check import kept_rays, projected_hull, truth_in_f3  # noqa: E402


def main():
    binary = sys.argv[1]
    rng = random.Random(4141)
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp)
        # Surfaces, some with b = 0 (dark pixels kept), lights, and images: each image shows
        # some surfaces under its light; every third image also a stray colour, which may leave
        # its light outside F3.
        surfaces = [(rng.randint(5, 300), rng.randint(5, 300), rng.choice([0, rng.randint(5, 300)]))
                    for _ in range(40)] + [(200, 180, 160)]
        lights = random_triples(rng, 12, 20, 80)
        names, pixels_of = [], []
        for i, e in enumerate(lights):
            shown = rng.sample(surfaces, 18) + [(200, 180, 160)]
            pixels = [tuple(s[k] * e[k] for k in range(3)) for s in shown]
            if i % 3 == 1:
                pixels.append((rng.randint(15000, 30000), rng.randint(1, 5), rng.randint(200, 600)))
            rows = [pixels[j:j + 4] + [pixels[-1]] * (4 - len(pixels[j:j + 4])) for j in range(0, len(pixels), 4)]
            name = f"img{i}.png"
            write_png16(os.path.join(tmp, name), rows)
            names.append(name)
            pixels_of.append([p for row in rows for p in row])
        # A constant image (one colour everywhere): no edges, no grey-edge light.
        write_png16(os.path.join(tmp, "flat.png"), [[(3000, 2000, 1000)] * 8 for _ in range(8)])
        truths = os.path.join(tmp, "truths.csv")
        with open(truths, "w") as f:
            f.write("image,r,g,b\n")
            for name, e in zip(names, lights):
                f.write(f"{name},{e[0]},{e[1]},{e[2]}\n")
            f.write("flat.png,3,2,1\n")
        records_path = os.path.join(tmp, "records.jsonl")
        csv_path = os.path.join(tmp, "summary.csv")
        methods = ("gm3d-max-trace,gm3d-max-volume,gm3d-centroid,gm2d-max-area,grey-world,grey-edge-1,"
                   "grey-edge-2,gm3d-edge1-max-trace,gm3d-1jet-max-trace")
        rc, out, err = r.run("benchmark", "--images", tmp, "--truths", truths, "--folds", "3", "--methods", methods,
                             "--records", records_path, "--csv", csv_path, "--no-progress")
        expect(rc == 0, err)
        lines = [json.loads(x) for x in open(records_path)][2:]
        n_images = len(names) + 1

        def truth_in_f_matches_the_cone_test():
            checked = 0
            for rec in lines:
                if not rec["method"].startswith("gm3d-max") and rec["method"] != "gm3d-centroid":
                    continue
                i = rec["index"]
                if i >= len(names):
                    continue
                fold = i % 3
                training = [projected_hull(kept_rays(pixels_of[j], 16, lights[j]))
                            for j in range(len(names)) if j % 3 != fold]
                want = truth_in_f3(training, kept_rays(pixels_of[i], 16, lights[i]))
                expect(rec["truth_in_feasible"] == want, (rec["image"], rec["method"], rec["truth_in_feasible"], want))
                checked += 1
            expect(checked == 3 * len(names), checked)
            inside = sum(1 for rec in lines if rec["method"] == "gm3d-max-trace" and rec["truth_in_feasible"]
                         and rec["image"] != "flat.png")
            expect(0 < inside < len(names), f"both answers reached: {inside} of {len(names)} inside")

        def worst_cases_cover_their_own_space():
            for rec in lines:
                if not rec.get("truth_in_feasible") or not rec["answered"] or rec.get("worst_case_deg") is None:
                    continue
                err_same = rec["worst_case_space_error_deg"]
                expect(err_same <= rec["worst_case_deg"], rec)
                if rec["method"].startswith("gm3d"):
                    expect(rec["worst_case_space"] == "map", rec)

        def counts_add_up():
            rows = list(csv.DictReader(x for x in open(csv_path) if not x.startswith("#")))
            expect(len(rows) == len(methods.split(",")), rows)
            for row in rows:
                total = int(row["answered"]) + int(row["empty"] or 0) + int(row["unanswered_other"])
                expect(total == int(row["images"]) == n_images, row)
            flat = {rec["method"]: rec for rec in lines if rec["image"] == "flat.png"}
            for m in ("grey-edge-1", "grey-edge-2", "gm3d-edge1-max-trace", "gm3d-1jet-max-trace"):
                expect(not flat[m]["answered"] and flat[m]["unanswered"] in ("no_light", "no_colours", "unbounded"),
                       flat[m])
            for rec in lines:
                expect(rec["answered"] == (rec["unanswered"] is None), rec)

        def edge_sigma_reaches_grey_edge():
            lights_at = {}
            for sigma in ("1", "2"):
                rp = os.path.join(tmp, f"sigma_{sigma}.jsonl")
                rc, out, err = r.run("benchmark", "--images", tmp, "--truths", truths, "--folds", "3", "--methods",
                                     "grey-edge-1,grey-world", "--edge-sigma", sigma, "--records", rp, "--no-progress")
                expect(rc == 0, err)
                lights_at[sigma] = [json.loads(x) for x in open(rp)][2:]
            changed = [a["image"] for a, b in zip(lights_at["1"], lights_at["2"])
                       if a["method"] == "grey-edge-1" and a["light"] != b["light"]]
            same_grey_world = all(a["light"] == b["light"] for a, b in zip(lights_at["1"], lights_at["2"])
                                  if a["method"] == "grey-world")
            expect(len(changed) >= len(names) - 1 and same_grey_world, (changed, same_grey_world))

        def a_method_named_twice_is_refused():
            rc, out, err = r.run("benchmark", "--images", tmp, "--truths", truths, "--folds", "3", "--methods",
                                 "grey-world,gm3d-max-trace,grey-world", "--no-progress")
            expect(rc == 2 and "given twice" in err and out == "", (rc, err))

        def canonical_3d_refuses_black_and_gives_true_vertices():
            write_png16(os.path.join(tmp, "black.png"), [[(0, 0, 0)] * 3] * 2)
            write_png16(os.path.join(tmp, "line.png"), [[(10, 20, 30), (20, 40, 60), (30, 60, 90), (40, 80, 120)]])
            t = r.file("image,r,g,b\nblack.png,1,1,1\nline.png,1,1,1\n")
            rc, out, err = r.run("canonical", "--from-images", "--space", "3d", "--truths", t,
                                 os.path.join(tmp, "black.png"))
            expect(rc == 2 and "black" in err and out == "", (rc, out, err))
            rc, out, err = r.run("canonical", "--from-images", "--space", "3d", "--truths", t,
                                 os.path.join(tmp, "line.png"), "--intensity", "none")
            expect(rc == 0, err)
            colours = [x for x in out.splitlines() if x and not x.startswith("#") and x != "r,g,b"]
            expect(colours == ["10,20,30", "40,80,120"], colours)

        # A canonical gamut for `estimate --space 3d`: every surface under white, its numbers
        # written times 10^k ("e" notation: exact, within the documented input limits).
        def canonical_csv(k):
            path = os.path.join(tmp, f"canonical_{len(os.listdir(tmp))}.csv")
            with open(path, "w") as f:
                f.write("r,g,b\n")
                for s in surfaces:
                    f.write(",".join(f"{c}e{k}" for c in s) + "\n")
            return path

        def estimate_3d_says_truth_in_f_and_records_what_is_in_effect():
            c = canonical_csv(0)
            e = lights[0]
            doc = r.json("estimate", "--space", "3d", "--canonical", c, "--truth", f"{e[0]},{e[1]},{e[2]}",
                         os.path.join(tmp, names[0]))
            image = doc["images"][0]
            expect(image["truth"]["in_feasible_set"] is True, image["truth"])
            for rule, est in image["estimates"].items():
                expect(est["map_error_deg"] <= est["worst_case_deg"], (rule, est))
            options = doc["provenance"]["options"]
            for name in ("--expand", "--expand-policy", "--on-empty", "--illuminant-worst-case"):
                expect(name not in options, name)
            expect(options["--colour-set"] == "hull-3d", options)
            rc, out, err = r.run("estimate", "--space", "3d", "--canonical", c, "--truth", "1,1,1",
                                 os.path.join(tmp, names[0]))
            expect(rc == 0 and "the feasible set (up to intensity)" in out, out)
            # The 2-D route records none of the 3-D route's options.
            options = r.json("estimate", "--canonical", c, os.path.join(tmp, names[0]))["provenance"]["options"]
            for name in ("--rules", "--black", "--centroid"):
                expect(name not in options, (name, options))
            expect(options["--colour-set"] == "hull", options)

        def lights_at_any_scale():
            e = lights[3]  # an image without a stray colour: F3 holds positive maps
            base = r.json("estimate", "--space", "3d", "--canonical", canonical_csv(0), os.path.join(tmp, names[3]))
            # 10^±140 (about 2^±465): the largest scales the documented input limits let a colour
            # file hold (coordinates up to 1e150); the library and Python take 2^±600.
            for k in (140, -140):
                for truth in (None, e):
                    args = ["estimate", "--space", "3d", "--canonical", canonical_csv(k),
                            "--canonical-illuminant", f"1e{k},1e{k},1e{k}"]
                    if truth:
                        args += ["--truth", ",".join(f"{x}e{k}" for x in truth)]
                    doc = r.json(*args, os.path.join(tmp, names[3]))
                    for rule, est in doc["images"][0]["estimates"].items():
                        want = base["images"][0]["estimates"][rule]["light"]
                        expect(all(abs(a - b) < 1e-12 for a, b in zip(est["light"], want)), (k, rule, est["light"], want))
            scaled_truths = os.path.join(tmp, "scaled_truths.csv")
            with open(scaled_truths, "w") as f:
                f.write("image,r,g,b\n")
                for name, e in list(zip(names, lights)) + [("flat.png", (3, 2, 1))]:
                    f.write(f"{name}," + ",".join(f"{x}e-170" for x in e) + "\n")
            runs = []
            for t in (truths, scaled_truths):
                rp = os.path.join(tmp, f"rec_{len(runs)}.jsonl")
                rc, out, err = r.run("benchmark", "--images", tmp, "--truths", t, "--folds", "3", "--intensity", "none",
                                     "--methods", "gm3d-max-trace,gm3d-centroid,grey-world", "--records", rp,
                                     "--no-progress")
                expect(rc == 0, err)
                runs.append([json.loads(x) for x in open(rp)][2:])
            for a, b in zip(*runs):
                for key in ("light", "error_deg", "truth_in_feasible", "answered"):
                    if key not in a:
                        expect(key not in b, (a, b))
                    elif isinstance(a[key], list):
                        expect(all(abs(x - y) < 1e-12 for x, y in zip(a[key], b[key])), (a, b))
                    elif isinstance(a[key], float):
                        expect(abs(a[key] - b[key]) < 1e-9, (a, b))
                    else:
                        expect(a[key] == b[key], (a, b))

        r.check_all(truth_in_f_matches_the_cone_test, worst_cases_cover_their_own_space, counts_add_up,
                    edge_sigma_reaches_grey_edge, a_method_named_twice_is_refused, canonical_3d_refuses_black_and_gives_true_vertices,
                    estimate_3d_says_truth_in_f_and_records_what_is_in_effect, lights_at_any_scale)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
