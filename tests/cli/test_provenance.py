#!/usr/bin/env python3
"""Provenance (docs/cli.md "Provenance"): every JSON document and CSV records the gmcc version,
the git commit of the build, the command, its content-determining options and the SHA-256 of
every input file; `gmcc --version` and `gmcc cite` name version and commit; CITATION.cff and the
README carry the version CMakeLists.txt declares.

The checks use routes independent of gmcc: the version from CMakeLists.txt, the commit from
`git rev-parse HEAD` on the source tree, the checksums from Python's hashlib.

    test_provenance.py GMCC_BINARY
"""

import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_harness import Runner, expect  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SAMPLES = os.path.join(ROOT, "data", "samples")
CANONICAL = os.path.join(SAMPLES, "canonical_munsell_D55.csv")
IMAGE = os.path.join(SAMPLES, "image_munsell_D75.csv")


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(gmcc VERSION (\d+\.\d+\.\d+)", f.read()).group(1)


def source_commit():
    """HEAD of the source tree, or None outside a git checkout."""
    try:
        p = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True,
                           text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    # .git is a directory in a clone and a file in a `git worktree` checkout.
    return p.stdout.strip() if p.returncode == 0 and os.path.exists(os.path.join(ROOT, ".git")) else None


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def check_record(p, command, version, commit):
    expect(p["software"] == "gmcc", f"software {p['software']!r}")
    expect(p["version"] == version, f"version {p['version']!r}, CMakeLists.txt says {version}")
    expect(p["commit"] == commit, f"commit {p['commit']!r}, --version says {commit!r}")
    expect(p["command"] == command, f"command {p['command']!r}, expected {command!r}")
    expect(isinstance(p["options"], dict), "options is an object")
    for name in ("--csv", "--plot", "--scenes-out", "--shard", "--time-limit", "--memory-limit"):
        expect(name not in p["options"], f"{name} (an output destination or limit) is recorded")
    for f in p["inputs"]:
        expect(f["sha256"] == sha256(f["path"]), f"{f['path']}: sha256 differs from hashlib's")
        expect(f["bytes"] == os.path.getsize(f["path"]), f"{f['path']}: size differs")


def csv_record(path):
    with open(path, encoding="utf-8") as f:
        first = f.readline()
    expect(first.startswith("# gmcc-provenance: "), f"{path}: first line {first[:40]!r}")
    return json.loads(first[len("# gmcc-provenance: "):])


def main():
    binary = sys.argv[1]
    version = project_version()
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(binary, tmp)
        rc, out, _ = r.run("--version")
        m = re.fullmatch(r"gmcc (\S+) \(commit (\S+), (\S+)\)\n", out)
        commit = m.group(2) if m else None

        def version_line():
            expect(rc == 0 and m, f"--version printed {out!r}")
            expect(m.group(1) == version, f"--version says {m.group(1)}, CMakeLists.txt {version}")
            head = source_commit()
            if head is None:
                expect(commit == "unknown", f"outside a checkout the commit is {commit!r}")
            else:
                expect(commit in (head, head + "-dirty"), f"commit {commit}, HEAD is {head}")
                expect(re.fullmatch(r"\d{4}-\d\d-\d\d", m.group(3)), f"date {m.group(3)!r}")

        def cite():
            rc, out, _ = r.run("cite")
            expect(rc == 0, f"cite exit {rc}")
            expect("@software{gmcc," in out and "@article{Finlayson1999Selection," in out,
                   "both entries")
            expect(f"version = {{{version}}}" in out, "the version")
            expect(f"git commit {commit}" in out, "the commit")

        def citation_files():
            with open(os.path.join(ROOT, "CITATION.cff"), encoding="utf-8") as f:
                cff = f.read()
            expect(re.search(rf"^version: {re.escape(version)}$", cff, re.M),
                   f"CITATION.cff's version is not {version}")
            with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
                readme = f.read()
            expect(f"version = {{{version}}}" in readme, f"README's BibTeX lacks version {version}")
            expect("gmcc cite" in readme, "README says how to cite a specific build")

        def accuracy_csv():
            path = os.path.join(tmp, "accuracy.csv")
            rc, _, err = r.run("accuracy", "--max-samples", "100", "--seed", "7", "--csv", path,
                               timeout=600)
            expect(rc == 0, f"accuracy exit {rc}: {err}")
            p = csv_record(path)
            check_record(p, "accuracy", version, commit)
            expect(p["options"].get("--seed") == "7", f"seed recorded as {p['options']}")
            expect(p["options"].get("--max-samples") == "100", f"options {p['options']}")

        def select_json():
            rc, out, err = r.run("select", "--canonical", CANONICAL, "--image", IMAGE, "--json",
                                 "--canonical-illuminant", "1,1,1")
            expect(rc == 0, f"select exit {rc}: {err}")
            doc = json.loads(out)
            expect(next(iter(doc)) == "provenance", "provenance is the first member")
            p = doc["provenance"]
            check_record(p, "select", version, commit)
            expect([f["path"] for f in p["inputs"]] == [CANONICAL, IMAGE], f"inputs {p['inputs']}")
            expect(p["options"]["--canonical"] == CANONICAL and "--json" not in p["options"],
                   f"options {p['options']}")
            expect(p["options"]["--mean3d"] == "analytic", "defaults are recorded")

        def select_batch_jsonl():
            scenes = os.path.join(tmp, "scenes.jsonl")
            with open(scenes, "w") as f:
                f.write('{"id":"a","colours":[[0.2,0.3,0.5],[0.4,0.3,0.3]]}\n')
            rc, out, err = r.run("select", "--canonical", CANONICAL, "--images", scenes,
                                 "--canonical-illuminant", "1,1,1")
            expect(rc == 0, f"select --images exit {rc}: {err}")
            first = json.loads(out.splitlines()[0])
            expect(list(first) == ["provenance"], f"first line {list(first)}")
            check_record(first["provenance"], "select", version, commit)
            expect(first["provenance"]["inputs"][-1]["path"] == scenes, "the scene file's digest")

        r.check_all(version_line, select_json, select_batch_jsonl, cite, citation_files, accuracy_csv)
        return r.finish()


if __name__ == "__main__":
    sys.exit(main())
