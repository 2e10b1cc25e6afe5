#!/usr/bin/python3
"""Input handling of `gmcc select` (docs/cli.md "Input files"): bad input and odd-but-valid input.

    /usr/bin/python3 tests/cli/test_select_errors.py GMCC_BINARY

Bad input (missing file, malformed number, NaN/inf, negative channel, wrong column count, no
usable colour, binary garbage, a line or number beyond the limits of docs/cli.md) must give exit
status 2, NOTHING on stdout, and exactly one short message line on stderr, free of control
characters, of the form `gmcc: error: FILE:LINE: what` naming the offending file and, for
line-level problems, the physical 1-based line number (`FILE:LINE:`).  The bad file is tried
both as --canonical and as --image (the other file valid).  So are directories, unreadable files
(unless run as root), maps beyond the limits, and a full disk on stdout (/dev/full).

Odd but valid input (CRLF, UTF-8 BOM, comments, blank lines, spaces around numbers, p/q, the
header `r,g,b`, colours with b = 0, exponents beyond double range) must give exit status 0 and
one JSON object equal to the oracle's answer; and decimals must be read exactly (`0.1` is 1/10,
checked through a point feasible set whose exact coordinates differ if 0.1 were a double).

The last line is exactly `N passed, N failed`; the exit status is 0 iff none failed.
"""

import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as Fr

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "oracle"))
import select_oracle as so  # noqa: E402
from test_select_oracle import compare  # noqa: E402

TIMEOUT_S = 60

GOOD = b"1,1,1\n2,1,1\n2,2,1\n1,2,1\n"  # chromaticities: the square [1,2]^2
GOOD_IMAGE = b"3,3,2\n"

# (name, bad file content, expected line number or None for a file-level problem)
BAD_CONTENT = [
    ("malformed 1.2.3", b"r,g,b\n1,1,1\n1.2.3,1,1\n", 3),
    ("malformed abc", b"1,1,1\n2,abc,1\n", 2),
    ("zero denominator 1/0", b"1,1,1\n1/0,1,1\n", 2),
    ("empty field", b"1,1,1\n1,,1\n", 2),
    ("blank field", b"1,1,1\n1, ,1\n", 2),
    ("trailing comma", b"1,1,1\n1,1,1,\n", 2),
    ("exponent without digits", b"1e,1,1\n", 1),
    ("p/ without q", b"1/,1,1\n", 1),
    ("/q without p", b"/2,1,1\n", 1),
    ("p/q/r", b"1/2/3,1,1\n", 1),
    ("two dots", b"1..2,1,1\n", 1),
    ("space inside a number", b"1 2,1,1\n", 1),
    ("hexadecimal", b"0x10,1,1\n", 1),
    ("double sign", b"--1,1,1\n", 1),
    ("NaN", b"1,1,1\n# ok\nNaN,1,1\n", 3),
    ("nan", b"nan,1,1\n", 1),
    ("inf", b"1,1,1\n1,inf,1\n", 2),
    ("Infinity", b"1,1,Infinity\n", 1),
    ("-inf", b"1,1,1\n\n-inf,1,1\n", 3),
    ("negative r", b"1,1,1\n-1,1,1\n", 2),
    ("negative g decimal", b"1,1,1\n1,-0.5,1\n", 2),
    ("negative b rational", b"1,1,1\n2,2,2\n1,1,-1/2\n", 3),
    ("2 columns", b"1,1,1\n1,1\n", 2),
    ("4 columns", b"1,1,1\n1,1,1,1\n", 2),
    ("1 column", b"5\n", 1),
    ("only comments and header", b"# nothing here\nr,g,b\n\n# still nothing\n", None),
    ("empty file", b"", None),
    ("only blank lines", b"\n\n  \n", None),
    ("all colours with b = 0", b"1,2,0\n3,4,0\n0,0,0\n", None),
    ("binary garbage", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe\x00\x01\xc3\x28", None),
    # Line numbers count every physical line, with BOM, CRLF, comments, blanks and header.
    ("line count with BOM and CRLF", b"\xef\xbb\xbfr,g,b\r\n# c\r\n\r\n1,2,3\r\n1,x,3\r\n", 5),
    ("line count after b = 0 lines", b"1,1,1\n1,1,0\n0,0,0\n1,1,1\n1,1,abc\n", 5),
    ("late error", b"".join(b"%d,%d,%d\n" % (i, i + 1, i + 2) for i in range(1, 50))
     + b"1,2,3,4\n", 50),
    # Limits (docs/cli.md): line length, digits per number, and chromaticities the doubles of
    # the output can hold; messages quote at most 40 characters, non-printable bytes escaped.
    ("enormous line", b"1,1,1\n" + b"7" * 100000 + b"\n", 2),
    ("a megabyte with no line end", b"1" * (1 << 20), 1),
    ("number with 101 digits", b"1,1,1\n1,2," + b"3" * 101 + b"\n", 2),
    ("exponent beyond 400", b"1,1,1\n1,1,4e+3619\n", 2),
    ("p/q with 101 digits", b"1,1,1\n1,2," + b"3" * 50 + b"/" + b"7" * 51 + b"\n", 2),
    ("binary garbage without NUL", b"1,1,1\n\x80\x81,\xfe\xff,\x01\x1b[2J\n", 2),
    ("chromaticity beyond 1e150", b"1,1,1\n1,1,1e-151\n", 2),
    ("r/b beyond 1e150", b"1,1,1\n1e100,1,1/1" + b"0" * 60 + b"\n", 2),
]


class Runner:
    def __init__(self, binary, tmp):
        self.binary = binary
        self.tmp = tmp
        self.count = 0
        self.passed = 0
        self.failed = 0

    def write(self, content, tag):
        self.count += 1
        path = os.path.join(self.tmp, f"{self.count:03d}-{tag}.csv")
        with open(path, "wb") as f:
            f.write(content)
        return path

    def run(self, cpath, ipath, extra=(), stdout=subprocess.PIPE):
        try:
            p = subprocess.run([self.binary, "select", "--canonical", cpath, "--image", ipath,
                                "--json", *extra], stdout=stdout, stderr=subprocess.PIPE,
                               timeout=TIMEOUT_S)
            return p.returncode, p.stdout or b"", p.stderr
        except subprocess.TimeoutExpired:
            return None, b"", b"(timed out)"

    def record(self, name, problems, detail):
        if problems:
            self.failed += 1
            print(f"FAIL {name}")
            for p in problems:
                print(f"  - {p}")
            print(detail)
        else:
            self.passed += 1

    def expect_error(self, name, cpath, ipath, bad_path, line, extra=(), stdout=subprocess.PIPE):
        code, out, err = self.run(cpath, ipath, extra, stdout)
        problems = []
        if len(err) > 600:
            problems.append(f"message of {len(err)} bytes")
        if any(b < 0x20 and b != 0x0A or b == 0x7F for b in err):
            problems.append("control characters in the message")
        if code != 2:
            problems.append(f"exit status {code}, expected 2")
        if out != b"":
            problems.append(f"stdout not empty: {out[:300]!r}")
        text = err.decode("utf-8", "replace")
        lines = [l for l in text.splitlines() if l.strip()]
        if len(lines) != 1:
            problems.append(f"stderr should hold exactly one message line, has {len(lines)}")
        elif not lines[0].startswith("gmcc: error: "):
            problems.append("message does not start with 'gmcc: error: '")
        if bad_path not in text:
            problems.append(f"message does not name the file {bad_path}")
        elif line is not None and f"{bad_path}:{line}:" not in text:
            problems.append(f"message does not give the line as '{bad_path}:{line}:'")
        self.record(name, problems, f"  stderr: {text.strip()[:500]!r}")

    def expect_success(self, name, canonical, image, exact=None):
        """Valid input: exit 0, one JSON object equal to the oracle's; `exact` optionally
        gives the expected exact feasible-set vertices [(x, y)] (hand-derived)."""
        cpath, ipath = self.write(canonical, "canonical"), self.write(image, "image")
        code, out, err = self.run(cpath, ipath)
        problems = []
        got = None
        if code != 0:
            problems.append(f"exit status {code} on valid input")
        else:
            try:
                got = json.loads(out.decode("utf-8"))
            except (UnicodeDecodeError, json.JSONDecodeError) as e:
                problems.append(f"stdout is not one JSON document: {e}")
        try:
            oracle = so.select_from_files(cpath, ipath)
        except so.InputError as e:
            raise AssertionError(f"oracle rejects the valid case {name}: {e.message()}")
        if exact is not None:
            assert [tuple(v) for v in oracle["_exact"]["vertices"]] == exact, name
        if got is not None:
            problems += compare(oracle, got, {})
        self.record(name, problems,
                    f"  canonical: {canonical!r}\n  image: {image!r}\n"
                    f"  binary stdout: {out[:3000]!r}\n  stderr: {err[:500]!r}")


def main():
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    with tempfile.TemporaryDirectory(prefix="gmcc-select-errors-") as tmp:
        r = Runner(sys.argv[1], tmp)

        # Missing files.
        missing = os.path.join(tmp, "does-not-exist.csv")
        r.expect_error("missing canonical file", missing, r.write(GOOD_IMAGE, "image"), missing, None)
        r.expect_error("missing image file", r.write(GOOD, "canonical"), missing, missing, None)

        # Each bad content, as the canonical file and as the image file.
        for name, content, line in BAD_CONTENT:
            bad = r.write(content, "bad")
            r.expect_error(f"{name} (canonical)", bad, r.write(GOOD_IMAGE, "image"), bad, line)
            bad = r.write(content, "bad")
            r.expect_error(f"{name} (image)", r.write(GOOD, "canonical"), bad, bad, line)

        # Whole-file and whole-run problems.
        r.expect_error("a directory", tmp, r.write(GOOD_IMAGE, "image"), tmp, None)
        if os.geteuid() != 0:  # as root, mode 000 does not stop reads
            unreadable = r.write(GOOD, "unreadable")
            os.chmod(unreadable, 0)
            r.expect_error("unreadable file", unreadable, r.write(GOOD_IMAGE, "image"), unreadable, None)
        huge = r.write(b"", "huge")  # sparse: 257 MiB of zeros that take no disk space
        os.truncate(huge, 257 << 20)
        r.expect_error("file larger than 256 MiB", huge, r.write(GOOD_IMAGE, "image"), huge, None)
        os.remove(huge)
        big = r.write(b"1e140,1e140,1\n", "canonical")
        small = r.write(b"1e-20,1e-20,1\n", "image")
        r.expect_error("feasible maps beyond 1e150", big, small, small, None)
        r.expect_error("expansion beyond 1e150", r.write(GOOD, "canonical"),
                       r.write(GOOD_IMAGE, "image"), "--expand", None,
                       extra=("--expand", "1e200", "--expand-policy", "multiplicative"))
        if os.path.exists("/dev/full"):  # a full disk: the output cut short must not pass
            with open("/dev/full", "wb") as full:
                r.expect_error("stdout on a full disk", r.write(GOOD, "canonical"),
                               r.write(GOOD_IMAGE, "image"), "standard output", None,
                               stdout=full)

        # Odd but valid input.  The square [1,2]^2 with the single image q = (3/2,3/2) gives
        # F = [1,2]^2 / (3/2) = [2/3,4/3]^2.
        box = [(Fr(2, 3), Fr(2, 3)), (Fr(4, 3), Fr(2, 3)), (Fr(4, 3), Fr(4, 3)), (Fr(2, 3), Fr(4, 3))]
        r.expect_success("plain", GOOD, GOOD_IMAGE, box)
        r.expect_success("CRLF line ends", GOOD.replace(b"\n", b"\r\n"), b"3,3,2\r\n", box)
        r.expect_success("no final newline", GOOD.rstrip(b"\n"), b"3,3,2", box)
        r.expect_success("UTF-8 BOM", b"\xef\xbb\xbf" + GOOD, b"\xef\xbb\xbf3,3,2\n", box)
        r.expect_success("BOM, header and CRLF", b"\xef\xbb\xbfr,g,b\r\n" + GOOD.replace(b"\n", b"\r\n"),
                         b"\xef\xbb\xbfr,g,b\r\n3,3,2\r\n", box)
        r.expect_success("comments and blank lines",
                         b"# canonical square\n\n1,1,1\n# more\n2,1,1\n\n\n2,2,1\n1,2,1\n# end\n",
                         b"\n# image\n3,3,2\n\n", box)
        r.expect_success("spaces around numbers", b" 1 , 1 ,1\n2,  1,1  \n  2,2,1\n1 ,2 , 1\n",
                         b"  3 ,3,  2  \n", box)
        r.expect_success("p/q numbers", b"1/1,2/2,3/3\n4/2,1,1\n2,6/3,1\n1,2,5/5\n", b"3/2,3/2,1\n", box)
        r.expect_success("header r,g,b", b"r,g,b\n" + GOOD, b"r,g,b\n3,3,2\n", box)
        r.expect_success("decimals and exponents",
                         b"1.0,1.00,1\n2.0,1e0,1.0E+0\n20e-1,0.2e1,1\n1,2,1.000\n", b"1.5,1.5,1\n", box)
        r.expect_success("colours with b = 0 are dropped", GOOD + b"1,2,0\n0,0,0\n",
                         b"5,6,0\n3,3,2\n", box)
        r.expect_success("100-digit numbers", GOOD.replace(b"2,2,1", b"2." + b"0" * 99 + b",2,1"),
                         b"3" + b"0" * 49 + b"/1" + b"0" * 49 + b",3,2\n", box)

        # Exact decimals.  Canonical (0.1,0.2,0.3) -> q_c = (1/3, 2/3); image (0.3,0.1,0.7) ->
        # q = (3/7, 1/7); F = {q_c / q} = the point (7/9, 14/3).  With doubles the coordinates
        # would be ratios of binary fractions, not 7/9 and 14/3.
        r.expect_success("0.1 is exactly 1/10", b"0.1,0.2,0.3\n", b"0.3,0.1,0.7\n",
                         [(Fr(7, 9), Fr(14, 3))])
        r.expect_success("1.5e-3 is exactly 3/2000", b"1.5e-3,3e-3,1\n", b"1,1,1\n",
                         [(Fr(3, 2000), Fr(3, 1000))])
        r.expect_success("0.1 against 1/10", b"0.1,0.7,0.3\n", b"1/10,1/10,3/10\n",
                         [(Fr(1), Fr(7))])
        # Beyond double range: 1e400 overflows and 1e-400 underflows a double.
        r.expect_success("exponents beyond double range", b"1e400,2e400,3e400\n",
                         b"1e-400,1e-400,1e-400\n", [(Fr(1, 3), Fr(2, 3))])

        print(f"{r.passed} passed, {r.failed} failed")
        return 1 if r.failed else 0


if __name__ == "__main__":
    sys.exit(main())
