#!/usr/bin/env python3
"""The repository's citations of its own documentation must resolve, inside the repository.

    check_citations.py [--root DIR]     check the tracked files of DIR (default: this repository)
    check_citations.py --self-test      check a made-up tree with known good and bad citations

Exit status 0 when every citation resolves, 1 with one line per problem (FILE:LINE: problem).

Files scanned: the tracked files (`git ls-files`; without git, every file under DIR but build*/
and .git/) whose names end in .cpp .h .hpp .c .py .md .in .txt .cmake .dict .sh .cff .gp, or
that lie in scripts/. The fuzzers' inputs (fuzz/corpus/, fuzz/findings/) are data, not text,
and this script's own examples are skipped.

What is checked:

A citation may wrap onto the next line (of the same comment: the next line's `//`, `///`, `#` or
`*` is skipped).

1. Section citations `docs/<page>.md §<x>` (also `<page>.md §<x>` without the folder, and
   `[<page>.md](<link>) §<x>`; a list `docs/math.md §1a, §1b and §3` cites each). A page named
   without a folder, or under docs/, is docs/<page>.md; `fuzz/README.md §x` is that file. The page
   must exist and hold a heading (any level, `#` lines outside ``` fences) whose *number* is x
   exactly. A heading's number is its first word when that word starts with a digit (after an
   optional `§`), less one trailing full stop:
       "## 2. Selection rules"      number 2
       "### 1a′. The certified route" number 1a′
       "## 1b. Forsyth's CRULE"     number 1b
       "### 4.3 Shallow constructions" number 4.3
   so §2 matches "## 2. …" only, not "### 2.1 …" and not "## 1b …".
2. Heading citations `docs/<page>.md "<heading>"` (a comma may come between; the quotes may be
   escaped, \\"…\\", inside a C++ string). The quoted text must equal a heading of that page,
   compared after removing backticks, the heading's number (as above) and collapsing white space;
   a trailing parenthesis of the heading may be left out: "JSON output" cites
   "JSON output (`--json`)".
3. Markdown links `[text](target)` in .md and .md.in files: a relative target must exist (a
   docs/src/*.md.in template is read as if it were in docs/, where it is generated), and an
   anchor `#a` must be the GitHub anchor of one of that page's headings (lower case; characters
   other than letters, digits, `-`, `_` and spaces removed; spaces become `-`).
4. No citation of documents outside the repository: the background notes SPEC, MATH,
   ARCHITECTURE and STYLE (as words in capitals, with or without .md) and `../shared` or
   `/work/shared` paths. A clone must stand alone.
"""

import os
import re
import subprocess
import sys
import tempfile

from doc_checks import report

TEXT_SUFFIXES = (".cpp", ".h", ".hpp", ".c", ".py", ".md", ".in", ".txt", ".cmake", ".dict",
                 ".sh", ".cff", ".gp")
DATA_FOLDERS = ("fuzz/corpus/", "fuzz/findings/")
SELF = "tests/docs/check_citations.py"  # its examples and planted mistakes are not citations

# Built from pieces so that this file does not cite what it forbids.
_OUTSIDE_NAMES = "|".join(["SP" + "EC", "MA" + "TH", "ARCHI" + "TECTURE", "ST" + "YLE"])
FORBIDDEN = [
    (re.compile(r"(?<![\w/])(?:" + _OUTSIDE_NAMES + r")(?:\.md)?\b(?!_)"),
     "cites a background document that is not in the repository"),
    (re.compile(r"\.\./" + "shared" + r"\b|/work/" + "shared" + r"\b"),
     "cites a path outside the repository"),
]

# `docs/math.md §1a, §1b and §3` (the page part: optional folders, then name.md; optionally the
# closing `](link)` of a Markdown link whose text ends in the page's name).
PAGE = r"((?:[\w.-]+/)*)([\w-]+)\.md(?:\]\([^)\s]*\))?"
SECTION_CITE = re.compile(PAGE + r"((?:\s*(?:,|and|or|/)?\s*§\s?[0-9][\w.′]*)+)")
SECTION_NUMBER = re.compile(r"§\s?([0-9][\w.′]*)")
HEADING_CITE = re.compile(PAGE + r",?\s+\\?\"([^\"\\\n]*)(\\?\")?")
LINK = re.compile(r"\[[^\]\n]*\]\(([^)\s]+)\)")
COMMENT_PREFIX = re.compile(r"^\s*(?://+|#+|\*+|/\*+)?\s*")


def strip_number(x):
    return x[:-1] if x.endswith(".") else x


def heading_number(text):
    words = text.split()
    if not words:
        return None
    w = words[0][1:] if words[0].startswith("§") else words[0]
    return strip_number(w) if w[:1].isdigit() else None


def normalise(text):
    return " ".join(text.replace("`", "").split())


def heading_names(text):
    """The names a heading can be cited by: its text without its number, and without a trailing
    parenthesis."""
    words = text.split()
    if words and heading_number(text) is not None:
        words = words[1:]
    name = normalise(" ".join(words))
    names = {name, normalise(text)}
    m = re.match(r"^(.*\S)\s*\([^()]*\)$", name)
    if m:
        names.add(m.group(1))
    return names


def github_anchor(text):
    s = text.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


class Page:
    def __init__(self, path):
        self.headings = []
        fenced = False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.lstrip().startswith("```"):
                    fenced = not fenced
                    continue
                m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
                if m and not fenced:
                    self.headings.append(m.group(2))
        self.numbers = {heading_number(h) for h in self.headings} - {None}
        self.names = set().union(*(heading_names(h) for h in self.headings)) if self.headings else set()
        self.anchors = set()
        seen = {}
        for h in self.headings:
            a = github_anchor(h)
            n = seen.get(a, 0)
            seen[a] = n + 1
            self.anchors.add(a if n == 0 else f"{a}-{n}")


class Checker:
    def __init__(self, root):
        self.root = os.path.abspath(root)
        self.pages = {}
        self.problems = []
        self.citations = 0

    def page(self, rel):
        if rel not in self.pages:
            path = os.path.join(self.root, rel)
            self.pages[rel] = Page(path) if os.path.isfile(path) else None
        return self.pages[rel]

    def files(self):
        names = None
        if os.path.exists(os.path.join(self.root, ".git")):
            try:
                out = subprocess.run(["git", "-C", self.root, "ls-files", "-z"], check=True,
                                     capture_output=True).stdout
                names = [n for n in out.decode().split("\0") if n]
            except (OSError, subprocess.CalledProcessError):
                names = None
        if names is None:
            names = []
            for d, subdirs, files in os.walk(self.root):
                subdirs[:] = [s for s in subdirs if s != ".git" and not s.startswith("build")]
                names += [os.path.relpath(os.path.join(d, f), self.root) for f in files]
        for n in sorted(names):
            n = n.replace(os.sep, "/")
            if n.startswith(DATA_FOLDERS) or n == SELF:
                continue
            if n.endswith(TEXT_SUFFIXES) or n.startswith("scripts/"):
                if os.path.isfile(os.path.join(self.root, n)):
                    yield n

    def report(self, where, what):
        self.problems.append(f"{where}: {what}")

    @staticmethod
    def page_path(folders, name):
        folders = folders.rstrip("/")
        if folders in ("", "docs", "../docs", "../../docs"):
            return f"docs/{name}.md"
        return f"{folders}/{name}.md"

    def check_file(self, rel):
        try:
            with open(os.path.join(self.root, rel), encoding="utf-8") as f:
                lines = f.read().split("\n")
        except UnicodeDecodeError:
            return
        markdown = rel.endswith((".md", ".md.in"))
        for i, line in enumerate(lines):
            where = f"{rel}:{i + 1}"
            for pattern, why in FORBIDDEN:
                for m in pattern.finditer(line):
                    self.report(where, f"{why}: {m.group(0)!r}")
            # A citation may wrap onto the next line of the same comment or paragraph.
            joined = line
            if i + 1 < len(lines):
                joined = line + " " + COMMENT_PREFIX.sub("", lines[i + 1], count=1)
            for m in SECTION_CITE.finditer(joined):
                if m.start() >= len(line):
                    break
                target = self.page_path(m.group(1), m.group(2))
                page = self.page(target)
                for x in SECTION_NUMBER.findall(m.group(3)):
                    self.citations += 1
                    x = strip_number(x)
                    if page is None:
                        self.report(where, f"cites {target} §{x}: no such page")
                    elif x not in page.numbers:
                        self.report(where, f"cites {target} §{x}: no heading numbered {x} "
                                           f"(numbers: {', '.join(sorted(page.numbers)) or 'none'})")
            for m in HEADING_CITE.finditer(joined):
                if m.start() >= len(line):
                    break
                if not m.group(4):
                    continue
                self.citations += 1
                target = self.page_path(m.group(1), m.group(2))
                page = self.page(target)
                quoted = normalise(m.group(3))
                if page is None:
                    self.report(where, f"cites {target} \"{quoted}\": no such page")
                elif quoted not in page.names:
                    self.report(where, f"cites {target} \"{quoted}\": no such heading")
            if markdown:
                self.check_links(rel, where, line)

    def check_links(self, rel, where, line):
        for m in LINK.finditer(line):
            target = m.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # https:, mailto:
                continue
            self.citations += 1
            path, _, anchor = target.partition("#")
            base = os.path.dirname(rel)
            if rel.startswith("docs/src/") and rel.endswith(".in"):
                base = "docs"  # generated into docs/
            dest = os.path.normpath(os.path.join(base, path)) if path else rel
            if dest.endswith(".in") and not path:
                dest = "docs/" + os.path.basename(dest)[:-3]
            if dest.startswith(".."):
                self.report(where, f"links to {target}: outside the repository")
                continue
            if not os.path.exists(os.path.join(self.root, dest)):
                self.report(where, f"links to {target}: {dest} does not exist")
                continue
            if anchor and dest.endswith(".md"):
                page = self.page(dest)
                if page is not None and anchor not in page.anchors:
                    self.report(where, f"links to {target}: {dest} has no heading with anchor #{anchor}")

    def run(self):
        for rel in self.files():
            self.check_file(rel)
        return self.problems


SELF_TEST_FILES = {
    "docs/math.md": "# Maths\n\n## 1. One\n### 1a′. Prime\n## 1b. Bee\n### 2.1 Two one\n"
                    "## Plain heading (`--json`)\n```\n## 9. In a fence\n```\n",
    "docs/cli.md": "# CLI\n\n## `gmcc select`\n### Input files\n"
                   "See [math](math.md#1-one) and [bad](math.md#nowhere), [gone](gone.md).\n",
    "src/good.cpp": "// docs/math.md §1, §1a′ and §1b; docs/math.md §2.1.\n"
                    "// docs/cli.md \"gmcc select\", docs/cli.md, \"Input files\"\n"
                    "// docs/math.md \"Plain heading\" and docs/math.md \"Plain\n"
                    "// heading (--json)\"\n"
                    "x = \"see docs/cli.md, \\\"Input files\\\"\";\n"
                    "// wrapped: docs/math.md\n// §1b, and docs/cli.md\n// \"Input files\".\n",
    "src/bad.cpp": "// docs/math.md §2\n"                 # 2 is not a heading's number
                   "// docs/math.md §1, §9\n"             # 9 only inside a fence
                   "// docs/nothing.md §1\n"              # no page
                   "// docs/cli.md \"Output files\"\n"    # no heading
                   "// see " + "SP" + "EC §5 and " + "MA" + "TH 1a.7\n"
                   "// ../" + "shared/docs/x\n"
                   "// wrapped: docs/math.md\n"
                   "// §7 and docs/cli.md\n"           # 7 is no heading's number
                   "// \"Output files\".\n",
    "scripts/tool": "# " + "ARCHI" + "TECTURE.md explains\n",
    "build/ignored.cpp": "// " + "SP" + "EC §1\n",
}
SELF_TEST_EXPECTED = [
    "docs/cli.md:5: links to math.md#nowhere",
    "docs/cli.md:5: links to gone.md",
    "scripts/tool:1: cites a background document",
    "src/bad.cpp:1: cites docs/math.md §2: no heading numbered 2",
    "src/bad.cpp:2: cites docs/math.md §9: no heading numbered 9",
    "src/bad.cpp:3: cites docs/nothing.md §1: no such page",
    "src/bad.cpp:4: cites docs/cli.md \"Output files\": no such heading",
    "src/bad.cpp:5: cites a background document",
    "src/bad.cpp:5: cites a background document",
    "src/bad.cpp:6: cites a path outside the repository",
    "src/bad.cpp:7: cites docs/math.md §7: no heading numbered 7",
    "src/bad.cpp:8: cites docs/cli.md \"Output files\": no such heading",
]


def self_test():
    """The checker on a made-up tree: it must pass the good citations and report exactly the
    bad ones."""
    with tempfile.TemporaryDirectory() as root:
        for rel, text in SELF_TEST_FILES.items():
            path = os.path.join(root, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        problems = sorted(Checker(root).run())
    expected = sorted(SELF_TEST_EXPECTED)
    ok = len(problems) == len(expected) and all(
        p.startswith(e) for p, e in zip(problems, expected))
    if not ok:
        print("self-test FAILED\nreported:", *problems, "expected (prefixes):", *expected,
              sep="\n  ")
        return 1
    print(f"self-test passed: {len(problems)} planted problems reported, no false alarm")
    return 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    root = argv[argv.index("--root") + 1] if "--root" in argv else \
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    checker = Checker(root)
    problems = checker.run()
    return report(problems, f"{len(problems)} problem(s) in {checker.citations} citations and links",
                  f"{checker.citations} citations and links resolve; none outside the repository")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
