"""Experiment records as a numpy structured array or, when pandas is installed, a DataFrame."""

from __future__ import annotations

import numpy as np


def records_array(columns: dict) -> np.ndarray:
    """The columns (name -> list or 1-D array, all of one length) as a structured array; text
    columns become fixed-width unicode fields."""
    fields = []
    arrays = []
    for name, values in columns.items():
        a = np.asarray(values)
        if a.dtype.kind in "OU":
            a = a.astype(str)
        fields.append((name, a.dtype))
        arrays.append(a)
    n = len(arrays[0]) if arrays else 0
    out = np.empty(n, dtype=fields)
    for (name, _), a in zip(fields, arrays):
        out[name] = a
    return out


def records_frame(columns: dict, frame=None):
    """A pandas DataFrame of the columns when ``frame`` is True, or None and pandas imports;
    else the structured array of records_array."""
    if frame is None or frame:
        try:
            import pandas as pd
        except ImportError:
            if frame:
                raise
        else:
            return pd.DataFrame({k: np.asarray(v) for k, v in columns.items()})
    return records_array(columns)
