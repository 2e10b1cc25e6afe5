#!/usr/bin/env python3
"""Every source the code cites by author and year must be in docs/references.bib.

    check_references.py [--root DIR]   check the tracked code of DIR (default: this repository)
    check_references.py --self-test    check made-up texts with known good and bad citations

A citation is one to four capitalised names joined by commas, "&" or "and", optionally followed
by "et al." or "'s", then a year 1900-2029, possibly in parentheses: "Forsyth 1990",
"Finlayson & Hordley (1999", "Barnard, Cardei & Funt 2002", "Gijsenij et al. (2010",
"Forsyth's (1990". It resolves when one entry of references.bib has that year and every cited
name in its author field ("van de Weijer 2007" resolves by "Weijer"). Words that are not authors
(RFC 1951, SFU's 1995 data, BMVC 2014) are listed in NOT_AUTHORS.

Files scanned: tracked .h, .cpp and .py files outside tests/, bench/ and fuzz/ (the library, the
command line, Python and the scripts' modules). Exit status 0 when every citation resolves, 1 with
one line per problem (FILE:LINE: problem).
"""
import os
import re
import sys

from doc_checks import arguments, tracked_texts

NAME = r"[A-Z][A-Za-z'’\-]+"
CITATION = re.compile(
    rf"((?:{NAME}(?:,\s+(?:and\s+|&\s+)?|\s+(?:&|and)\s+)){{0,3}}{NAME})(\s+et al\.)?(?:'s)?,?\s+\(?((?:19|20)\d\d)\b")
NOT_AUTHORS = {"RFC", "SFU", "BMVC", "JOSA", "CIC", "IEEE", "ISO", "Debian", "C", "Part", "Fig",
               "Table", "Section", "Eq", "CRULE", "CRULE-AVE", "CRULE-MV", "Python", "CMake", "Ubuntu", "MATLAB", "Release", "Version"}
ENTRY = re.compile(r"@\w+\{([^,]+),(.*?)(?=\n@|\Z)", re.S)


def entries(bib_text):
    """(key, author field, year) of each entry."""
    out = []
    for key, body in ENTRY.findall(bib_text):
        author = re.search(r"author\s*=\s*\{(.*?)\}\s*,", body, re.S)
        year = re.search(r"year\s*=\s*\{(\d{4})\}", body)
        if author and year:
            out.append((key, " ".join(author.group(1).split()), year.group(1)))
    return out


def citations(text):
    """(line, names, year) of each author-year citation in `text`."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        for m in CITATION.finditer(line):
            names = [n.removesuffix("'s") for n in re.split(r",\s+(?:and\s+|&\s+)?|\s+(?:&|and)\s+", m.group(1))]
            names = [n for n in names if n not in NOT_AUTHORS]
            if names:
                found.append((number, names, m.group(3)))
    return found


def problems(files, bib_text):
    """One line per citation that no entry resolves; `files` maps a name to its text."""
    bib = entries(bib_text)
    out = []
    for name, text in files.items():
        for line, names, year in citations(text):
            if not any(y == year and all(n in author for n in names) for _, author, y in bib):
                out.append(f"{name}:{line}: {' & '.join(names)} {year} is not in docs/references.bib")
    return out


def scanned(path):
    return path.endswith((".h", ".cpp", ".py")) and not path.startswith(("tests/", "bench/", "fuzz/"))


def self_test():
    bib = """@article{A1990,
  author = {David A. Forsyth}, title = {x}, year = {1990}}
@article{B2002,
  author = {Kobus Barnard and Vlad Cardei and Brian Funt}, title = {y}, year = {2002}}
@article{C2010,
  author = {Arjan Gijsenij and Theo Gevers and Joost van de Weijer}, title = {z},
  year = {2010}}
"""
    good = ("// Forsyth 1990; Forsyth's (1990); Barnard, Cardei & Funt 2002; Cardei & Funt (2002\n"
            "// Gijsenij et al. (2010; Gijsenij, Gevers & van de Weijer 2010; RFC 1951; SFU's 1995\n")
    bad = "// Forsyth 1991\n// Barnard & Smith 2002\n// Land 1977\n"
    ok = problems({"good": good}, bib) == [] and len(problems({"bad": bad}, bib)) == 3
    print("self-test:", "ok" if ok else "FAILED", problems({"good": good, "bad": bad}, bib))
    return 0 if ok else 1


def main():
    a = arguments()
    if a.self_test:
        return self_test()
    with open(os.path.join(a.root, "docs", "references.bib"), encoding="utf-8") as f:
        bib_text = f.read()
    files = tracked_texts(a.root, scanned)
    found = problems(files, bib_text)
    for p in found:
        print(p)
    count = sum(len(citations(t)) for t in files.values())
    print(f"check_references: {count} citations in {len(files)} files, {len(found)} unresolved")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
