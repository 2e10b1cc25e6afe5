#!/usr/bin/python3
"""Issue 13's reproducers at the command line: each gives a clear message and exit 2, or a correct
answer, within a bounded time (docs/cli.md "Resource limits").

    /usr/bin/python3 tests/cli/test_reliability.py GMCC_BINARY

Every run has a subprocess timeout: a hang is a failure here, not a wait. No time is asserted.
The last line is `N passed, N failed`; the exit status is 0 iff none failed.
"""

import json
import os
import sys
import tempfile
from fractions import Fraction as Fr

from cli_harness import Runner, expect

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "data")


def refused(r, args, option, *words):
    """exit 2, nothing on stdout, one line on stderr naming the option and the words."""
    rc, out, err = r.run(*args, timeout=60)
    expect(rc == 2 and out == "", (args, rc, out[:200], err))
    lines = err.strip().split("\n")
    expect(len(lines) == 1 and lines[0].startswith("gmcc: error: " + option + ":"), (args, err))
    for w in words:
        expect(w in err, (args, w, err))


def main():
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp, timeout=300)
        synthetic = ["reproduce", "synthetic", "--scenes", "1", "--surfaces", "1"]

        def planck_out_of_range():
            # P1e-5 / P1e-400 crashed with SIGFPE; P0.0001 grew to 4 GB; P1/100 took 19 s;
            # P1/3 reported every error as 0.
            for t in ("1e-5", "1e-400", "0.0001", "1/100", "1/3", "999", "100001", "1e6"):
                refused(r, synthetic + ["--lights", "P" + t], "--lights", "P" + t, "1000 to 100000 K")
            refused(r, synthetic + ["--canonical", "P1e-5"], "--canonical", "P1e-5", "1000 to 100000 K")
            refused(r, synthetic + ["--lights", "D1000"], "--lights", "D1000", "D40 to D249")

        def planck_at_the_limits():
            # The limits themselves are lights: one scene each, a finite table.
            rc, out, err = r.run(*synthetic, "--lights", "P1000,P100000,D40,D249", "--canonical",
                                 "P100000", timeout=300)
            expect(rc == 0 and err == "", (rc, err))
            for name in ("P1000", "P100000", "D40", "D249"):
                expect(name in out, (name, out))
            expect("nan" not in out and "inf" not in out, out)

        def light_errors_blame_their_option():
            refused(r, synthetic + ["--canonical", "nope"], "--canonical", "unknown light 'nope'")
            refused(r, synthetic + ["--lights", "D65,nope"], "--lights", "unknown light 'nope'")
            refused(r, ["reproduce", "camera", "--scenes", "1", "--lights", "nope"], "--lights",
                    "unknown light 'nope'", "solux-4700")
            refused(r, ["reproduce", "camera", "--scenes", "1", "--canonical", "nope"], "--canonical",
                    "unknown light 'nope'")
            refused(r, synthetic + ["--lights", ",".join(["D65"] * 65)], "--lights", "at most 64")

        square = r.file("1,1,1\n2,1,1\n2,2,1\n1,2,1\n")

        def option_messages():
            refused(r, ["select", "--canonical", square, "--image", square, "--seed", "abc"], "--seed",
                    "must be an integer", "'abc'")
            long = "1" + "0" * 100
            refused(r, ["select", "--canonical", square, "--image", square, "--canonical-illuminant",
                        long + ",1,1"], "--canonical-illuminant", "101 digits")
            refused(r, ["select", "--canonical", square, "--image", square, "--canonical-illuminant",
                        "1,0,1"], "--canonical-illuminant", "> 0")
            refused(r, ["select", "--canonical", square, "--image", square, "--mean3d", "monte-carlo",
                        "--samples", "1000000001"], "--samples", "1000000000")

        def crule_lp_terminates():
            # CGAL's default pivoting rule cycled forever on this program (issue 13).
            image = os.path.join(HERE, "data", "crule_cycling_80.csv")
            canonical = os.path.join(DATA, "samples", "canonical_munsell_D55.csv")
            rc, out, err = r.run("select", "--space", "3d", "--canonical", canonical, "--image", image,
                                 "--json", timeout=600)
            expect(rc == 0, (rc, err))
            d = json.loads(out)
            f = d["feasible_set"]
            expect(f["kind"] == "polytope" and Fr(f["volume"]) > 0, f["kind"])
            vs = [tuple(Fr(x) for x in v) for v in f["vertices"]]
            # Each face is a planar cycle with every vertex on the inner side: F3 is convex and
            # its faces are its facets; the centroid (exact) lies strictly inside.
            c = tuple(Fr(x) for x in d["selections"]["centroid"]["map_exact"])
            for face in f["faces"]:
                p, q, s = (vs[i] for i in face[:3])
                n = [(q[1] - p[1]) * (s[2] - p[2]) - (q[2] - p[2]) * (s[1] - p[1]),
                     (q[2] - p[2]) * (s[0] - p[0]) - (q[0] - p[0]) * (s[2] - p[2]),
                     (q[0] - p[0]) * (s[1] - p[1]) - (q[1] - p[1]) * (s[0] - p[0])]
                h = lambda x: sum(n[k] * (x[k] - p[k]) for k in range(3))  # noqa: E731
                expect(all(h(vs[i]) == 0 for i in face), "a face is not planar")
                expect(all(h(v) <= 0 for v in vs), "a vertex outside a face (seen from outside)")
                expect(h(c) < 0, "the centroid is not strictly inside")

        def quadrature_declines_instead_of_subdividing_forever():
            # A triangle from the origin to 1e20: the subdivision grew as 4^depth (minutes).
            one = r.file("1,1,1\n")
            for e in (20, 40, 150):
                tri = r.file(f"1e-{e},1e-{e},1\n1e{e},0,1\n0,1e{e},1\n")
                rc, out, err = r.run("select", "--canonical", tri, "--image", one, "--mean3d",
                                     "quadrature", "--order", "12", "--json", timeout=120)
                expect(rc == 0, (e, rc, err))
                m = json.loads(out)["selections"]["mean_3d"]
                expect(m["map"] is None and "extended precision" in m["note"], (e, m))
                rc, out, err = r.run("select", "--canonical", tri, "--image", one, "--json", timeout=120)
                m = json.loads(out)["selections"]["mean_3d"]
                expect(rc == 0 and m["method"] == "analytic" and m["map"] is not None, (e, m))

        def min_violation_refuses_beyond_its_limit():
            # O(k·m²) in rationals: 6000 gamut edges took 150 s; more than 2000 are refused.
            n = 2001
            para = r.file("\n".join(f"{1 + Fr(i, n)},{1 + Fr(i, n) ** 2},1"
                                    for i in range(n)) + "\n")
            far = r.file("1,1,1\n1000,1,1\n1,1000,1\n")
            refused(r, ["select", "--canonical", para, "--image", far, "--on-empty", "min-violation"],
                    "--on-empty", "at most 2000 vertices", "2001")
            rc, out, err = r.run("select", "--canonical", para, "--image", far, "--on-empty",
                                 "grow-canonical", "--json", timeout=300)
            expect(rc == 0 and json.loads(out)["recovery"]["applied"], (rc, err))

        for name, fn in list(locals().items()):
            if callable(fn) and name not in ("r", "refused"):
                r.check(name, fn)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
