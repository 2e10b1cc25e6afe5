"""The examples in gmcc's docstrings run as written (doctest): every public function, class and
method of every layer module (gmcc.geometry, ... ``__all__``) and the package's own docstring, the
extension's docstrings (python/src/docstrings.h) and the Python wrappers' alike. Each example runs
with ``gmcc`` and ``Fraction`` in its namespace; an object with no example is skipped, and the
test fails when no example ran at all."""

import doctest
import inspect
from fractions import Fraction

import pytest

import gmcc

LAYERS = (gmcc.geometry, gmcc.selection, gmcc.input, gmcc.photo, gmcc.validation)


def documented():
    """(qualified name, object) of the package, every layer's public names and their methods."""
    out = [("gmcc", gmcc)] + [(m.__name__, m) for m in LAYERS]
    for module in LAYERS:
        for name in module.__all__:
            obj = getattr(module, name)
            out.append((f"{module.__name__}.{name}", obj))
            if inspect.isclass(obj):
                out += [(f"{module.__name__}.{name}.{k}", v) for k, v in vars(obj).items()
                        if not k.startswith("_") and callable(v)]
    return out


def examples():
    parser = doctest.DocTestParser()
    out = []
    for name, obj in documented():
        doc = obj.__doc__ or ""
        if ">>>" in doc:
            out.append(parser.get_doctest(doc, {"gmcc": gmcc, "Fraction": Fraction}, name, None, 0))
    return out


EXAMPLES = examples()


def test_there_are_examples():
    assert len(EXAMPLES) >= 8


@pytest.mark.parametrize("test", EXAMPLES, ids=[t.name for t in EXAMPLES])
def test_example_runs_as_written(test):
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    out = []
    result = runner.run(test, out=out.append)
    assert result.failed == 0, "".join(out)
