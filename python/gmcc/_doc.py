"""Shared parameter descriptions spliced into the pure-Python wrappers' docstrings.

A docstring line that holds only ``@name@`` (indented as a numpydoc entry) is replaced by the part
``name``: the extension's (``gmcc._core._doc_parts``: the pixel rules and the canonical side's
options, the text its own functions' docstrings carry) or the caller's. Each text is written once.
"""

from . import _core


def doc(**own):
    """A decorator splicing ``_core._doc_parts`` and ``own`` into a function's docstring (a no-op
    under python -OO, where there are no docstrings)."""
    parts = dict(_core._doc_parts, **own)

    def splice(f):
        if f.__doc__:
            for name, text in parts.items():
                indented = "".join("    " + line if line.strip() else line for line in text.splitlines(True))
                f.__doc__ = f.__doc__.replace("    @" + name + "@\n", indented)
        return f
    return splice
