#!/usr/bin/python3
"""Determinism (docs/conventions.md §7): identical inputs and seeds give identical output bytes.

    /usr/bin/python3 tests/cli/test_determinism.py GMCC_BINARY

Runs, each twice under different surroundings (working directory, locale and time-zone variables,
environment size), and compares stdout byte for byte:
  * `gmcc select` on the shipped sample gamuts with each 3-D mean route (analytic, quadrature,
    monte-carlo --seed 7), as JSON and as text;
  * `gmcc accuracy --max-samples 10000` (its table).
A different seed must change the Monte Carlo output (so the comparison can fail), and the JSON
must name the seed it used. gmcc is single-threaded, so there are no thread counts to vary.

The last line is exactly `N passed, N failed`; the exit status is 0 iff none failed.
"""

import json
import os
import subprocess
import sys

import tempfile

from cli_harness import Tally

HERE = os.path.dirname(os.path.abspath(__file__))
SAMPLES = os.path.join(HERE, "..", "..", "data", "samples")
CANONICAL = os.path.join(SAMPLES, "canonical_munsell_D55.csv")
IMAGE = os.path.join(SAMPLES, "image_munsell_D75.csv")
TIMEOUT_S = 300

# Two surroundings that must not matter: a C++ program that honoured the locale would print
# "1,5" for 1.5 under de_DE; the environment's size shifts the stack and heap addresses.
SURROUNDINGS = [
    {"LC_ALL": "C", "TZ": "UTC"},
    {"LC_ALL": "de_DE.UTF-8", "LANG": "de_DE.UTF-8", "TZ": "Pacific/Chatham", "PADDING": "x" * 4096},
]



tally = Tally()
check = tally.check


def run(binary, args, surroundings, cwd):
    env = dict(os.environ)
    env.update(surroundings)
    p = subprocess.run([binary] + args, capture_output=True, env=env, cwd=cwd, timeout=TIMEOUT_S)
    check(p.returncode == 0, f"{args}: exit {p.returncode}, stderr {p.stderr[-300:]!r}")
    return p.stdout


def twice(binary, args, tmp):
    """stdout of two runs in different surroundings and directories; checked equal."""
    a = run(binary, args, SURROUNDINGS[0], tmp)
    b = run(binary, args, SURROUNDINGS[1], HERE)
    check(a != b"" and a == b, f"{' '.join(args[:4])}...: same bytes both times")
    return a


def main():
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    binary = os.path.abspath(sys.argv[1])
    select = ["select", "--canonical", os.path.abspath(CANONICAL), "--image", os.path.abspath(IMAGE)]
    with tempfile.TemporaryDirectory(prefix="gmcc-determinism-") as tmp:
        for route in (["--mean3d", "analytic"], ["--mean3d", "quadrature"],
                      ["--mean3d", "monte-carlo", "--seed", "7"]):
            twice(binary, select + route + ["--json"], tmp)
            twice(binary, select + route, tmp)
        mc = select + ["--mean3d", "monte-carlo", "--json"]
        seven = json.loads(run(binary, mc + ["--seed", "7"], SURROUNDINGS[0], tmp))
        eight = json.loads(run(binary, mc + ["--seed", "8"], SURROUNDINGS[0], tmp))
        m7, m8 = seven["selections"]["mean_3d"], eight["selections"]["mean_3d"]
        check(m7["seed"] == 7 and m8["seed"] == 8, "the JSON names the seed used")
        check(m7["map"] != m8["map"], "another seed changes the Monte Carlo map")
        check(seven["selections"]["max_area"] == eight["selections"]["max_area"],
              "the seed changes nothing but Monte Carlo")
        twice(binary, ["accuracy", "--max-samples", "10000"], tmp)
    return tally.finish()


if __name__ == "__main__":
    sys.exit(main())
