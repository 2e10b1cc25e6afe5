#!/usr/bin/python3
"""`gmcc select` beyond the paper's rules (issue 5): --illuminants, --on-empty, --space 3d.

    /usr/bin/python3 tests/cli/test_select_extensions.py GMCC_BINARY

Each case runs the binary on small hand-made files whose answers are known exactly (worked out
in the comments) and checks the JSON members. The last line is `N passed, N failed`; the exit
status is 0 iff none failed.
"""

import os
import sys
import tempfile
from fractions import Fraction as Fr

from cli_harness import Runner, expect

SQUARE = "1,1,1\n2,1,1\n2,2,1\n1,2,1\n"  # chromaticities: the square [1, 2]^2


def fr_pairs(vertices):
    return [tuple(Fr(x) for x in v) for v in vertices]


def main():
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp, prefix=["select"])
        square, one = r.file(SQUARE), r.file("1,1,1\n")
        wide = r.file("1,1,1\n4,1,1\n")  # x-extent 1..4 against the gamut's 1..2: F empty

        def constraint_cuts():
            # Lights (1,1,2) and (1,1,3) have maps (2,2) and (3,3): C is a segment touching F at (2,2).
            d = r.json("--canonical", square, "--image", one, "--illuminants",
                       r.file("1,1,2\n1,1,3\n"))
            expect(d["constraint"]["illuminants"] == 2, d["constraint"])
            expect(d["constraint"]["kind"] == "segment", d["constraint"])
            expect(d["constraint"]["unconstrained_feasible_set"]["area"] == "1", d["constraint"])
            expect(d["feasible_set"]["kind"] == "point", d["feasible_set"])
            expect(fr_pairs(d["feasible_set"]["vertices"]) == [(2, 2)], d["feasible_set"])
            expect(d["selections"]["max_area"]["map_exact"] == ["2", "2"], d["selections"])

        def constraint_empties():
            d = r.json("--canonical", square, "--image", one, "--illuminants",
                       r.file("1,1,3\n1,2,5\n2,1,5\n"))
            expect(d["feasible_set"]["kind"] == "empty", d)
            expect("plausible illuminant" in d["feasible_set"]["reason"], d)
            expect(d["selections"] == {}, d)

        def empty_has_reason():
            d = r.json("--canonical", square, "--image", wide)
            expect(d["feasible_set"]["kind"] == "empty", d)
            expect("no diagonal map" in d["feasible_set"]["reason"], d)
            expect("recovery" not in d, d)

        def grow_brackets_sqrt2():
            # Least factor sqrt(2) - 1 (tests/geometry/test_empty_recovery.cpp).
            d = r.json("--canonical", square, "--image", wide, "--on-empty", "grow-canonical")
            rec = d["recovery"]
            expect(rec["applied"] and rec["policy"] == "grow-canonical", rec)
            lo, hi, eps = Fr(rec["empty_below"]), Fr(rec["factor"]), Fr(rec["precision"])
            expect((1 + lo) ** 2 < 2 <= (1 + hi) ** 2 and hi - lo <= eps, rec)
            expect(d["feasible_set"]["kind"] == "polygon", d["feasible_set"])
            expect("reason" not in d["feasible_set"] and "no diagonal map" in rec["reason"], d)
            expect(set(d["selections"]) == {"max_area", "mean_2d", "mean_3d"}, d["selections"])

        def min_violation_by_hand():
            d = r.json("--canonical", square, "--image", wide, "--on-empty", "min-violation")
            rec = d["recovery"]
            expect(rec["violation"] == "2/5" and rec["applied"], rec)
            expect(fr_pairs(d["feasible_set"]["vertices"]) == [(Fr(3, 5), Fr(3, 5)),
                                                               (Fr(3, 5), Fr(12, 5))], d)

        def recovery_not_needed():
            d = r.json("--canonical", square, "--image", one, "--on-empty", "min-violation")
            expect(d["recovery"] == {"policy": "min-violation", "applied": False}, d["recovery"])
            expect(d["feasible_set"]["area"] == "1", d)

        def bad_illuminant_line():
            rc, out, err = r.run("--canonical", square, "--image", one, "--illuminants",
                                 r.file("# lights\n1,1,1\n1,0,2\n"))
            expect(rc == 2 and out == "" and ":3:" in err, (rc, out, err))
            rc, out, err = r.run("--canonical", square, "--image", one, "--illuminants",
                                 os.path.join(tmp, "missing.csv"))
            expect(rc == 2 and out == "" and "missing.csv" in err, (rc, out, err))
            rc, out, err = r.run("--canonical", square, "--image", wide, "--on-empty", "magic")
            expect(rc == 2 and out == "", (rc, out, err))
            rc, out, err = r.run("--canonical", square, "--image", wide, "--expand", "0.1",
                                 "--expand-policy", "centroid-clip", "--on-empty",
                                 "grow-canonical")
            expect(rc == 2 and out == "" and "--on-empty" in err, (rc, out, err))

        cube = r.file("".join(f"{1 + (i & 1)},{1 + (i >> 1 & 1)},{1 + (i >> 2 & 1)}\n"
                              for i in range(8)))

        def crule_3d_cube():
            # Without black F3 is the cube [1,2]^3: volume 1, max-volume (2,2,2), centroid (3/2)^3.
            d = r.json("--space", "3d", "--black", "exclude", "--canonical", cube, "--image", one)
            f = d["feasible_set"]
            expect(d["space"] == "3d" and f["kind"] == "polytope" and f["volume"] == "1", f)
            expect(len(f["vertices"]) == 8 and len(f["faces"]) == 6, f)
            expect(all(len(face) == 4 for face in f["faces"]), f)
            expect(d["selections"]["max_volume"]["map_exact"] == ["2", "2", "2"], d["selections"])
            expect(d["selections"]["centroid"]["map_exact"] == ["3/2", "3/2", "3/2"], d["selections"])
            # With black: conv(0, cube), volume 1 + 3 pyramids of 1/3 = 2, and 0 is a vertex.
            d = r.json("--space", "3d", "--canonical", cube, "--image", one)
            expect(d["feasible_set"]["volume"] == "2", d["feasible_set"])
            expect(["0", "0", "0"] in d["feasible_set"]["vertices"], d["feasible_set"])
            expect(d["canonical_gamut"]["black"] == "include", d)

        def crule_3d_kinds_and_irrational():
            pt = r.json("--space", "3d", "--black", "exclude", "--canonical", cube, "--image",
                        r.file("1,1,1\n2,2,2\n"))
            expect(pt["feasible_set"]["kind"] == "point", pt["feasible_set"])
            empty = r.json("--space", "3d", "--black", "exclude", "--canonical", cube, "--image", wide)
            expect(empty["feasible_set"]["kind"] == "empty" and empty["selections"] == {}, empty)
            # The segment (1,4,1)-(4,1,2): max of (1+3t)(4-3t)(1+t) at t = sqrt(13/27).
            d = r.json("--space", "3d", "--black", "exclude", "--canonical",
                       r.file("1,4,1\n4,1,2\n"), "--image", one)
            mv = d["selections"]["max_volume"]
            t = (13 / 27) ** 0.5
            expect(mv["method"] == "certified" and "map_exact" not in mv, mv)
            expect(abs(mv["map"][0] - (1 + 3 * t)) < 1e-14, mv)
            expect(mv["exact_form"]["quadratic"] == ["-27", "0", "13"], mv)
            for (lo, hi), x in zip(mv["enclosure"], mv["map"]):
                expect(lo <= x <= hi, mv)

        def crule_3d_rejects_2d_options():
            # (--illuminants applies to --space 3d too since issue 45: tests/cli/test_constrained.py.)
            for extra in (["--expand", "0.1", "--expand-policy", "multiplicative"],
                          ["--on-empty", "min-violation"]):
                rc, out, err = r.run("--space", "3d", "--canonical", cube, "--image", one, *extra)
                expect(rc == 2 and out == "" and "3d" in err, (extra, rc, out, err))
            rc, out, err = r.run("--space", "3d", "--canonical", cube, "--image",
                                 r.file("0,1,1\n0,2,1\n"))
            expect(rc == 2 and out == "" and "unbounded" in err, (rc, out, err))

        for name, fn in list(locals().items()):
            if callable(fn) and name not in ("r",) and fn.__code__.co_argcount == 0:
                r.check(name, fn)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
