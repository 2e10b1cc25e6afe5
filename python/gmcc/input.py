"""The input layer (gmcc/input/; docs/architecture.md "Layers"): camera images read as the command
line reads them, the pixel rules that make them colours (docs/conventions.md §8), and the shipped
spectral data.

``read_image`` and ``image_colours`` are the extension's, re-exported as they are (signatures,
defaults and docstrings in python/src/docstrings.h); ``data_dir`` is Python.
"""

from __future__ import annotations

import os as _os

from ._core import ImageColours, image_colours, read_image  # noqa: F401  (re-exported)
from . import _core

__all__ = ["ImageColours", "read_image", "image_colours", "data_dir"]


def data_dir() -> str:
    """The folder of gmcc's shipped spectral data, the inputs of the paper's experiments.

    The Munsell chips, CIE illuminants and daylight basis of Finlayson & Hordley (1999) §4,
    the SFU camera data and the Gehler–Shi chart colours (data/SOURCES.md): $GMCC_DATA_DIR, else
    data/ installed next to the package, else the source tree's data/ recorded at build time.

    Returns
    -------
    str
        The folder's path.

    Raises
    ------
    FileNotFoundError
        None of those folders holds the data.
    """
    env = _os.environ.get("GMCC_DATA_DIR")
    if env:
        return env
    here = _os.path.dirname(__file__)
    for candidate in (_os.path.join(here, "data"), getattr(_core, "__data_dir__", "")):
        if candidate and _os.path.isfile(_os.path.join(candidate, "munsell_matt_1269_joensuu_5nm.csv")):
            return candidate
    raise FileNotFoundError("gmcc's spectral data not found: set GMCC_DATA_DIR to the data/ folder")
