#!/usr/bin/python3
"""`gmcc accuracy` (docs/accuracy.md): the study's numbers obey what each route promises.

    /usr/bin/python3 tests/cli/test_accuracy.py GMCC_BINARY

Runs `GMCC_BINARY accuracy --max-samples 100000 --csv ... --plot ...` (a quick run: Monte Carlo
at 10^4 and 10^5 samples only) and checks, from the CSV, at every width w = 10 ... 1e-12:
  * the reference (4096-bit closed form) is within 2^-53 relative of the true map, i.e. its
    reported bound is no more than the rounding to double;
  * the certified closed form: error <= its bound + the reference's bound (both are rigorous,
    so this cannot fail unless one of them is wrong), and <= 1e-15 relative;
  * the double closed form (docs/derivations.md §1.6): fine at w = 10 and 1 (<= 1e-14), broken
    at w = 1e-8 (> 1e-6), and worse at 1e-6 than at 1e-2;
  * quadrature: order 16 within its own estimate (+ the reference's bound); every order within
    1.5 times its estimate; order 16 no worse than order 2; and for w <= 1e-4 every order >= 4
    within 1e-15 relative (it works in offsets, so small polygons do not cancel);
  * Monte Carlo: a run is either valid, with >= 1000 points kept and error <= 6 standard
    errors, or marked too few samples (n/a) with < 1000 kept; no run keeps more than it drew.
Also: the same seed gives the same bytes, another seed changes only the Monte Carlo rows; the
plot data and script are written (and the PNG/SVG when gnuplot is on PATH); bad option values
and unwritable paths give exit status 2, nothing on stdout, one `gmcc: error:` line, and leave
no file behind.

The last line is exactly `N passed, N failed`; the exit status is 0 iff none failed.
"""

import csv
import os
import shutil
import subprocess
import sys
import tempfile

TIMEOUT_S = 120
CAP = 100000
WIDTHS = ["10", "1"] + [f"1e-{k}" for k in range(1, 13)]
HEADER = "width,route,parameter,error_abs,error_rel,reported_bound,extra"


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, condition, what):
        if condition:
            self.passed += 1
        else:
            self.failed += 1
            print(f"FAIL: {what}")


def run(binary, args):
    return subprocess.run([binary, "accuracy"] + args, capture_output=True, timeout=TIMEOUT_S)


def read_csv(path):
    with open(path, newline="") as f:
        text = f.read()
    # The first line is the provenance record (docs/cli.md "Provenance"; test_provenance.py).
    lines = text.splitlines()
    if lines and lines[0].startswith("# gmcc-provenance: "):
        lines = lines[1:]
        text = text.split("\n", 1)[1]
    rows = list(csv.DictReader(lines))
    return text, rows


def extra_fields(extra):
    out = {}
    for item in extra.split(";"):
        if "=" in item:
            key, value = item.split("=", 1)
            out[key] = value
    return out


def check_study(c, rows):
    by = {}
    for r in rows:
        by[(r["width"], r["route"], r["parameter"])] = r
    c.check([r["width"] for r in rows if r["route"] == "reference"] == WIDTHS,
            f"one reference row per width, in order {WIDTHS}")
    counts = ["10000", "100000"]  # 10^4, 10^5 capped at CAP; 10^6 and 10^7 collapse onto CAP
    expected = {"reference": ["4096"], "double": [""], "analytic": ["auto"],
                "quadrature": ["2", "4", "8", "16"], "monte-carlo": counts}
    for w in WIDTHS:
        got = {}
        for r in rows:
            if r["width"] == w:
                got.setdefault(r["route"], []).append(r["parameter"])
        c.check(got == expected, f"w={w}: routes and parameters {got} == {expected}")

    def f(w, route, param, column):
        return float(by[(w, route, param)][column])

    for w in WIDTHS:
        ref = by.get((w, "reference", "4096"))
        if ref is None:
            continue
        ex = extra_fields(ref["extra"])
        c.check(ex.get("precision_bits") == "4096", f"w={w}: reference at 4096 bits")
        m = [float(x) for x in ex.get("map", "nan nan").split()]
        scale = max(abs(m[0]), abs(m[1]))
        ref_bound = float(ref["reported_bound"])
        c.check(0 < ref_bound <= 2.0 ** -53 * scale,
                f"w={w}: reference bound {ref_bound} <= 2^-53 * {scale} (only the rounding)")
        # The map is near (1.1, 0.7) except where w = 10 is clipped.
        if w != "10":
            c.check(abs(m[0] - 1.1) <= float(w) and abs(m[1] - 0.7) <= float(w),
                    f"w={w}: reference map {m} within w of the centre (1.1, 0.7)")

        e, b = f(w, "analytic", "auto", "error_abs"), f(w, "analytic", "auto", "reported_bound")
        c.check(e <= b + ref_bound, f"w={w}: analytic error {e} <= bound {b} + ref {ref_bound}")
        c.check(f(w, "analytic", "auto", "error_rel") <= 1e-15,
                f"w={w}: analytic relative error <= 1e-15")
        c.check(b <= 2.0 ** -51 * scale, f"w={w}: analytic bound {b} <= 2^-51 relative")
        bits = int(extra_fields(by[(w, "analytic", "auto")]["extra"]).get("precision_bits", 0))
        c.check(bits >= 53, f"w={w}: analytic precision_bits {bits} >= 53")

        q = {n: (f(w, "quadrature", n, "error_abs"), f(w, "quadrature", n, "reported_bound"))
             for n in ["2", "4", "8", "16"]}
        c.check(q["16"][0] <= q["16"][1] + ref_bound,
                f"w={w}: quadrature n=16 error {q['16'][0]} <= its estimate {q['16'][1]} + ref")
        for n, (err, est) in q.items():
            c.check(err <= 1.5 * est + ref_bound,
                    f"w={w}: quadrature n={n} error {err} <= 1.5 x estimate {est} + ref")
        c.check(q["16"][0] <= q["2"][0] + ref_bound, f"w={w}: quadrature n=16 no worse than n=2")
        if float(w) <= 1e-4:
            for n in ["4", "8", "16"]:
                rel = f(w, "quadrature", n, "error_rel")
                c.check(rel <= 1e-15, f"w={w}: quadrature n={n} relative error {rel} <= 1e-15")

        for n in counts:
            r = by.get((w, "monte-carlo", n))
            if r is None:
                continue
            ex = extra_fields(r["extra"])
            kept = int(ex.get("kept", -1))
            c.check(0 <= kept <= int(n), f"w={w} N={n}: 0 <= kept {kept} <= N")
            if r["error_abs"] == "n/a":
                c.check(kept < 1000 and "too few" in r["extra"] and r["error_rel"] == "n/a"
                        and r["reported_bound"] == "n/a",
                        f"w={w} N={n}: invalid run has < 1000 kept and says too few: {r}")
            else:
                err, se = float(r["error_abs"]), float(r["reported_bound"])
                c.check(kept >= 1000 and 0 < se and err <= 6 * se,
                        f"w={w} N={n}: valid run, kept {kept} >= 1000, error {err} <= 6 SE {se}")
        if float(w) <= 1e-3:
            c.check(all(by[(w, "monte-carlo", n)]["error_abs"] == "n/a" for n in counts),
                    f"w={w}: Monte Carlo at <= {CAP} samples has too few samples")

    d = {w: f(w, "double", "", "error_abs") for w in WIDTHS if (w, "double", "") in by}
    if len(d) == len(WIDTHS):
        c.check(d["10"] <= 1e-14 and d["1"] <= 1e-14, f"double closed form fine at w >= 1: {d}")
        c.check(d["1e-8"] > 1e-6, f"double closed form broken at w = 1e-8: {d['1e-8']} > 1e-6")
        c.check(d["1e-6"] > d["1e-2"], "double closed form worse at 1e-6 than at 1e-2")
    c.check(by.get(("10", "monte-carlo", "10000"), {}).get("error_abs", "n/a") != "n/a",
            "Monte Carlo at 10^4 samples is valid for w = 10")


def expect_error(c, binary, name, args, tmp):
    before = sorted(os.listdir(tmp))
    p = run(binary, args)
    lines = p.stderr.decode(errors="replace").strip().splitlines()
    c.check(p.returncode == 2 and p.stdout == b"" and lines and lines[0].startswith("gmcc: error:"),
            f"{name}: exit 2, empty stdout, `gmcc: error:` (got {p.returncode}, {p.stdout[:80]!r}, "
            f"{lines[:2]})")
    c.check(sorted(os.listdir(tmp)) == before, f"{name}: no file left behind")


def leftover_temporaries(root):
    return [os.path.join(d, f) for d, _, files in os.walk(root) for f in files if ".tmp-" in f]


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    c = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        out_csv = os.path.join(tmp, "a.csv")
        fig = os.path.join(tmp, "fig")
        p = run(binary, ["--max-samples", str(CAP), "--csv", out_csv, "--plot", fig])
        c.check(p.returncode == 0, f"study runs (exit {p.returncode}, stderr {p.stderr[-300:]!r})")
        stdout = p.stdout.decode()
        for w in WIDTHS:
            c.check(any(line.split()[:1] == [w] for line in stdout.splitlines()),
                    f"table has a row for width {w}")
        c.check("Monte Carlo" in stdout and "N=1e5" in stdout and "N=1e6" not in stdout,
                "table's Monte Carlo columns follow --max-samples")
        if os.path.exists(out_csv):
            text, rows = read_csv(out_csv)
            c.check(text.splitlines()[0] == HEADER, f"CSV header is {HEADER}")
            try:
                check_study(c, rows)
            except (KeyError, ValueError) as e:
                c.check(False, f"CSV complete and well-formed ({e!r})")
        else:
            c.check(False, "CSV written")

        dat, gp = os.path.join(fig, "accuracy.dat"), os.path.join(fig, "accuracy.gp")
        c.check(os.path.isfile(dat) and os.path.isfile(gp), "plot data and script written")
        if os.path.isfile(gp):
            with open(gp) as f:
                script = f.read()
            c.check("'accuracy.dat'" in script and script.count(" index ") >= 9,
                    "plot script draws accuracy.dat, one index per line")
        if shutil.which("gnuplot"):
            png, svg = os.path.join(fig, "accuracy.png"), os.path.join(fig, "accuracy.svg")
            c.check(os.path.isfile(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n",
                    "gnuplot made accuracy.png")
            c.check(os.path.isfile(svg) and b"<svg" in open(svg, "rb").read(2000),
                    "gnuplot made accuracy.svg")
        c.check(leftover_temporaries(tmp) == [], f"no temporary files left: {leftover_temporaries(tmp)}")

        # Reproducible: same seed, same bytes (and no progress chatter when stderr is no tty);
        # another seed moves only the Monte Carlo rows.
        again = os.path.join(tmp, "again.csv")
        p2 = run(binary, ["--max-samples", str(CAP), "--csv", again])
        c.check(p2.returncode == 0 and p2.stderr == b"", "second run: exit 0, nothing on stderr")
        c.check(p2.stdout == p.stdout, "same seed: same table")
        if os.path.exists(out_csv) and os.path.exists(again):
            c.check(read_csv(again)[0] == read_csv(out_csv)[0], "same seed: same CSV bytes")
            other = os.path.join(tmp, "seed2.csv")
            p3 = run(binary, ["--max-samples", str(CAP), "--seed", "2", "--csv", other])
            if p3.returncode == 0:
                a, b = read_csv(out_csv)[1], read_csv(other)[1]
                same = [x == y for x, y in zip(a, b)]
                mc = [x["route"] == "monte-carlo" for x in a]
                c.check(len(a) == len(b) and all(s for s, m in zip(same, mc) if not m)
                        and not all(s for s, m in zip(same, mc) if m),
                        "seed 2 changes the Monte Carlo rows and nothing else")
            else:
                c.check(False, f"--seed 2 runs (exit {p3.returncode})")

    with tempfile.TemporaryDirectory() as tmp:
        a_file = os.path.join(tmp, "file")
        with open(a_file, "w") as f:
            f.write("x\n")
        for name, args in [
            ("--max-samples 0", ["--max-samples", "0"]),
            ("--max-samples -1", ["--max-samples", "-1"]),
            ("--max-samples 2.5", ["--max-samples", "2.5"]),
            ("--max-samples abc", ["--max-samples", "abc"]),
            ("--max-samples 1e99", ["--max-samples", "1e99"]),
            ("--seed -1", ["--seed", "-1"]),
            ("--seed 2^64", ["--seed", "18446744073709551616"]),
            ("--seed 1/2", ["--seed", "1/2"]),
            ("--csv ''", ["--csv", ""]),
            ("--csv in a missing directory", ["--csv", os.path.join(tmp, "missing", "a.csv")]),
            ("--csv a directory", ["--csv", tmp]),
            ("--plot under a file", ["--plot", os.path.join(a_file, "fig")]),
            ("--plot a file", ["--plot", a_file]),
            ("unknown option", ["--samples", "10"]),
        ]:
            quick = [] if args[0] == "--max-samples" else ["--max-samples", "10"]
            expect_error(c, binary, name, quick + args, tmp)
        # A good value written the way gmcc reads numbers: 1e4 is 10000.
        p = run(binary, ["--max-samples", "1e4", "--seed", "0"])
        c.check(p.returncode == 0 and b"N=1e4" in p.stdout and b"N=1e5" not in p.stdout,
                "--max-samples 1e4 is read exactly as 10000")

    print(f"{c.passed} passed, {c.failed} failed")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
