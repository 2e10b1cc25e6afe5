"""gmcc — gamut-mapping colour constancy with exact geometry, from Python.

A thin layer over the C++ library (docs/python.md): the canonical gamut, the feasible set of
perspective diagonal maps (Finlayson & Hordley 1999 eqs. 7–9, in perspective), the selection
rules max-area, 2-D mean and 3-D mean (§3) with their worst cases (§4), Forsyth's 3-D CRULE,
the paper's experiments (synthetic, camera and Gehler–Shi charts) and the statistics the field
reports.

Input is read exactly: a float (or a numpy float) is the rational of its value — ``0.1`` is
3602879701896397/36028797018963968, not 1/10 — an int or a ``fractions.Fraction`` its own
value, and a ``str`` is read as the command line reads a file (``"0.1"`` is 1/10). Exact results
come back as ``Fraction``; irrational ones (the 3-D mean) as the nearest double with a certified
error bound. The GIL is released during geometry and selection; calls are thread-safe.

The package mirrors the library's layers (docs/architecture.md): ``gmcc.geometry``,
``gmcc.selection``, ``gmcc.input``, ``gmcc.photo`` and ``gmcc.validation``; every public name is
also here, at the top level (``gmcc.select`` is ``gmcc.selection.select``).

>>> import gmcc
>>> gmcc.rules()
['max_area', 'mean_2d', 'mean_3d']
>>> gmcc.select is gmcc.selection.select
True
"""

from __future__ import annotations

from . import _core, geometry, input, photo, selection, validation  # noqa: A004
from .geometry import *  # noqa: F401,F403
from .input import *  # noqa: F401,F403
from .photo import *  # noqa: F401,F403
from .selection import *  # noqa: F401,F403
from .validation import *  # noqa: F401,F403

__version__: str = _core.__version__
__commit__: str = _core.__commit__
__commit_date__: str = _core.__commit_date__

# The layers' public names, in the library's order (docs/architecture.md "Layers").
__all__ = ["__version__", "__commit__", "__commit_date__", *geometry.__all__, *selection.__all__, *input.__all__,
           *photo.__all__, *validation.__all__]
