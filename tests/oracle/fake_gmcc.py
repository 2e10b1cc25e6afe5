#!/usr/bin/python3
"""A stand-in for the `gmcc` binary, built on select_oracle.py, to exercise the CLI test drivers
(tests/cli/test_select_oracle.py, tests/cli/test_select_errors.py) before the C++ tool exists.

    fake_gmcc.py select --canonical C.csv --image I.csv --json

With GMCC_FAKE_BUG=<name> it injects one known bug, to show that the drivers catch it:
  float_parse     numbers read as doubles and then converted exactly (0.1 != 1/10)
  clockwise       polygon vertices listed clockwise
  mean3d_double   3-D mean by Arvo's formula in double precision (docs/derivations.md §1.6),
                  tiny error bound
  worst_acos      worst-case angle via acos of the normalised dot product in double
  degenerate_empty  segment/point feasible sets reported as empty (regularised Booleans)
  unreduced       integers written "p/1"
  no_line         error messages without the line number
  stdout_on_error a partial JSON document on stdout before a bad-input error
  rotate          polygon vertices start at another index (NOT a bug: must still pass)
"""

import json
import math
import os
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import select_oracle as so  # noqa: E402

BUG = os.environ.get("GMCC_FAKE_BUG", "")


def _double_parse(field):
    value = _original_parse_number(field)  # keeps the error behaviour
    return Fraction(float(value))


def _mean3d_double(kind, vertices):
    if kind != "polygon":
        return _original_mean_3d(kind, vertices)
    tau = [0.0, 0.0, 0.0]
    n = len(vertices)
    for i in range(n):
        u = (float(vertices[i][0]), float(vertices[i][1]), 1.0)
        v = (float(vertices[(i + 1) % n][0]), float(vertices[(i + 1) % n][1]), 1.0)
        c = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        norm = math.sqrt(c[0] ** 2 + c[1] ** 2 + c[2] ** 2)
        theta = math.atan2(norm, u[0] * v[0] + u[1] * v[1] + u[2] * v[2])
        for k in range(3):
            tau[k] += theta * c[k] / norm
    return (tau[0] / tau[2], tau[1] / tau[2]), 1e-16


def _angle_acos(m, v):
    a = (float(m[0]), float(m[1]), 1.0)
    b = (float(v[0]), float(v[1]), 1.0)
    dot = sum(x * y for x, y in zip(a, b))
    c = dot / math.sqrt(sum(x * x for x in a) * sum(x * x for x in b))
    return math.degrees(math.acos(min(1.0, c)))


_original_parse_number = so.parse_number
_original_mean_3d = so.mean_3d
_original_feasible_set = so.feasible_set

if BUG == "float_parse":
    so.parse_number = _double_parse
elif BUG == "mean3d_double":
    so.mean_3d = _mean3d_double
elif BUG == "worst_acos":
    so.angle_deg = _angle_acos
elif BUG == "degenerate_empty":
    def _regularised(c, i):
        kind, verts = _original_feasible_set(c, i)
        return ("empty", []) if kind in ("segment", "point") else (kind, verts)
    so.feasible_set = _regularised
elif BUG == "unreduced":
    so.rational_text = lambda x: f"{Fraction(x).numerator}/{Fraction(x).denominator}"


def main(argv):
    args = argv[1:]
    if not args or args[0] != "select":
        sys.stderr.write("usage: fake_gmcc.py select --canonical C.csv --image I.csv --json\n")
        return 2
    opts = {}
    i = 1
    while i < len(args):
        if args[i] in ("--canonical", "--image") and i + 1 < len(args):
            opts[args[i]] = args[i + 1]
            i += 2
        elif args[i] == "--json":
            i += 1
        else:
            sys.stderr.write(f"gmcc: error: unknown option {args[i]}\n")
            return 2
    try:
        result = so.select_from_files(opts["--canonical"], opts["--image"])
    except KeyError:
        sys.stderr.write("gmcc: error: --canonical and --image are required\n")
        return 2
    except so.InputError as e:
        if BUG == "no_line":
            e.line = None
        if BUG == "stdout_on_error":
            sys.stdout.write('{"feasible_set": ')
        sys.stderr.write(e.message() + "\n")
        return 2
    fs = result["feasible_set"]
    if BUG == "clockwise" and fs["kind"] == "polygon":
        fs["vertices"].reverse()
        fs["vertices_approx"].reverse()
    if BUG == "rotate" and fs["kind"] == "polygon":
        fs["vertices"] = fs["vertices"][1:] + fs["vertices"][:1]
        fs["vertices_approx"] = fs["vertices_approx"][1:] + fs["vertices_approx"][:1]
    print(json.dumps({k: v for k, v in result.items() if k != "_exact"}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
