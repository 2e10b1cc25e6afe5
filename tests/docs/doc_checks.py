"""What the documentation checks share: their arguments, the tracked files they read, and how a
check reports what it found.

A check script imports it from its own folder (python3 puts the script's folder on sys.path).
"""
import argparse
import os
import subprocess

REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def arguments():
    """--root DIR (default: this repository) and --self-test, parsed."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", default=REPOSITORY)
    ap.add_argument("--self-test", action="store_true")
    return ap.parse_args()


def tracked_texts(root, keep):
    """{path: text} of the files git tracks under `root` whose path `keep` accepts."""
    listed = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True, check=True)
    texts = {}
    for path in listed.stdout.split("\n"):
        if path and keep(path):
            with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                texts[path] = f.read()
    return texts


def report(problems, failed, passed):
    """Print each problem, then `failed` (if any) or `passed`: the exit status, 1 iff any."""
    for p in problems:
        print(p)
    print(failed if problems else passed)
    return 1 if problems else 0
