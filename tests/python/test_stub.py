"""The type stub gmcc/__init__.pyi against the module it describes: the same public names as
``gmcc.__all__``; for every public function the same parameters (names, kinds, defaults) as
``inspect.signature`` of the real function; for every public class the same public attributes and
methods, read-only attributes declared as properties, the same base classes, and for every method
(pybind11: its signature line) the same parameters. The stub checked is the one shipped beside the
imported package, i.e. the one a type checker reads."""

import ast
import builtins
import inspect
from pathlib import Path

import pytest

import gmcc
from signatures import ast_parameters, pybind_parameters, runtime_parameters

STUB = Path(gmcc.__file__).with_name("__init__.pyi")
STUB_TREE = ast.parse(STUB.read_text(encoding="utf-8"))
# Dunders a class's stub must declare when the runtime class defines them (the protocols a type
# checker looks at); __repr__, __hash__ and the like are object's and need no declaration.
PROTOCOL_DUNDERS = {"__init__", "__len__", "__bool__", "__eq__", "__iter__", "__contains__", "__getitem__"}


def public(name):
    return not name.startswith("_") or (name.startswith("__") and name.endswith("__"))


def stub_top_level():
    """name -> ast node of the stub's top-level definitions."""
    out = {}
    for node in STUB_TREE.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            out[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            out[node.target.id] = node
        elif isinstance(node, ast.Assign):
            for t in node.targets:
                if isinstance(t, ast.Name):
                    out[t.id] = node
    return out


TOP = stub_top_level()


def is_pybind_function(f):
    return type(f).__name__ in ("builtin_function_or_method", "instancemethod") or (
        callable(f) and not inspect.isfunction(f) and (f.__doc__ or "").startswith(getattr(f, "__name__", "?") + "("))


def test_public_names_agree():
    stub_public = {name for name in TOP if public(name)}
    assert set(gmcc.__all__) == stub_public, (
        f"in __all__ but not in the stub: {sorted(set(gmcc.__all__) - stub_public)}; "
        f"in the stub but not in __all__: {sorted(stub_public - set(gmcc.__all__))}")
    assert len(gmcc.__all__) == len(set(gmcc.__all__)), "a name is listed twice in __all__"
    for name in gmcc.__all__:
        assert hasattr(gmcc, name), f"__all__ names {name}, which gmcc does not define"


def test_private_stub_names_are_not_runtime_api():
    # The stub's helper aliases must look private: a public-looking name a type checker accepts
    # (from gmcc import Number) would fail at run time.
    for name in TOP:
        if not public(name):
            assert name not in gmcc.__all__


@pytest.mark.parametrize("name", [n for n in gmcc.__all__ if isinstance(TOP.get(n), ast.AnnAssign)])
def test_module_constants_have_the_declared_type(name):
    annotation = TOP[name].annotation
    assert isinstance(annotation, ast.Name) and hasattr(builtins, annotation.id)
    assert isinstance(getattr(gmcc, name), getattr(builtins, annotation.id))


FUNCTIONS = [n for n in gmcc.__all__ if inspect.isfunction(getattr(gmcc, n)) or is_pybind_function(getattr(gmcc, n))]
CLASSES = [n for n in gmcc.__all__ if inspect.isclass(getattr(gmcc, n))]


def test_every_public_name_is_a_function_a_class_or_a_constant():
    constants = {n for n in gmcc.__all__ if isinstance(TOP.get(n), ast.AnnAssign)}
    assert set(FUNCTIONS) | set(CLASSES) | constants == set(gmcc.__all__)
    assert len(FUNCTIONS) > 20 and len(CLASSES) > 15  # the selection itself works


@pytest.mark.parametrize("name", FUNCTIONS)
def test_function_signature_matches_the_stub(name):
    f = getattr(gmcc, name)
    node = TOP.get(name)
    assert isinstance(node, ast.FunctionDef), f"the stub declares {name} as {type(node).__name__}, not a function"
    stub = ast_parameters(node)
    real = runtime_parameters(f) if inspect.isfunction(f) else pybind_parameters(f)
    unstated = [p[0] for p in stub if p[2] == "..."]
    assert not unstated, f"{name}: the stub gives no default value for {unstated} (write the real one)"
    assert stub == real, f"{name}:\n  stub    {stub}\n  runtime {real}"


def stub_class_members(name, seen=None):
    """member name -> 'property' | 'attribute' | 'method' declared by the stub's class `name`,
    its stub base classes included."""
    node = TOP[name]
    out = {}
    for base in node.bases:
        if isinstance(base, ast.Name) and isinstance(TOP.get(base.id), ast.ClassDef):
            out.update(stub_class_members(base.id))
    for item in node.body:
        if isinstance(item, ast.FunctionDef):
            decorators = {d.id for d in item.decorator_list if isinstance(d, ast.Name)}
            out[item.name] = "property" if "property" in decorators else "method"
        elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
            out[item.target.id] = "attribute"
    return out


def runtime_class_members(cls):
    """member name -> 'property' | 'readwrite' | 'method' of a gmcc class (its own and its gmcc
    bases'), public names and protocol dunders; an __init__ only when a constructor is defined."""
    out = {}
    for c in reversed(cls.__mro__):
        if not c.__module__.startswith("gmcc"):
            continue
        for k, v in vars(c).items():
            if k.startswith("_") and k not in PROTOCOL_DUNDERS:
                continue
            if k == "__init__" and not (v.__doc__ or "").startswith("__init__("):
                continue  # pybind11's "No constructor defined"
            if isinstance(v, property):
                out[k] = "property" if v.fset is None else "readwrite"
            else:
                out[k] = "method"
    return out


@pytest.mark.parametrize("name", CLASSES)
def test_class_matches_the_stub(name):
    cls = getattr(gmcc, name)
    node = TOP.get(name)
    assert isinstance(node, ast.ClassDef), f"the stub declares {name} as {type(node).__name__}, not a class"
    for base in node.bases:
        assert isinstance(base, ast.Name) and issubclass(cls, getattr(gmcc, base.id)), (
            f"the stub derives {name} from {ast.unparse(base)}, the module does not")
    stub = stub_class_members(name)
    real = runtime_class_members(cls)
    assert set(real) - set(stub) == set(), f"{name}: not in the stub: {sorted(set(real) - set(stub))}"
    assert set(stub) - set(real) == set(), f"{name}: in the stub only: {sorted(set(stub) - set(real))}"
    for member, kind in real.items():
        expected = {"property": "property", "readwrite": "attribute", "method": "method"}[kind]
        assert stub[member] == expected, (
            f"{name}.{member} is a {kind} at run time; the stub declares it as {stub[member]}")


@pytest.mark.parametrize("name", CLASSES)
def test_method_signatures_match_the_stub(name):
    cls = getattr(gmcc, name)
    stub_methods = {}
    for item in TOP[name].body:
        if isinstance(item, ast.FunctionDef) and not any(
                isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list):
            stub_methods[item.name] = item
    for member, kind in runtime_class_members(cls).items():
        if kind != "method" or member.startswith("__") and member != "__init__":
            continue
        stub = ast_parameters(stub_methods[member])
        real = pybind_parameters(getattr(cls, member))
        assert stub == real, f"{name}.{member}:\n  stub    {stub}\n  runtime {real}"


def test_the_checks_see_a_wrong_stub():
    # The comparison itself: a stub that drops a parameter, misstates a default or a kind, or
    # declares a read-only attribute as writable is caught.
    real = runtime_parameters(gmcc.canonical_gamut)
    wrong = ast.parse("def canonical_gamut(canonical, *, expand=0, expand_policy='none'): ...").body[0]
    assert ast_parameters(wrong) != real
    wrong = ast.parse("def canonical_gamut(canonical, *, expand=1, expand_policy='none', "
                      "nonpositive_blue='drop'): ...").body[0]
    assert ast_parameters(wrong) != real
    wrong = ast.parse("def canonical_gamut(canonical, expand=0, expand_policy='none', "
                      "nonpositive_blue='drop'): ...").body[0]
    assert ast_parameters(wrong) != real
    right = ast.parse("def canonical_gamut(canonical, *, expand=0, expand_policy='none', "
                      "nonpositive_blue='drop'): ...").body[0]
    assert ast_parameters(right) == real
    assert runtime_class_members(gmcc.Canonical)["gamut"] == "property"  # read-only at run time
    assert pybind_parameters(gmcc.ConvexSet.contains) == [("point", "POSITIONAL_OR_KEYWORD", None)]
