"""Every public function and class of gmcc (``gmcc.__all__``) and every public method has a
numpy-style docstring: a one-line summary, a citation of its paper (an author-year and an
equation, section or figure), ``Parameters`` naming exactly the parameters it takes (each with
a type, and ``optional`` or ``default`` when it has a default), ``Returns``, and ``Raises`` (known
exception types) for a function that takes arguments; a class lists its public attributes,
exactly, under ``Attributes``."""

import builtins
import inspect
import re

import pytest

import gmcc
from signatures import pybind_parameters

YEAR = re.compile(r"\b(19|20)\d\d\b")
PLACE = re.compile(r"(§\s?\d|\beqs?\.\s?\d|\bFigs?\.\s?\d)")


def sections(doc):
    """{title: [lines]} of a numpydoc docstring (a title is a line underlined by dashes of its
    length); '' holds the summary and the extended description."""
    lines = doc.splitlines()
    out = {"": []}
    title = ""
    i = 0
    while i < len(lines):
        if i + 1 < len(lines) and lines[i].strip() and set(lines[i + 1].strip()) == {"-"} and \
                len(lines[i + 1].strip()) == len(lines[i].strip()):
            title = lines[i].strip()
            out[title] = []
            i += 2
            continue
        out[title].append(lines[i])
        i += 1
    return out


def entries(lines):
    """[(names, type or None)] of a Parameters or Attributes section: its unindented lines."""
    out = []
    for line in lines:
        if not line.strip() or line.startswith(" "):
            continue
        head, sep, kind = line.partition(" : ")
        names = [n.strip().lstrip("*") for n in head.split(",")]
        out.append((names, kind.strip() if sep else None))
    return out


def own_doc(obj):
    """The docstring without a pybind11 signature line (``name(self: ...) -> T``)."""
    doc = inspect.getdoc(obj) or ""
    name = getattr(obj, "__name__", "")
    if doc.startswith(name + "("):
        doc = doc.split("\n", 1)[1] if "\n" in doc else ""
    return inspect.cleandoc(doc)


def parameters(obj):
    """The parameters (inspect.Parameter) a caller gives, self excluded; pybind11 functions from
    their signature line."""
    if inspect.isfunction(obj):
        return list(inspect.signature(obj).parameters.values())
    out = []
    for name, kind, default in pybind_parameters(obj):
        out.append(inspect.Parameter(name, getattr(inspect.Parameter, kind),
                                     default=inspect.Parameter.empty if default is None else default))
    return out


def check_summary_and_citation(what, doc):
    assert doc, f"{what}: no docstring"
    lines = doc.splitlines()
    assert lines[0].strip() and lines[0].rstrip().endswith("."), f"{what}: the summary line is {lines[0]!r}"
    assert len(lines) == 1 or not lines[1].strip(), f"{what}: the summary is more than one line"
    assert YEAR.search(doc) and PLACE.search(doc), (
        f"{what}: no citation of a paper with its equation, section or figure")


def checked_doc(what, obj):
    """obj's own docstring (own_doc), its summary and citation checked."""
    doc = own_doc(obj)
    check_summary_and_citation(what, doc)
    return doc


def check_parameters(what, doc, params):
    s = sections(doc)
    if not params:
        assert "Parameters" not in s, f"{what}: documents parameters it does not take"
        return
    assert "Parameters" in s, f"{what}: no Parameters section"
    documented = entries(s["Parameters"])
    names = [n for ns, _ in documented for n in ns]
    assert names == [p.name for p in params], (
        f"{what}: documents {names}, takes {[p.name for p in params]}")
    by_name = {n: kind for ns, kind in documented for n in ns}
    for p in params:
        if p.kind is inspect.Parameter.VAR_KEYWORD:
            continue
        kind = by_name[p.name]
        assert kind, f"{what}: parameter {p.name} has no type"
        if p.default is not inspect.Parameter.empty:
            assert "default" in kind or "optional" in kind, (
                f"{what}: parameter {p.name} has a default; its type line says neither 'default' nor 'optional'")


def check_returns_and_raises(what, doc, takes_arguments):
    s = sections(doc)
    assert "Returns" in s and any(line.strip() for line in s["Returns"]), f"{what}: no Returns section"
    if takes_arguments:
        assert "Raises" in s, f"{what}: takes arguments but has no Raises section"
        raised = [ns[0] for ns, _ in entries(s["Raises"])]
        assert raised, f"{what}: an empty Raises section"
        for name in raised:
            assert isinstance(getattr(builtins, name, None), type) and issubclass(getattr(builtins, name), BaseException), (
                f"{what}: Raises names {name!r}, not an exception")


FUNCTIONS = [n for n in gmcc.__all__ if callable(getattr(gmcc, n)) and not inspect.isclass(getattr(gmcc, n))]
CLASSES = [n for n in gmcc.__all__ if inspect.isclass(getattr(gmcc, n))]


@pytest.mark.parametrize("name", FUNCTIONS)
def test_function_docstring(name):
    f = getattr(gmcc, name)
    doc = checked_doc(name, f)
    params = parameters(f)
    check_parameters(name, doc, params)
    check_returns_and_raises(name, doc, bool(params))


def public_members(cls):
    """(attributes, methods) of a gmcc class: its public properties and public methods."""
    attributes, methods = [], []
    for k, v in vars(cls).items():
        if k.startswith("_"):
            continue
        (attributes if isinstance(v, property) else methods).append(k)
    return attributes, methods


@pytest.mark.parametrize("name", CLASSES)
def test_class_docstring(name):
    cls = getattr(gmcc, name)
    doc = checked_doc(name, cls)
    s = sections(doc)
    attributes, methods = public_members(cls)
    assert "Attributes" in s, f"{name}: no Attributes section"
    documented = [n for ns, _ in entries(s["Attributes"]) for n in ns]
    assert sorted(documented) == sorted(attributes), (
        f"{name}: Attributes lists {sorted(documented)}; the class has {sorted(attributes)}")
    init = vars(cls).get("__init__")
    params = parameters(init) if init is not None and (init.__doc__ or "").startswith("__init__(") else []
    check_parameters(name, doc, params)
    for method in methods:
        m = getattr(cls, method)
        what = f"{name}.{method}"
        mdoc = checked_doc(what, m)
        mparams = parameters(m)
        check_parameters(what, mdoc, mparams)
        check_returns_and_raises(what, mdoc, bool(mparams))


def test_the_checks_see_a_bad_docstring():
    def f(a, b=1):
        """Does a thing.

        Parameters
        ----------
        a : int
            The a.

        Returns
        -------
        int
        """

    doc = own_doc(f)
    with pytest.raises(AssertionError, match="citation"):
        check_summary_and_citation("f", doc)
    with pytest.raises(AssertionError, match="documents"):
        check_parameters("f", doc, parameters(f))
    with pytest.raises(AssertionError, match="Raises"):
        check_returns_and_raises("f", doc, True)
    with pytest.raises(AssertionError, match="summary"):
        check_summary_and_citation("f", "Two lines\nof summary (Forsyth 1990 §3).")
