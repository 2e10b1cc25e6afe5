#!/usr/bin/env python3
"""README.md's example is the binary's own output: the `sh` block holding a `gmcc …` command is
run (from the repository's root, with this build's binary) and its output must equal the plain
block that follows, byte for byte. `--write` puts the binary's output in place instead.

    check_readme_example.py GMCC_BINARY --root DIR [--write]
"""

import argparse
import re
import shlex
import subprocess
import sys

BLOCK = re.compile(r"```sh\n(gmcc [^\n]+)\n```\n\n```\n(.*?)```\n", re.S)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--root", required=True)
    ap.add_argument("--write", action="store_true")
    a = ap.parse_args()
    path = f"{a.root}/README.md"
    text = open(path, encoding="utf-8").read()
    found = list(BLOCK.finditer(text))
    if not found:
        print("FAIL: README.md has no ```sh gmcc …``` block followed by its output")
        return 1
    failed, out = 0, text
    for m in reversed(found):
        args = shlex.split(m.group(1))[1:]
        run = subprocess.run([a.binary, *args], cwd=a.root, capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            print(f"FAIL: `{m.group(1)}` exited {run.returncode}: {run.stderr.strip()}")
            failed += 1
            continue
        if run.stdout != m.group(2):
            if a.write:
                out = out[:m.start(2)] + run.stdout + out[m.end(2):]
            else:
                print(f"FAIL: README.md's output of `{m.group(1)}` is not the binary's:\n"
                      f"--- README\n{m.group(2)}--- binary\n{run.stdout}")
                failed += 1
    if a.write and out != text:
        open(path, "w", encoding="utf-8").write(out)
    print(f"{len(found) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
