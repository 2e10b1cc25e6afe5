"""The harness the command-line tests share: a runner of the gmcc binary with a folder for the
files a case writes, named checks that report every failure and go on, and `expect`.

A test script imports it from its own folder (python3 puts the script's folder on sys.path);
importing it puts the tests' shared helpers (tests/support: png16, dng, ...) on the path too.
"""

import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "support"))


def random_triples(rng, n, lo, hi):
    """n triples (r, g, b) of integers from [lo, hi], drawn in that order from random.Random rng."""
    return [(rng.randint(lo, hi), rng.randint(lo, hi), rng.randint(lo, hi)) for _ in range(n)]


class Runner:
    """Runs `binary *prefix *args`; `prefix` is the subcommand a script always uses, if any."""

    def __init__(self, binary, tmp, prefix=(), timeout=120):
        self.binary, self.tmp, self.prefix, self.timeout = binary, tmp, list(prefix), timeout
        self.passed, self.failed, self.n = 0, 0, 0

    def file(self, text):
        self.n += 1
        path = os.path.join(self.tmp, f"f{self.n}.csv")
        with open(path, "w") as f:
            f.write(text)
        return path

    def run(self, *args, timeout=None, prefix=None):
        """Exit status, stdout and stderr; `prefix` replaces the script's subcommand."""
        first = self.prefix if prefix is None else list(prefix)
        p = subprocess.run([self.binary, *first, *args], capture_output=True, text=True,
                           timeout=timeout or self.timeout)
        return p.returncode, p.stdout, p.stderr

    def json(self, *args):
        rc, out, err = self.run(*args, "--json")
        if rc != 0:
            raise AssertionError(f"exit {rc}: {err.strip()}")
        return json.loads(out)

    def check(self, name, fn):
        try:
            fn()
            self.passed += 1
        except Exception as e:  # noqa: BLE001 - report every failure and go on
            self.failed += 1
            print(f"FAIL {name}: {e!r}")

    def check_all(self, *fns):
        """`check` each function under its own name, in order."""
        for fn in fns:
            self.check(fn.__name__, fn)

    def finish(self):
        """Print the closing line `N passed, M failed` that ctest's log shows; the exit status."""
        print(f"{self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0


class Tally:
    """Counts checks that report every failure and go on; `finish` prints the closing line
    `N passed, M failed` that ctest's log shows and returns the exit status."""

    def __init__(self):
        self.passed = self.failed = 0

    def check(self, ok, what, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print(f"FAIL: {what}" + (f"\n  {detail}" if detail else ""))

    def finish(self):
        print(f"{self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0


def memory_limit(binary, mib):
    """`--memory-limit MIB` for `binary`, or nothing under AddressSanitizer: its shadow memory alone
    is terabytes of address space, so RLIMIT_AS makes its own allocator fail first. (What such a
    test checks, a refusal before anything is allocated, holds without the limit too.)"""
    with open(binary, "rb") as f:
        if b"__asan_init" in f.read():
            return []
    return ["--memory-limit", str(mib)]


def angle(u, v):
    """The angle in degrees between two 3-vectors (atan2 of |u×v| and u·v), in floats."""
    import math
    dot = sum(a * b for a, b in zip(u, v))
    cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return math.degrees(math.atan2(math.sqrt(sum(c * c for c in cross)), dot))


def expect(cond, what):
    if not cond:
        raise AssertionError(what)
