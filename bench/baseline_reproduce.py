#!/usr/bin/python3
"""Benchmark baseline: the synthetic colour-constancy experiment of
Finlayson & Hordley (1999), section 4, Fig. 3, on plain doubles in Python.

The test oracle tests/oracle/reproduce_oracle.py (the independent Python
implementation of the experiment) extended to the pipeline gmcc's experiment
runs per scene: besides the feasible set, the three rules, their map errors
and map-space worst cases, it also computes the illuminant-space and
reproduction errors and whether the true map lies in F.  It imports the
oracle's pipeline and adds only these; the output is the oracle's CSV (the
additions are computed, not printed).  It is the "straightforward
floating-point implementation" that bench/run_reproduce_bench.py times gmcc
against; it is not part of the library and not a test.

Usage:
    baseline_reproduce.py [--scenes S] [--seed X] [--data DIR] [--lights D75,P2856]
                          [--surfaces 1-11] [--check-illuminants] [--quiet]

Options, CSV columns and pipeline: see tests/oracle/reproduce_oracle.py.
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "oracle"))

import reproduce_oracle as ro  # noqa: E402
from reproduce_oracle import REL_EPS, cross2  # noqa: E402


def angle3(a, b):
    """Angle between two 3-vectors, degrees, atan2 form."""
    cx = a[1] * b[2] - a[2] * b[1]
    cy = a[2] * b[0] - a[0] * b[2]
    cz = a[0] * b[1] - a[1] * b[0]
    return math.degrees(math.atan2(math.sqrt(cx * cx + cy * cy + cz * cz),
                                   a[0] * b[0] + a[1] * b[1] + a[2] * b[2]))


def contains(poly, m):
    """m in the CCW polygon (closed), in doubles with the clipping tolerance."""
    k = len(poly)
    if k < 3:
        return True
    for i in range(k):
        a, b = poly[i], poly[(i + 1) % k]
        if cross2(a, b, m) < -REL_EPS * (abs(a[0]) + abs(a[1]) + abs(b[0]) + abs(b[1])):
            return False
    return True


class BaselineExperiment(ro.Experiment):
    """The oracle's experiment; each rule's result gains (illuminant error,
    reproduction error, true map in F)."""

    def scene_extras(self, poly, truth, maps, out):
        c = self.canon
        inside = contains(poly, truth)
        for rule, m in maps.items():
            if m[0] > 0 and m[1] > 0:
                ill = angle3((c[0] / m[0], c[1] / m[1], c[2]),
                             (c[0] / truth[0], c[1] / truth[1], c[2]))
                rep = angle3((m[0] / truth[0], m[1] / truth[1], 1.0), (1.0, 1.0, 1.0))
            else:
                ill = rep = float("nan")
            out[rule] += (ill, rep, inside)


if __name__ == "__main__":
    sys.exit(ro.main(experiment=BaselineExperiment, doc=__doc__))
