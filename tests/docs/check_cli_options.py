#!/usr/bin/env python3
"""docs/cli.md documents exactly the options `gmcc --help` lists, command by command.

    check_cli_options.py GMCC_BINARY [--doc docs/cli.md]
    check_cli_options.py --self-test

Exit status 0 when they agree, 1 with one line per difference.

The commands are found from the binary: `gmcc --help`, then `gmcc CMD --help` for every name
under "Subcommands:", recursively (`gmcc reproduce synthetic --help`, …). A command's options are
the long names (`--name`) in the first column of its "Options:" list; `--help` is left out.

Where docs/cli.md lists a command's options:
* its section: the `## ` section whose heading starts with `` `gmcc CMD` `` for the first word
  of the command (`` ## `gmcc cite` and `gmcc --version` `` is cite's), with its `###`
  subsections; for `gmcc` itself, the text above the first `## `;
* synopsis lines in that section's ``` blocks: a line `gmcc CMD SUB … [--opt …]` lists its
  options for the command `CMD SUB` (as many leading words as name commands), and so do the
  indented lines that continue it; a line for a command of another section is left to that one;
* option tables in that section: rows whose first cell starts with `` `--``; every `--name` in
  the first cell is listed. If the table has a column headed `commands`, a row applies to the
  commands named in it by their last word (`all`: every command of the section that has no
  subcommands), else to every command of the section that has no subcommands.

Checks, per command: every option of its --help is listed for it (in a synopsis line or a table
row that applies to it); every option a synopsis line or an applicable table row lists exists in
its --help; every command has a section. So a new option needs its row (or synopsis entry) and a
new command its `## \\`gmcc CMD\\`` section; nothing in this script changes.
"""

import os
import re
import subprocess
import sys
import tempfile

from doc_checks import report

OPTION = re.compile(r"--[a-z0-9][a-z0-9-]*")


def help_text(binary, path):
    p = subprocess.run([binary, *path, "--help"], capture_output=True, text=True, timeout=60)
    if p.returncode != 0:
        raise RuntimeError(f"`gmcc {' '.join(path)} --help` exited {p.returncode}: {p.stderr}")
    return p.stdout


def parse_help(text):
    """(options, subcommands) of one --help page."""
    options, subs, part = set(), [], None
    for line in text.splitlines():
        if re.match(r"^[A-Z][\w ]*:\s*$", line):
            part = line.strip()[:-1]
            continue
        if part == "Options" and re.match(r"^  -", line):
            first = re.split(r"\s{2,}", line.strip())[0]
            options.update(o for o in OPTION.findall(first) if o != "--help")
        elif part == "Subcommands":
            m = re.match(r"^  ([a-z][\w-]*)(\s{2,}|$)", line)
            if m:
                subs.append(m.group(1))
    return options, subs


def commands(binary):
    """{command path (tuple): (options, has subcommands)} for the whole tree."""
    tree, todo = {}, [()]
    while todo:
        path = todo.pop(0)
        options, subs = parse_help(help_text(binary, path))
        tree[path] = (options, bool(subs))
        todo += [path + (s,) for s in subs]
    return tree


def sections(doc):
    """{first command word or '': lines of its section}."""
    out, key = {"": []}, ""
    for line in doc.splitlines():
        m = re.match(r"^##\s+(.*)$", line)
        if m and not line.startswith("###"):
            h = re.match(r"^`gmcc ([a-z][\w-]*)`", m.group(1).strip())
            key = h.group(1) if h else None
            if key is not None:
                out[key] = []
            continue
        if key is not None:
            out[key].append(line)
    return out


def listed(lines, tree, first):
    """{command path: set of options listed for it} in one section."""
    in_section = [p for p in tree if p[:1] == (first,)] if first else [()]
    leaves = [p for p in in_section if not tree[p][1]] or in_section
    names = {w for p in tree for w in p}
    found = {p: set() for p in in_section}
    fenced, current, header = False, None, None
    for line in lines:
        if line.lstrip().startswith("```"):
            fenced, current = not fenced, None
            continue
        if fenced:
            words = line.split()
            if words[:1] == ["gmcc"]:
                path = []
                for w in words[1:]:
                    if w in names and tuple(path + [w]) in tree:
                        path.append(w)
                    else:
                        break
                current = tuple(path)
                if current not in found:  # another section's command: listed there
                    current = None
            elif not line[:1].isspace():
                current = None
            if current is not None:
                found[current].update(OPTION.findall(line))
            continue
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not cells[0].startswith("`--"):
                if cells and not set(cells[0]) <= set("-: "):
                    header = [c.lower() for c in cells]
                continue
            opts = set(OPTION.findall(cells[0]))
            targets = leaves
            if header and "commands" in header:
                named = cells[header.index("commands")].replace("`", "").replace(",", " ").split()
                if "all" not in named:
                    targets = [p for p in in_section if p and p[-1] in named]
            for p in targets:
                found[p].update(opts)
        else:
            header = None if not line.strip() else header
    return found


def check(tree, doc):
    problems = []
    secs = sections(doc)
    by_first = {}
    for p in tree:
        by_first.setdefault(p[0] if p else "", []).append(p)
    for first in sorted(by_first):
        if first not in secs:
            problems.append(f"gmcc {first}: no section headed `gmcc {first}` in docs/cli.md")
            continue
        found = listed(secs[first], tree, first)
        for p in sorted(found):
            name = " ".join(("gmcc",) + p)
            if p not in tree:
                continue
            options, has_subs = tree[p]
            for o in sorted(options - found[p]):
                problems.append(f"{name}: {o} is in --help but not listed in docs/cli.md")
            for o in sorted(found[p] - options):
                problems.append(f"{name}: docs/cli.md lists {o}, which --help does not have")
    return problems


SELF_TEST_HELP = {
    (): "Options:\n  -h,--help  help\n  --time-limit S  t\n\nSubcommands:\n  run  r\n  exp  e\n",
    ("run",): "Options:\n  -h,--help  help\n  --a TEXT  a\n  --b-opt TEXT:{x,y}=x\n      wrapped\n",
    ("exp",): "Options:\n  -h,--help\n\nSubcommands:\n  one  1\n  two  2\n",
    ("exp", "one"): "Options:\n  --c N=1  c\n  --d  d\n",
    ("exp", "two"): "Options:\n  --c N=1  c\n",
}
SELF_TEST_DOC = """# gmcc
```
gmcc [--time-limit S] COMMAND
```
## `gmcc run`
```
gmcc run --a X [--b-opt x|y] [--gone]
```
## `gmcc exp` and more words
```
gmcc --time-limit S exp one
gmcc exp one [--c N]
gmcc exp two [--c N]
```
| option | commands | meaning |
|---|---|---|
| `--c N` | all | c, for both leaves, not for `gmcc exp` |
| `--d` | one | d |
| `--zz` | two | not in two's help |
"""
SELF_TEST_EXPECTED = [
    "gmcc exp two: docs/cli.md lists --zz, which --help does not have",
    "gmcc run: docs/cli.md lists --gone, which --help does not have",
]


def self_test():
    """Made-up help pages and doc: the good listings pass, the two planted mistakes are reported,
    and a new undocumented option and a missing section are caught."""
    tree = {p: (parse_help(t)[0], bool(parse_help(t)[1])) for p, t in SELF_TEST_HELP.items()}
    ok = True
    got = check(tree, SELF_TEST_DOC)
    if got != SELF_TEST_EXPECTED:
        print("self-test FAILED: planted mistakes", *got, sep="\n  ")
        ok = False
    tree2 = dict(tree)
    tree2[("run",)] = (tree[("run",)][0] | {"--new"}, False)
    tree2[("merge",)] = (set(), False)
    got2 = check(tree2, SELF_TEST_DOC)
    want2 = ["gmcc merge: no section headed `gmcc merge` in docs/cli.md",
             "gmcc run: --new is in --help but not listed in docs/cli.md"]
    if not all(w in got2 for w in want2):
        print("self-test FAILED: new option or command", *got2, sep="\n  ")
        ok = False
    if ok:
        print(f"self-test passed: {len(got) + len(want2)} planted differences reported")
    return 0 if ok else 1


def main(argv):
    if "--self-test" in argv:
        return self_test()
    if not argv:
        print(__doc__)
        return 2
    doc_path = argv[argv.index("--doc") + 1] if "--doc" in argv else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "cli.md")
    tree = commands(argv[0])
    with open(doc_path, encoding="utf-8") as f:
        problems = check(tree, f.read())
    n = sum(len(o) for o, _ in tree.values())
    return report(problems, f"{len(problems)} difference(s) between --help and docs/cli.md",
                  f"{len(tree)} commands, {n} options: docs/cli.md and --help agree")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
