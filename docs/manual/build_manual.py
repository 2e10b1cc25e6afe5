#!/usr/bin/env python3
"""Build gmcc's HTML manual with Doxygen: the API reference of the public headers and the pages
of docs/ as manual pages, with a front page (docs/manual/mainpage.md).

    build_manual.py --source DIR --out DIR [--version X.Y.Z] [--doxygen PATH]

Writes OUT/html/index.html. Exit status 0 when Doxygen ran without a single warning; 1 with
the warnings printed otherwise (undocumented members, broken references, unknown commands).

The docs pages are GitHub-flavoured Markdown and stay so: this script copies them into
OUT/pages/ and rewrites what Doxygen would not resolve the way GitHub does, leaving the
originals alone:
  - every heading gets an explicit label, `{#docs_<page>_<github anchor>}` (the page title:
    `{#docs_<page>}`), so a link `page.md#anchor` becomes `@ref` to that label;
  - links to other pages of docs/ (and to public headers) become `@ref` links; links to data
    files beside the pages (CSV, SVG, BibTeX) point at their copies in OUT/html/files/; images
    `figures/x.png` are found through IMAGE_PATH; links to other files of the repository
    (tests, fuzz/) become their repository path in code, since the manual does not carry them;
  - `docs/<page>.md §n` and `docs/<page>.md "heading"` citations in the text, and public header
    names in code spans, become links too. The same filter (--filter FILE) runs on the headers
    (Doxygen's INPUT_FILTER), so an API page's `docs/math.md §2` is a link into the manual.
  - `\\word` and `@word` in prose are escaped (GitHub shows them as text, Doxygen would read
    commands); a table's code span with an escaped pipe is split around it; headings never skip
    a level and lose their backticks (Doxygen would print `<tt>`); a comment before a page's
    title goes;
  - the version and git commit of the checkout are written into the front page's
    `<!-- gmcc:build-info -->` line, as `gmcc cite` prints them (cmake/build_info.cmake's rule),
    the BibTeX between `<!-- gmcc:cite-begin -->` and `<!-- gmcc:cite-end -->` becomes what
    `gmcc cite` prints for that version and commit (--gmcc PATH checks that it does), and
    `<!-- gmcc:all-pages -->` becomes a list of every page of docs/ (a page added later,
    e.g. docs/python.md, is in the manual without an edit here).
In the headers (the filter) an abbreviation's full stop (`eqs. 7`, `e.g. the`) is written
`.\\ ` so that it does not end the brief description (JAVADOC_AUTOBRIEF).
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PUBLIC_INCLUDE = ["numerics/include", "geometry/include", "selection/include", "input/include", "photo/include",
                  "validation/include"]

FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
# Link text and code spans may wrap onto the next line of their paragraph, never past it.
LINK = re.compile(r"(!?)\[((?:[^\]\n]|\\\]|\n(?!\s*\n))*)\]\(([^)\s]+)\)")
CODE_SPAN = re.compile(r"(`+)((?:[^`\n]|\n(?!\s*\n))+?)\1")
# `docs/math.md §1b, §2 and §3` and `docs/cli.md "Provenance"` (tests/docs/check_citations.py)
SECTION_CITE = re.compile(r"(?<![\w/\[])((?:docs/)?([\w-]+)\.md)((?:\s*(?:,|and|or|/)?\s*§\s?[0-9][\w.′]*)+)")
SECTION_NUMBER = re.compile(r"§\s?([0-9][\w.′]*?)(?=[.]?(?:[^\w.′]|$))")
HEADING_CITE = re.compile(r"(?<![\w/\[])((?:docs/)?([\w-]+)\.md),?(\s+)\"([^\"\n]*)\"")


def leading_comment(lines):
    """How many of lines are blank lines and HTML comments before anything else."""
    n = 0
    while n < len(lines):
        if not lines[n].strip():
            n += 1
        elif lines[n].lstrip().startswith("<!--"):
            while n < len(lines) and "-->" not in lines[n]:
                n += 1
            n += 1
        else:
            break
    return min(n, len(lines))


def escape_commands(text):
    """Prose as GitHub shows it: `\\word` and `@word` are Doxygen commands, not text."""
    text = re.sub(r"\\(?=[A-Za-z])", r"\\\\", text)
    return re.sub(r"@(?=[A-Za-z])", r"\\@", text)


def table_row(line):
    """A table row's code span that holds GitHub's escaped pipe `\\|` split around it, the pipe
    outside the code (`a`\\|`b`): Doxygen would show the backslash inside a code span, and an
    HTML <code> would have its `--` turned into a dash."""
    def span(m):
        if "\\|" not in m.group(2):
            return m.group(0)
        return "\\|".join("`%s`" % p if p else "" for p in m.group(2).split("\\|"))
    return CODE_SPAN.sub(span, line)


def header_link(base, text):
    """A link to a public header's API page (Doxygen resolves a file name)."""
    return "[%s](@ref %s)" % (text, base)


ABBREVIATION = re.compile(r"(?<![\w.])(e\.g|i\.e|eqs?|Eqs?|Figs?|cf|vs|al|resp|approx|ca)\.(?= )")


def github_anchor(text):
    """GitHub's anchor of a heading: lower case, only letters, digits, - and _ and spaces, each
    space a hyphen (the same rule as tests/docs/check_citations.py)."""
    text = re.sub(r"`", "", text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def heading_number(text):
    words = text.split()
    if not words:
        return None
    w = words[0].lstrip("§")
    if not w or not w[0].isdigit():
        return None
    return w[:-1] if w.endswith(".") else w


def normalise(text):
    text = text.replace("`", "")
    words = text.split()
    if words and heading_number(text) is not None:
        words = words[1:]
    return " ".join(words)


def outside_fences(lines):
    """Yield (index, line, in_fence) for each line."""
    fence = None
    for i, line in enumerate(lines):
        m = FENCE.match(line)
        if m:
            if fence is None:
                fence = m.group(1)
                yield i, line, True
                continue
            if line.strip().startswith(fence):
                fence = None
                yield i, line, True
                continue
        yield i, line, fence is not None


class Page:
    """One Markdown page of docs/: its label, and its headings' labels by GitHub anchor, by
    number and by normalised text."""

    def __init__(self, path, label):
        self.path = path
        self.label = label
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().split("\n")
        self.anchors = {}      # github anchor -> label
        self.numbers = {}      # "2", "1a′" -> label
        self.titles = {}       # normalised heading text -> label
        self.heading_labels = {}  # line index -> label
        seen = {}
        first = True
        for i, line, fenced in outside_fences(self.lines):
            m = HEADING.match(line)
            if fenced or not m:
                continue
            text = m.group(2)
            if first and m.group(1) == "#":
                self.heading_labels[i] = label
                first = False
                continue
            first = False
            anchor = github_anchor(text)
            n = seen.get(anchor, 0)
            seen[anchor] = n + 1
            if n:
                anchor = "%s-%d" % (anchor, n)
            lab = label + "_" + re.sub(r"[^A-Za-z0-9_]", "_", anchor)
            while lab in self.heading_labels.values():
                lab += "_"
            self.heading_labels[i] = lab
            self.anchors[anchor] = lab
            num = heading_number(text)
            if num is not None:
                self.numbers.setdefault(num, lab)
            t = normalise(text)
            self.titles.setdefault(t, lab)
            self.titles.setdefault(re.sub(r"\s*\([^()]*\)$", "", t), lab)


class Manual:
    def __init__(self, source):
        self.source = source
        self.pages = {}   # repo-relative path -> Page
        for path in sorted(glob.glob(os.path.join(source, "docs", "*.md"))):
            stem = os.path.splitext(os.path.basename(path))[0]
            label = "docs_" + re.sub(r"[^A-Za-z0-9_]", "_", stem)
            self.pages[os.path.relpath(path, source)] = Page(path, label)
        main = os.path.join(source, "docs", "manual", "mainpage.md")
        self.pages[os.path.relpath(main, source)] = Page(main, "index")
        self.headers = {}  # basename -> repo-relative path
        for inc in PUBLIC_INCLUDE:
            for path in glob.glob(os.path.join(source, inc, "gmcc", "*", "*.h")):
                self.headers[os.path.basename(path)] = os.path.relpath(path, source)
        self.data_files = []  # repo-relative paths copied to html/files/

    # ---- links -------------------------------------------------------------------------
    def page_by_name(self, name):
        return self.pages.get("docs/%s.md" % name)

    def resolve(self, rel_dir, target):
        """The rewritten link target for `target` in a file of folder rel_dir (repo-relative),
        as ('ref', label) | ('file', html path) | ('image', basename) | ('code', repo path) |
        ('keep', target)."""
        if re.match(r"^[a-z]+:", target):
            return ("keep", target)
        path, _, anchor = target.partition("#")
        if not path:
            return ("anchor", anchor)
        rel = os.path.normpath(os.path.join(rel_dir, path))
        if rel in self.pages:
            page = self.pages[rel]
            if anchor:
                if anchor not in page.anchors:
                    raise ValueError("no heading with anchor #%s in %s" % (anchor, rel))
                return ("ref", page.anchors[anchor])
            return ("ref", page.label)
        base = os.path.basename(rel)
        if base in self.headers and self.headers[base] == rel:
            return ("header", base)
        if rel.startswith("docs/") and os.path.isfile(os.path.join(self.source, rel)):
            if rel.endswith(".png") or rel.endswith(".jpg"):
                return ("image", base)
            if rel not in self.data_files:
                self.data_files.append(rel)
            return ("file", "files/" + os.path.relpath(rel, "docs"))
        if os.path.exists(os.path.join(self.source, rel)):
            return ("code", rel)
        raise ValueError("link to %s, which is not in the repository" % target)

    def rewrite_link(self, m, rel_dir, page):
        # Link text that wraps onto the next line: on one line, the line break after the link
        # (Doxygen 1.9.4 loses the page's section structure after a wrapped `@ref` text).
        out = self.rewrite_link_text(m, rel_dir, page, m.group(2).replace("\n", " "))
        return out + "\n" * m.group(2).count("\n")

    def rewrite_link_text(self, m, rel_dir, page, text):
        bang, target = m.group(1), m.group(3)
        kind, value = self.resolve(rel_dir, target)
        if kind == "anchor":
            if value not in page.anchors:
                raise ValueError("no heading with anchor #%s in %s" % (value, page.path))
            kind, value = "ref", page.anchors[value]
        if bang:
            if kind != "image":
                raise ValueError("image %s is not a figure under docs/" % target)
            return "![%s](%s)" % (text, value)
        if kind == "ref":
            return "[%s](@ref %s)" % (text, value)
        if kind == "header":
            return header_link(value, text)
        if kind == "file":
            return '<a href="%s">%s</a>' % (value, text)
        if kind == "image":
            return "<a href=\"%s\">%s</a>" % (value, text)
        if kind == "code":
            return "%s (`%s` in the repository)" % (text, value)
        return m.group(0)

    def cite_links(self, text, doxygen_ref):
        """`docs/math.md §2` and `docs/cli.md "Provenance"` citations as links."""
        def ref(label, shown):
            if doxygen_ref:
                return '\\ref %s "%s"' % (label, shown.replace('"', "'"))
            return "[%s](@ref %s)" % (shown, label)

        def sections(m):
            page = self.page_by_name(m.group(2))
            if page is None:
                return m.group(0)
            out = ref(page.label, m.group(1))
            rest = m.group(3)
            pos = 0
            parts = []
            for s in SECTION_NUMBER.finditer(rest):
                label = page.numbers.get(s.group(1))
                parts.append(rest[pos:s.start()])
                parts.append(ref(label, s.group(0)) if label else s.group(0))
                pos = s.end()
            parts.append(rest[pos:])
            return out + "".join(parts)

        def headings(m):
            page = self.page_by_name(m.group(2))
            if page is None:
                return m.group(0)
            label = page.titles.get(" ".join(m.group(4).split()))
            if label is None:
                return m.group(0)
            shown = ("“%s”" if doxygen_ref else '"%s"') % m.group(4)
            return ref(page.label, m.group(1)) + m.group(3) + ref(label, shown)

        text = SECTION_CITE.sub(sections, text)
        text = HEADING_CITE.sub(headings, text)
        return text

    def header_spans(self, text):
        """`gmcc/geometry/feasible_set.h` (or a shorter path of a public header) in a code span as
        a link to its API page."""
        def span(m):
            inner = m.group(2)
            base = os.path.basename(inner)
            if inner.endswith(".h") and base in self.headers and \
                    self.headers[base].endswith(inner) and " " not in inner:
                return header_link(base, m.group(0))
            return m.group(0)
        return CODE_SPAN.sub(span, text)

    def rewrite_prose(self, line, rel_dir, page):
        """One line outside code fences: links, citations and header names, code spans kept."""
        # Split on code spans so that nothing inside them is rewritten (but header names are).
        out = []
        pos = 0
        for m in CODE_SPAN.finditer(line):
            out.append(self.rewrite_text(line[pos:m.start()], rel_dir, page))
            out.append(self.header_spans(m.group(0)))
            pos = m.end()
        out.append(self.rewrite_text(line[pos:], rel_dir, page))
        return "".join(out)

    def rewrite_text(self, text, rel_dir, page):
        # Links first (their targets hold `.md#…`), then citations in what is left.
        parts = []
        pos = 0
        for m in LINK.finditer(text):
            parts.append(self.cite_links(escape_commands(text[pos:m.start()]), False))
            parts.append(self.rewrite_link(m, rel_dir, page))
            pos = m.end()
        parts.append(self.cite_links(escape_commands(text[pos:]), False))
        return "".join(parts)

    def all_pages(self):
        """Every page of docs/ (whatever docs/*.md holds when the manual is built), linked."""
        items = []
        for rel, page in self.pages.items():
            if page.label == "index":
                continue
            for i, line, fenced in outside_fences(page.lines):
                m = HEADING.match(line)
                if not fenced and m:
                    items.append("[%s](@ref %s)" % (m.group(2).replace("`", ""), page.label))
                    break
        return "Every page of `docs/` in this manual: " + "; ".join(items) + "."

    def write_page(self, rel, page, out_dir, build_info):
        rel_dir = os.path.dirname(rel)
        lines = list(page.lines)
        result = []
        depth = 0
        block = []  # the lines of one run of prose, rewritten together (links may wrap)

        def flush():
            if block:
                result.append(self.rewrite_line("\n".join(block), rel_dir, page))
                block.clear()

        for i, line, fenced in outside_fences(lines):
            if fenced:
                flush()
                result.append(line)
                continue
            if i in page.heading_labels:
                flush()
                m = HEADING.match(line)
                level, text = m.group(1), m.group(2)
                text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # no links in headings
                # Doxygen 1.9.4 prints a code span in a section title as a literal "<tt>…</tt>".
                text = text.replace("`", "")
                if page.label == "index":   # the front page: Doxygen's main page, no label
                    result.append("%s %s" % (level, text))
                    continue
                # Doxygen wants no level skipped (### right under # is "outside of section
                # context"): a heading is at most one level below the one before it.
                level = "#" * min(len(level), depth + 1)
                depth = len(level)
                if page.heading_labels[i] == page.label:
                    # A comment before the title (accuracy.md's "generated" note) would
                    # hide the title from Doxygen: it goes, as it is not shown anyway.
                    del result[:leading_comment(result)]
                result.append("%s %s {#%s}" % (level, text, page.heading_labels[i]))
                if page.heading_labels[i] == page.label:
                    result.append("")
                    result.append("[TOC]")
                continue
            if line.lstrip().startswith("|"):
                line = table_row(line)
            if "<!-- gmcc:build-info -->" in line:
                line = line.replace("<!-- gmcc:build-info -->", build_info)
            block.append(line)
        flush()
        name = os.path.basename(rel) if rel_dir == "docs" else "mainpage.md"
        text = "\n".join(result).replace("<!-- gmcc:all-pages -->", self.all_pages())
        text = re.sub(r"<!-- gmcc:cite-begin -->.*?<!-- gmcc:cite-end -->",
                      lambda m: "```bibtex\n" + self.cite + "```", text, flags=re.S)
        with open(os.path.join(out_dir, name), "w", encoding="utf-8") as f:
            f.write(text)

    def rewrite_line(self, line, rel_dir, page):
        # Links whose text is a code span: rewrite the whole link first, then the rest.
        out = []
        pos = 0
        for m in LINK.finditer(line):
            # Only links not inside a code span: check the backticks before the match.
            if line[:m.start()].count("`") % 2:
                continue
            out.append(self.rewrite_prose(line[pos:m.start()], rel_dir, page))
            out.append(self.rewrite_link(m, rel_dir, page))
            pos = m.end()
        out.append(self.rewrite_prose(line[pos:], rel_dir, page))
        return "".join(out)


def bibtex_of_this_build(version, commit, date):
    """What `gmcc cite` prints for a binary of this version and commit: cli/citation.bib.in, the
    one text of the entries, filled in as cli/provenance.cpp fills it; --gmcc checks the two agree."""
    with open(os.path.join(HERE, "..", "..", "cli", "citation.bib.in"), encoding="utf-8") as f:
        b = f.read()
    dated = ""
    if len(date) >= 4 and date != "unknown":
        dated = "  year    = {" + date[:4] + "},\n  date    = {" + date + "},\n"
    for key, value in (("@VERSION@", version), ("@COMMIT@", commit), ("@DATED@", dated)):
        b = b.replace(key, value, 1)
    return b


def check_cite(gmcc):
    """bibtex_of_this_build against `gmcc cite`, for the binary's own version and commit."""
    line = subprocess.run([gmcc, "--version"], capture_output=True, text=True).stdout.strip()
    m = re.match(r"^gmcc (\S+) \(commit (\S+), (\S+)\)$", line)
    if not m:
        return "`gmcc --version` printed %r" % line
    cite = subprocess.run([gmcc, "cite"], capture_output=True, text=True).stdout
    mine = bibtex_of_this_build(m.group(1), m.group(2), m.group(3))
    if cite != mine:
        return "the front page's citation differs from `gmcc cite`:\n%s\n---\n%s" % (mine, cite)
    return None


def git_commit(source):
    """HEAD's full hash, with -dirty when tracked files differ; its date (cmake/build_info.cmake)."""
    def git(*args):
        return subprocess.run(["git", "-C", source] + list(args), capture_output=True,
                              text=True)
    if not os.path.exists(os.path.join(source, ".git")) or shutil.which("git") is None:
        return "unknown", "unknown"
    head = git("rev-parse", "HEAD")
    if head.returncode or not re.match(r"^[0-9a-f]+$", head.stdout.strip()):
        return "unknown", "unknown"
    commit = head.stdout.strip()
    date = git("log", "-1", "--format=%cs", "HEAD").stdout.strip() or "unknown"
    status = git("status", "--porcelain", "--untracked-files=no")
    if status.returncode or status.stdout.strip():
        commit += "-dirty"
    return commit, date


def filter_header(manual, path):
    """Doxygen INPUT_FILTER for a public header: docs citations in /// comments as \\ref links,
    line for line (line numbers are kept)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    for line in lines:
        m = re.match(r"^(\s*///<?)(.*)$", line)
        if m:
            text = manual.cite_links(m.group(2), True)
            # JAVADOC_AUTOBRIEF ends the brief at the first full stop and space: not at an
            # abbreviation ("eqs. 7–9", "e.g. the", "et al. 2002"), which gets Doxygen's `.\ `.
            parts = re.split(r"(`[^`]*`)", text)
            text = "".join(p if p.startswith("`") else ABBREVIATION.sub(r"\1.\\", p)
                           for p in parts)
            line = m.group(1) + text
        out.append(line)
    sys.stdout.write("\n".join(out))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--source", default=os.path.dirname(os.path.dirname(HERE)))
    ap.add_argument("--out")
    ap.add_argument("--version", default="unknown")
    ap.add_argument("--doxygen", default="doxygen")
    ap.add_argument("--filter", help="act as Doxygen's INPUT_FILTER for this header")
    ap.add_argument("--gmcc", help="check the front page's citation against `GMCC cite`")
    args = ap.parse_args(argv)
    source = os.path.abspath(args.source)
    manual = Manual(source)
    if args.filter:
        filter_header(manual, args.filter)
        return 0
    if not args.out:
        ap.error("--out is required")
    out = os.path.abspath(args.out)
    start = time.monotonic()
    pages_dir = os.path.join(out, "pages")
    shutil.rmtree(pages_dir, ignore_errors=True)
    shutil.rmtree(os.path.join(out, "html"), ignore_errors=True)
    os.makedirs(pages_dir)
    commit, date = git_commit(source)
    manual.cite = bibtex_of_this_build(args.version, commit, date)
    if args.gmcc:
        problem = check_cite(args.gmcc)
        if problem:
            print("build_manual.py: %s" % problem, file=sys.stderr)
            return 1
    build_info = ("This manual documents **gmcc %s**, built from git commit `%s` (%s)."
                  % (args.version, commit, date))
    try:
        for rel, page in manual.pages.items():
            manual.write_page(rel, page, pages_dir, build_info)
    except ValueError as e:
        print("build_manual.py: %s" % e, file=sys.stderr)
        return 1

    with open(os.path.join(HERE, "Doxyfile.in"), encoding="utf-8") as f:
        doxyfile = f.read()
    values = {
        "VERSION": args.version,
        "COMMIT": commit,
        "SOURCE": source,
        "OUT": out,
        "PAGES": pages_dir,
        "FILTER": "%s %s --source %s --filter" % (sys.executable, os.path.abspath(__file__),
                                                  source),
    }
    for k, v in values.items():
        doxyfile = doxyfile.replace("@%s@" % k, v)
    with open(os.path.join(out, "Doxyfile"), "w", encoding="utf-8") as f:
        f.write(doxyfile)
    warnings = os.path.join(out, "doxygen-warnings.txt")
    run = subprocess.run([args.doxygen, os.path.join(out, "Doxyfile")], cwd=out,
                         capture_output=True, text=True)
    if run.returncode and not os.path.exists(warnings):
        sys.stderr.write(run.stdout + run.stderr)
        return 1
    files_dir = os.path.join(out, "html", "files")
    for rel in manual.data_files:
        dest = os.path.join(files_dir, os.path.relpath(rel, "docs"))
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        shutil.copyfile(os.path.join(source, rel), dest)
    with open(warnings, encoding="utf-8") as f:
        text = f.read().strip()
    seconds = time.monotonic() - start
    if text or run.returncode:
        print(text)
        print("build_manual.py: Doxygen warned (%d lines above, also in %s): the manual is not "
              "clean" % (len(text.splitlines()), warnings), file=sys.stderr)
        return 1
    print("gmcc manual %s (commit %s) built in %.1f s: %s" %
          (args.version, commit, seconds, os.path.join(out, "html", "index.html")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
