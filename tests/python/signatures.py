"""Parameter lists of functions, compared by tests/python/test_stub.py and
tests/python/test_docstrings.py: from a stub's (or any) ``def`` parsed by ``ast``, from
``inspect.signature`` of a Python function, and from the signature line pybind11 writes at the
head of a compiled function's docstring. Each is [(name, kind, default repr or None)], self
excluded, kind an ``inspect.Parameter`` kind's name."""

import ast
import inspect


def default_text(node):
    """A default as the repr of its value; '...' (no value stated) is refused by the caller."""
    if isinstance(node, ast.Constant) and node.value is Ellipsis:
        return "..."
    return repr(ast.literal_eval(node))


def ast_parameters(fn):
    """[(name, kind, default repr or None)] of a FunctionDef, in order, without self."""
    a = fn.args
    out = []
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    for i, (arg, d) in enumerate(zip(positional, defaults)):
        kind = "POSITIONAL_ONLY" if i < len(a.posonlyargs) else "POSITIONAL_OR_KEYWORD"
        out.append((arg.arg, kind, None if d is None else default_text(d)))
    if a.vararg:
        out.append((a.vararg.arg, "VAR_POSITIONAL", None))
    for arg, d in zip(a.kwonlyargs, a.kw_defaults):
        out.append((arg.arg, "KEYWORD_ONLY", None if d is None else default_text(d)))
    if a.kwarg:
        out.append((a.kwarg.arg, "VAR_KEYWORD", None))
    if out and out[0][0] == "self":
        out = out[1:]
    return out


def runtime_parameters(f):
    """The same for a Python function (inspect.signature)."""
    out = []
    for p in inspect.signature(f).parameters.values():
        d = None if p.default is inspect.Parameter.empty else repr(p.default)
        out.append((p.name, p.kind.name, d))
    return out


def pybind_parameters(f):
    """The same for a pybind11 function or method, from the signature line heading its docstring
    (``name(self: T, a: T = d, *, b: T = d) -> R``), parsed as a Python def."""
    line = (f.__doc__ or "").splitlines()[0]
    assert line.startswith(f.__name__ + "("), f"{f.__qualname__}: no signature line: {line!r}"
    fn = ast.parse("def " + line + ": ...").body[0]
    return ast_parameters(fn)
