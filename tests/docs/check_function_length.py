#!/usr/bin/env python3
"""No function of the project's C++ is longer than 80 lines (issue 29's "done when").

    check_function_length.py [--root DIR]   check the tracked C++ of DIR (default: this repository)
    check_function_length.py --self-test    check made-up sources with known long and short functions

Scanned: tracked .h and .cpp files under geometry/, selection/, numerics/, input/, photo/,
validation/, cli/ and python/src/ (not tests/, fuzz/ or bench/). A function's length is the
number of lines its body's braces span, the line of `{` and the line of `}` included; a function
of 80 lines passes, one of 81 does not.

How functions are found (a brace-matching scan, not a C++ parser):
- comments, string and character literals (raw strings and digit separators included) and
  preprocessor lines are blanked first, keeping the line breaks;
- each `{` is classified by the text since the previous `;`, `{` or `}` (its head): a `namespace`
  or `extern "C"` head opens a scope that is scanned further, a `class`, `struct` or `union` head
  opens one whose member functions are scanned too, a head with a `)` and no `=` or `[` before its
  first `(` is a function (free, member, constructor, operator, or a macro such as
  PYBIND11_MODULE), and anything else (an initialiser, an enum, a namespace-level lambda) is
  skipped to its matching `}`;
- nothing inside a function is examined: lambdas and local classes count towards their function.
Limits: a constructor's braced member initialiser `x_{a}` is read as a one-line function and its
body then measured from the next brace; braces that `#if` branches leave unbalanced are not
understood (the file is reported as unbalanced, not skipped); a function written by a macro is
invisible. Functions are named by the qualified identifier before their head's first `(`.

ALLOWED lists functions known to be longer, each with why it is still there; an entry that is no
longer over the limit (or no longer exists) is reported too, so the list only shrinks. Exit status
0 when nothing is over the limit outside the list, 1 with one line per problem (FILE:LINE: ...).
"""
import os
import re
import subprocess
import sys
import tempfile

from doc_checks import arguments, report, tracked_texts

LIMIT = 80
FOLDERS = ("geometry/", "selection/", "numerics/", "input/", "photo/", "validation/", "cli/", "python/src/")

# (file, function) -> why it is over the limit: empty, every function is within it. An entry is
# for a function that cannot be split yet, with the reason; the scan reports an entry that has
# become short enough, so that it is deleted and the list only shrinks.
ALLOWED = {}


PREPROCESSOR = re.compile(r"[ \t]*#")
RAW_STRING = re.compile(r'(?:u8|u|U|L)?R"([^()\\ ]{0,16})\(')


def skipped_end(text, i, line_start):
    """Where the comment, literal or preprocessor line that starts at i ends, or None."""
    n = len(text)
    if line_start and PREPROCESSOR.match(text, i):  # with its backslash continuations
        j = i
        while j < n and text[j] != "\n":
            j = j + 2 if text[j] == "\\" and j + 1 < n else j + 1
        return j
    if text.startswith("//", i):
        j = text.find("\n", i)
        return n if j < 0 else j
    if text.startswith("/*", i):
        j = text.find("*/", i + 2)
        return n if j < 0 else j + 2
    raw = RAW_STRING.match(text, i)
    if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
        end = text.find(")" + raw.group(1) + '"', raw.end())
        return n if end < 0 else end + len(raw.group(1)) + 2
    c = text[i]
    if c == '"' or (c == "'" and not digit_separator(text, i)):
        j = i + 1
        while j < n and text[j] != c and text[j] != "\n":
            j += 2 if text[j] == "\\" else 1
        return min(n, j + 1)
    return None


def blank(text):
    """`text` with comments, literals and preprocessor lines replaced by spaces, newlines kept."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            out.append(c)
            i += 1
            line_start = True
            continue
        j = skipped_end(text, i, line_start)
        line_start = line_start and c in " \t"
        if j is None:
            out.append(c)
            i += 1
        else:
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
    return "".join(out)


def digit_separator(text, i):
    """True when the ' at i separates digits (1'000'000), not opens a character literal."""
    m = re.search(r"([A-Za-z0-9_]+)$", text[max(0, i - 64):i])
    return bool(m) and m.group(1) not in ("u8", "u", "U", "L") and m.group(1)[0].isdigit()


def classify(head):
    """What a `{` with this head opens: 'scope', 'class', 'function' or 'other'."""
    h = " ".join(head.split())
    if re.match(r"^(inline\s+)?namespace\b", h) or re.match(r'^extern\s*"?', h) and "(" not in h:
        return "scope"
    h = re.sub(r"^template\s*<[^{;]*?>\s*(?=[\w:~])", "", h)  # template <class T> T f(...)
    paren = h.find("(")
    before = h if paren < 0 else h[:paren]
    bare = re.sub(r"operator\s*(\(\)|\[\]|[^\w\s(]+)", "operator", before)  # operator==, operator[]
    if re.search(r"\b(class|struct|union)\b", bare) and "=" not in bare:
        return "class"
    if paren >= 0 and ")" in h and "=" not in bare and "[" not in bare and not re.search(r"\benum\b", bare):
        return "function"
    return "other"


def function_name(head):
    h = " ".join(head.split())
    before = h[:h.find("(")] if "(" in h else h
    if re.search(r"operator\s*$", before):  # operator()(...)
        return re.findall(r"[\w:~]+", before)[-1] + "()"
    m = re.search(r"((?:[\w~]+(?:<[^()]*?>)?\s*::\s*)*(?:operator\s*\S+|[\w~]+))\s*(?:<[^()]*>)?\s*$", before)
    return re.sub(r"\s+", "", m.group(1)) if m else "?"


def long_functions(text, limit=LIMIT):
    """(name, first line, length) of each function longer than `limit` lines; raises ValueError
    when the braces do not balance."""
    code = blank(text)
    found = []
    stack = []  # kinds of the open scopes: 'scope' or 'class'
    head_start = 0
    i, n = 0, len(code)
    line = 1
    while i < n:
        c = code[i]
        if c == "\n":
            line += 1
        elif c in ";":
            head_start = i + 1
        elif c == "}":
            if not stack:
                raise ValueError(f"line {line}: unbalanced '}}'")
            stack.pop()
            head_start = i + 1
        elif c == "{":
            head = code[head_start:i]
            kind = classify(head)
            if kind in ("scope", "class"):
                stack.append(kind)
                head_start = i + 1
            else:
                end, end_line = matching(code, i, line)
                length = end_line - line + 1
                if kind == "function" and length > limit:
                    found.append((function_name(head), line, length))
                line = end_line
                i = end + 1
                head_start = i
                continue
        i += 1
    if stack:
        raise ValueError("unbalanced '{' at the end of the file")
    return found


def matching(code, i, line):
    """The index and line of the `}` matching the `{` at i (on `line`)."""
    depth = 0
    for j in range(i, len(code)):
        if code[j] == "\n":
            line += 1
        elif code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j, line
    raise ValueError(f"line {line}: unbalanced '{{'")


def problems(files, allowed, limit=LIMIT):
    """One line per function over `limit` not in `allowed`, and per stale entry of `allowed`;
    `files` maps a path to its text."""
    out, seen = [], set()
    for path, text in sorted(files.items()):
        try:
            found = long_functions(text, limit)
        except ValueError as e:
            out.append(f"{path}: braces not understood ({e})")
            continue
        for name, line, length in found:
            if (path, name) in allowed:
                seen.add((path, name))
            else:
                out.append(f"{path}:{line}: {name} is {length} lines, more than {limit}")
    for key in sorted(set(allowed) - seen):
        out.append(f"{key[0]}: {key[1]} is allowed to be long but is not (any more): remove it from ALLOWED")
    return out


def scanned(path):
    return path.endswith((".h", ".cpp")) and path.startswith(FOLDERS)


def self_test():
    def body(lines):  # a function whose braces span `lines` lines
        return "{\n" + "  ++x;\n" * (lines - 2) + "}\n"
    source = (
        '#include <string>\n#define OPEN {\n'
        "namespace gmcc {\nnamespace {\n"
        "int long_free(int x) " + body(81) +
        "int just_fits(int x) " + body(80) +
        "}  // namespace\n"
        "struct S {\n  int member(int x) const " + body(90) + "  int y = 0;\n};\n"
        "const int table[] = {1, 2, 3};\n"
        "enum class E { a, b };\n"
        "template <class T>\nT Holder<T>::templated(T x) " + body(82) +
        "int strings(int x) {\n  const char* s = \"}}}{\"; // }\n  /* { */ const char c = '}';\n"
        "  const std::string r = R\"x(}})x\";\n  return 1'000'000 + x;\n}\n"
        "bool operator==(const S& a, const S& b) " + body(85) +
        "}  // namespace gmcc\n")
    got = long_functions(source)
    want = [("long_free", 5, 81), ("member", 168, 90), ("Holder<T>::templated", 263, 82),
            ("operator==", 351, 85)]
    names_ok = [(n, l) for n, l, _ in got] == [(n, l) for n, l, _ in want] and [g[2] for g in got] == [w[2] for w in want]
    allowed = {("a.cpp", "long_free"): "why", ("a.cpp", "gone"): "why"}
    listed = problems({"a.cpp": source, "b.cpp": "int f() {\n"}, allowed)
    stale_ok = (any("gone" in p and "ALLOWED" in p for p in listed)
                and not any("long_free" in p for p in listed)
                and any(p.startswith("b.cpp: braces not understood") for p in listed)
                and "a.cpp:168: member is 90 lines, more than 80" in listed)
    # The real scan over a scratch tree: a planted long function is flagged by main's route.
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "geometry", "src"))
        with open(os.path.join(tmp, "geometry", "src", "planted.cpp"), "w", encoding="utf-8") as f:
            f.write("int planted(int x) " + body(81))
        subprocess.run(["git", "-C", tmp, "init", "-q"], check=True)
        subprocess.run(["git", "-C", tmp, "add", "."], check=True)
        tree_ok = problems(tracked_texts(tmp, scanned), {}) == ["geometry/src/planted.cpp:1: planted is 81 lines, more than 80"]
    ok = names_ok and stale_ok and tree_ok
    print("self-test:", "ok" if ok else "FAILED", got, listed)
    return 0 if ok else 1


def main():
    a = arguments()
    if a.self_test:
        return self_test()
    files = tracked_texts(a.root, scanned)
    found = problems(files, ALLOWED)
    return report(found, f"check_function_length: {len(found)} problems in {len(files)} files",
                  f"check_function_length: no function over {LIMIT} lines in {len(files)} files "
                  f"({len(ALLOWED)} allowed, each named in ALLOWED)")


if __name__ == "__main__":
    sys.exit(main())
