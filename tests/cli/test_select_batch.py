#!/usr/bin/python3
"""`gmcc select` for studies (issue 12): --truth, batch selection (--images), and the options
that cannot apply, refused with a reason.

    /usr/bin/python3 tests/cli/test_select_batch.py GMCC_BINARY

Hand-made files with exact answers (worked out in the comments); batch records are compared
field by field with one `gmcc select --json` per scene. The last line is `N passed, N failed`;
the exit status is 0 iff none failed.
"""

import json
import math
import os
import sys
import tempfile
from fractions import Fraction as Fr

from cli_harness import Runner, expect

SQUARE = "1,1,1\n2,1,1\n2,2,1\n1,2,1\n"  # chromaticities: the square [1, 2]^2
C = ["--canonical-illuminant", "1,1,1"]


def angle_deg(u, v):
    dot = sum(a * b for a, b in zip(u, v))
    cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return math.degrees(math.atan2(math.sqrt(sum(x * x for x in cross)), dot))


def scene_records(out):
    """The records of a batch's JSON Lines output, after its provenance line
    (docs/cli.md "Provenance"; test_provenance.py checks that line's content)."""
    lines = out.splitlines()
    expect(lines and set(json.loads(lines[0])) == {"provenance"}, f"first line {lines[:1]}")
    return [json.loads(x) for x in lines[1:]]


def main():
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp, prefix=["select"])
        square, one = r.file(SQUARE), r.file("1,1,1\n")

        def jsonl(lines):
            r.n += 1
            path = os.path.join(tmp, f"s{r.n}.jsonl")
            with open(path, "w") as f:
                f.write("".join(lines))
            return path

        def truth_inside():
            # F = [1,2]^2; the true light (2,2,3) has the map c / e in perspective = (3/2, 3/2),
            # which is the 2-D mean: map error 0. Max-area (2,2): the angle between (2,2,1) and
            # (3/2,3/2,1).
            d = r.json("--canonical", square, "--image", one, "--truth", "2,2,3", *C)
            t = d["truth"]
            expect(t["map_exact"] == ["3/2", "3/2"] and t["in_feasible_set"] is True, t)
            expect(t["light"] == ["2", "2", "3"], t)
            expect(t["errors"]["mean_2d"]["map_error_deg"] == 0, t)
            expect(abs(t["errors"]["max_area"]["map_error_deg"] - angle_deg((2, 2, 1), (1.5, 1.5, 1))) < 1e-12, t)
            # Illuminant error: the angle between the lights the maps imply, c / (m, 1):
            # (1/2, 1/2, 1) against (2/3, 2/3, 1).
            expect(abs(t["errors"]["max_area"]["illuminant_error_deg"]
                       - angle_deg((0.5, 0.5, 1), (2 / 3, 2 / 3, 1))) < 1e-12, t)
            expect("reproduction_error_deg" in t["errors"]["mean_3d"], t)
            # The same selections as without --truth.
            plain = r.json("--canonical", square, "--image", one, *C)
            expect(plain["selections"] == d["selections"], "selections changed by --truth")
            expect("truth" not in plain, plain)

        def truth_outside_and_text():
            # Under c = (2,1,1) the true map is (3, 3/2): outside F.
            d = r.json("--canonical", square, "--image", one, "--truth", "2,2,3",
                       "--canonical-illuminant", "2,1,1")
            expect(d["truth"]["map_exact"] == ["3", "3/2"] and not d["truth"]["in_feasible_set"], d["truth"])
            rc, out, err = r.run("--canonical", square, "--image", one, "--truth", "2,2,3", *C)
            expect(rc == 0 and "against the true light (2, 2, 3)" in out and "inside" in out, out)
            expect(err == "", err)

        def truth_warns_without_canonical_illuminant():
            rc, out, err = r.run("--canonical", square, "--image", one, "--truth", "2,2,3", "--json")
            expect(rc == 0 and "warning" in err and "--canonical-illuminant" in err, (rc, err))
            rc, out, err = r.run("--canonical", square, "--image", one, "--illuminants",
                                 r.file("1,1,2\n1,1,3\n"), "--json")
            expect(rc == 0 and "warning: --illuminants" in err, (rc, err))
            json.loads(out)  # stdout still one JSON document

        def truth_rejected():
            for bad in ("0,1,1", "1,1", "a,b,c", "-1,1,1"):
                rc, out, err = r.run("--canonical", square, "--image", one, "--truth", bad, *C)
                expect(rc == 2 and out == "" and err.startswith("gmcc: error: --truth:"), (bad, rc, err))

        scenes = [
            ("a", "3,3,2\n", '"3","3","2"'),
            ("b", "1,1,1\n2,2,1\n", '1,1,1],[2,2,1'),       # F the point (1, 1)
            ("c", "1,1,1\n4,1,1\n", '1,1,1],[4,1,1'),       # F empty
            ("d", "1.5,1.25,1\n1,1,0.75\n", '1.5,1.25,1],["1","1","3/4"'),  # decimals, exact
        ]

        def batch_equals_one_by_one():
            lines = [f'{{"id":"{i}","colours":[[{j}]],"truth":[2,2,3]}}\n' for i, _, j in scenes]
            rc, out, err = r.run("--canonical", square, "--images", jsonl(lines), *C)
            expect(rc == 0 and err == "", (rc, err))
            records = scene_records(out)
            expect(len(records) == len(scenes), out)
            for rec, (i, csv, _) in zip(records, scenes):
                one_run = r.json("--canonical", square, "--image", r.file(csv), "--truth", "2,2,3", *C)
                expect(rec["id"] == i, rec)
                for key in ("feasible_set", "selections", "truth"):
                    expect(rec[key] == one_run[key], (i, key, rec[key], one_run[key]))
                expect(rec["input"]["image_colours"] == one_run["input"]["image_colours"], rec)
            expect(records[1]["feasible_set"]["kind"] == "point", records[1])
            expect(records[2]["feasible_set"]["kind"] == "empty" and records[2]["selections"] == {}, records[2])
            expect(records[3]["line"] == 4, records[3])

        def batch_record_form():
            # --record (docs/cli.md "Record contract"): contract version 1; every exact vertex and
            # rational map of the full record within the record's radius of its midpoint (checked
            # in fractions); angles within 2^-36·(1 + θ) of the full record's (the 3-D mean's are
            # measured at the exact map, the full record's at its rounded map: twice that).
            lines = [f'{{"id":"{i}","colours":[[{j}]],"truth":[2,2,3]}}\n' for i, _, j in scenes]
            path = jsonl(lines)
            rc, out, err = r.run("--canonical", square, "--images", path, "--record", *C)
            expect(rc == 0 and err == "", (rc, err))
            records = scene_records(out)
            rc, full_out, err = r.run("--canonical", square, "--images", path, *C)
            fulls = scene_records(full_out)
            expect(len(records) == len(fulls) == len(scenes), out)
            acc = 2.0 ** -36
            for rec, full in zip(records, fulls):
                expect(rec["record"] == 1 and rec["id"] == full["id"] and rec["line"] == full["line"], rec)
                expect(rec["input"] == full["input"], rec)
                f, ff = rec["feasible_set"], full["feasible_set"]
                expect(f["kind"] == ff["kind"] and len(f["vertices"]) == len(ff["vertices"]), (f, ff))
                for v, w in zip(f["vertices"], ff["vertices"]):
                    for a, b in zip(v, w):
                        expect(abs(Fr(a) - Fr(b)) <= Fr(f["vertex_radius"]), (v, w))
                expect(set(rec.get("selections", {})) == set(full["selections"]), rec)
                for rule, s in rec.get("selections", {}).items():
                    fs = full["selections"][rule]
                    if "map_exact" in fs:
                        for a, rad, b in zip(s["map"], s["map_radius"], fs["map_exact"]):
                            expect(abs(Fr(a) - Fr(b)) <= Fr(rad), (rule, s, fs))
                    k = 1 if "map_exact" in fs else 2
                    for key in ("worst_case_deg", "worst_case_illuminant_deg"):
                        expect((key in s) == (key in fs), (rule, key))
                        if key in s:
                            expect(abs(s[key] - fs[key]) <= k * acc * (1 + fs[key]), (rule, key, s, fs))
                    te, fe = rec["truth"]["errors"][rule], full["truth"]["errors"][rule]
                    for key in ("map_error_deg", "illuminant_error_deg", "reproduction_error_deg"):
                        expect(abs(te[key] - fe[key]) <= k * acc * (1 + fe[key]), (rule, key, te, fe))
                expect(rec["truth"]["in_feasible_set"] == full["truth"]["in_feasible_set"], rec)
                expect(not {"area", "vertices_approx"} & set(f), f)
                expect(all("map_exact" not in s for s in rec.get("selections", {}).values()), rec)
            expect(records[2]["feasible_set"]["kind"] == "empty" and "selections" not in records[2], records[2])
            # Only with --images, and only for the closed-form 3-D mean.
            for extra, name in ((["--image", one], "--record"),
                                (["--images", path, "--mean3d", "quadrature"], "--mean3d"),
                                (["--images", path, "--precision", "200"], "--precision")):
                rc, out, err = r.run("--canonical", square, "--record", *extra, *C)
                expect(rc == 2 and out == "" and err.startswith(f"gmcc: error: {name}:"), (extra, rc, err))

        def batch_threads_change_nothing():
            # 600 scenes (more than one block of 256), with error lines among them: the same bytes
            # on 1, 2 and 3 threads, full and record form; --threads only with --images.
            lines = []
            for i in range(600):
                a, b = 1 + i % 7, 1 + (i * 5) % 11
                lines.append('{"colours":[[1,2]]}\n' if i % 97 == 5 else
                             f'{{"id":{i},"colours":[[{a},{b},3],[{b},{a},2],[3,3,2]],"truth":[2,2,3]}}\n')
            path = jsonl(lines)
            for extra in ([], ["--record"]):
                outs = []
                for t in ("1", "2", "3"):
                    rc, out, err = r.run("--canonical", square, "--images", path, "--threads", t, *extra, *C)
                    expect(rc == 2 and "7 of 600 scenes" in err, (t, extra, rc, err))
                    outs.append(out)
                expect(outs[0] == outs[1] == outs[2], extra)
                recs = scene_records(outs[0])
                expect([x["line"] for x in recs] == list(range(1, 601)), "records out of order")
            rc, out, err = r.run("--canonical", square, "--image", one, "--threads", "2", *C)
            expect(rc == 2 and err.startswith("gmcc: error: --threads:"), (rc, err))

        def batch_warns_once_and_options_apply():
            lines = ['{"colours":[[3,3,2]],"truth":[2,2,3]}\n'] * 3
            rc, out, err = r.run("--canonical", square, "--images", jsonl(lines),
                                 "--illuminant-worst-case", "off")
            expect(rc == 0 and err.count("warning") == 1, (rc, err))
            recs = scene_records(out)
            expect(len(recs) == 3 and all("worst_case_illuminant_deg" not in rec["selections"]["max_area"]
                                          for rec in recs), recs)
            expect(all("worst_case_deg" in rec["selections"]["max_area"] for rec in recs), recs)

        def batch_exact_decimals():
            # 0.1 read as a double would not give the exact point (7/9, 14/3) (test_select_errors).
            can = r.file("0.1,0.2,0.3\n")
            rc, out, err = r.run("--canonical", can, "--images",
                                 jsonl(['{"colours":[[0.3,0.1,0.7]]}\n']), *C)
            (rec,) = scene_records(out)
            expect(rc == 0 and rec["feasible_set"]["vertices"] == [["7/9", "14/3"]], (rc, out, err))
            expect("id" not in rec, rec)

        def batch_malformed_lines():
            lines = ['{"id":1,"colours":[[3,3,2]]}\n',
                     'not json\n',
                     '\n',                                              # blank: skipped
                     '{"id":"x","colours":[[1,2]]}\n',                  # a colour of 2 numbers
                     '{"id":2,"colors":[[3,3,2]]}\n',                   # unknown member
                     '{"id":3,"colours":[[1,1,1],[0,1,1],[0,2,1]],"truth":[1,1,1]}\n',  # valid: F a segment
                     '{"id":4,"colours":[[3,3,2]],"truth":[0,1,1]}\n',  # truth channel 0
                     '{"id":5,"colours":[[-1,3,2]]}\n',                 # negative channel
                     '{"id":6,"colours":[["1/0",3,2]]}\n',              # p/0
                     '{"id":7,"colours":[[3,3,2]]}\n']
            path = jsonl(lines)
            rc, out, err = r.run("--canonical", square, "--images", path, *C)
            records = scene_records(out)
            expect(rc == 2, (rc, err))
            expect("could not be selected" in err and err.count("\n") == 1, err)
            expect(len(records) == 9, out)
            by_line = {rec["line"]: rec for rec in records}
            expect("error" not in by_line[1] and by_line[1]["id"] == 1, by_line[1])
            expect(by_line[2]["error"].startswith(f"{path}:2: not a JSON object"), by_line[2])
            expect(by_line[4]["id"] == "x" and "colours[0]" in by_line[4]["error"], by_line[4])
            expect(by_line[4]["error"].startswith(f"{path}:4:"), by_line[4])
            expect("unknown member 'colors'" in by_line[5]["error"], by_line[5])
            expect(by_line[7]["error"].startswith(f"{path}:7: truth:"), by_line[7])
            expect("colours[0][0] is negative" in by_line[8]["error"], by_line[8])
            expect("colours[0][0]" in by_line[9]["error"], by_line[9])
            expect("error" not in by_line[10] and by_line[10]["id"] == 7, by_line[10])

        def batch_odd_lines():
            path = os.path.join(tmp, "odd.jsonl")
            with open(path, "wb") as f:
                f.write(b'{"colours":[[1e400,1,1]]}\n'
                        b'{"colours":[["\xff\xfe",1,1]]}\n'
                        b'{"caf\xc3\xa9":1,"colours":[[3,3,2]]}\n'
                        b'{"colours":[[1,1,1]]} trailing\n'
                        b'{"colours":[[[[[[[[[[1]]]]]]]]]]}\n'
                        b'{"colours":[["1e400",1,1]]}\n'
                        b'{"colours":[[3,3,2]]}\n')
            rc, out, err = r.run("--canonical", square, "--images", path, *C)
            recs = scene_records(out)
            expect(rc == 2 and len(recs) == 7, (rc, out, err))
            expect("as strings" in recs[0]["error"], recs[0])
            expect(recs[1]["error"].startswith(f"{path}:2: not a JSON object"), recs[1])
            expect("unknown member" in recs[2]["error"], recs[2])
            expect("end of input" in recs[3]["error"], recs[3])
            expect("nested" in recs[4]["error"], recs[4])
            expect("exceeds 1e150" in recs[5]["error"], recs[5])
            expect("error" not in recs[6], recs[6])

        def batch_unbounded_and_blue():
            rc, out, err = r.run("--canonical", square, "--images",
                                 jsonl(['{"colours":[[0,1,1],[0,2,1]]}\n',
                                        '{"colours":[[1,1,1],[1,1,0]]}\n']),
                                 "--nonpositive-blue", "reject", *C)
            recs = scene_records(out)
            expect(rc == 2 and "unbounded" in recs[0]["error"], (rc, recs))
            expect("colours[1]: b <= 0" in recs[1]["error"], recs[1])

        def batch_whole_file_problems():
            for path in (os.path.join(tmp, "missing.jsonl"), jsonl(["\n\n"])):
                rc, out, err = r.run("--canonical", square, "--images", path, *C)
                expect(rc == 2 and out == "" and path in err, (rc, out, err))
            rc, out, err = r.run("--canonical", r.file("1,1,0\n"), "--images",
                                 jsonl(['{"colours":[[1,1,1]]}\n']), *C)
            expect(rc == 2 and out == "" and "no usable colour" in err, (rc, out, err))

        def batch_scene_limit():
            # 10^5 + 1 scene lines: refused before any work, naming the line past the limit.
            path = jsonl(["\n"] + ["x\n"] * 100001)
            rc, out, err = r.run("--canonical", square, "--images", path, *C)
            expect(rc == 2 and out == "" and f"{path}:100002: more than 100000 scenes" in err, (rc, err))

        def batch_constraint_and_recovery():
            lights = r.file("1,1,2\n1,1,3\n")
            lines = ['{"colours":[[1,1,1]]}\n', '{"colours":[[1,1,1],[4,1,1]]}\n']
            rc, out, err = r.run("--canonical", square, "--images", jsonl(lines), "--illuminants",
                                 lights, "--on-empty", "min-violation", *C)
            recs = scene_records(out)
            expect(rc == 0, (rc, err))
            expect(recs[0]["constraint"]["kind"] == "segment" and recs[0]["feasible_set"]["kind"] == "point", recs[0])
            expect(recs[1]["recovery"]["applied"] is True, recs[1])
            for rec, line in zip(recs, lines):
                one_run = r.json("--canonical", square, "--image",
                                 r.file("\n".join(",".join(str(x) for x in c) for c in json.loads(line)["colours"]) + "\n"),
                                 "--illuminants", lights, "--on-empty", "min-violation", *C)
                for key in ("feasible_set", "selections", "constraint", "recovery"):
                    expect(rec[key] == one_run[key], (key, rec[key], one_run[key]))

        def inapplicable_options():
            cases = [
                (["--space", "3d", "--mean3d", "monte-carlo", "--samples", "5"], "--mean3d"),
                (["--space", "3d", "--samples", "5"], "--samples"),
                (["--space", "3d", "--canonical-illuminant", "1,1,2"], "--canonical-illuminant"),
                (["--space", "3d", "--nonpositive-blue", "reject"], "--nonpositive-blue"),
                (["--space", "3d", "--truth", "1,1,1"], "--truth"),
                (["--space", "3d", "--illuminant-worst-case", "off"], "--illuminant-worst-case"),
                (["--samples", "5"], "--samples"),
                (["--seed", "5"], "--seed"),
                (["--mean3d", "quadrature", "--samples", "5"], "--samples"),
                (["--order", "4"], "--order"),
                (["--mean3d", "monte-carlo", "--order", "4"], "--order"),
                (["--mean3d", "quadrature", "--precision", "100"], "--precision"),
                (["--black", "exclude"], "--black"),
                (["--images", one], "--images"),  # with --image
            ]
            for extra, name in cases:
                rc, out, err = r.run("--canonical", square, "--image", one, *extra)
                expect(rc == 2 and out == "" and err.startswith(f"gmcc: error: {name}:"), (extra, rc, err))
                expect(err.count("\n") == 1, err)
            rc, out, err = r.run("--canonical", square)
            expect(rc == 2 and "--image" in err and "--images" in err, (rc, err))
            rc, out, err = r.run("--canonical", square, "--images", one, "--truth", "1,1,1")
            expect(rc == 2 and err.startswith("gmcc: error: --truth:"), (rc, err))
            # Each route's own options are accepted.
            for extra in (["--mean3d", "monte-carlo", "--samples", "100", "--seed", "3"],
                          ["--mean3d", "quadrature", "--order", "4"], ["--precision", "100"],
                          ["--space", "3d", "--black", "exclude"]):
                rc, out, err = r.run("--canonical", square, "--image", one, *extra)
                expect(rc == 0, (extra, rc, err))

        def malformed_value_named_first():
            rc, out, err = r.run("--canonical", square, "--image", one, "--seed", "abc")
            expect(rc == 2 and "must be an integer" in err, err)

        def sliver_vertices_distinct_in_text():
            # Canonical gamut: the triangle (1,1), (1+2^-60, 1), (1, 2): F for the image (1,1,1)
            # has two vertices whose nearest doubles coincide; the text prints them exactly too.
            tiny = "1152921504606846977/1152921504606846976"
            rc, out, err = r.run("--canonical", r.file(f"1,1,1\n{tiny},1,1\n1,2,1\n"), "--image", one, *C)
            vertex_lines = [x for x in out.splitlines() if x.startswith("  (")]
            expect(rc == 0 and len(vertex_lines) == 3, out)
            expect(len(set(vertex_lines)) == 3, vertex_lines)
            expect(sum("exact (" in x for x in vertex_lines) == 2, vertex_lines)

        def monte_carlo_note_names_no_flag():
            d = r.json("--canonical", square, "--image", r.file("1,1,1\n2,1,1\n"),
                       "--mean3d", "monte-carlo", "--samples", "100")
            note = d["selections"]["mean_3d"]["note"]
            expect("--" not in note and "segment" in note, note)

        for name, fn in list(locals().items()):
            if callable(fn) and name not in ("r", "jsonl") and fn.__code__.co_argcount == 0:
                r.check(name, fn)
        sys.exit(r.finish())


if __name__ == "__main__":
    main()
