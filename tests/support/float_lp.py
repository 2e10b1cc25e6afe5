"""The float baseline of 3-D max-trace, independent of gmcc: SciPy's HiGHS on the same linear
program (tests/python/test_photographs.py checks gmcc's exact max-trace against it; bench/photo_speed.py
times it as the baseline a researcher writes)."""

import numpy as np
from scipy.optimize import linprog


def max_trace(A, b, q, unique_check=True):
    """Maximise d1 + d2 + d3 subject to A (d ∘ q) <= b for every row q of `q`, d >= 0 (SciPy's
    result), and, with unique_check and a solution, whether the maximiser is unique: each
    coordinate's range over the optimal face (a second LP fixes the trace and maximises, then
    minimises, it) below 1e-7 relative; else None."""
    rows = (A[:, None, :] * q[None, :, :]).reshape(-1, 3)
    rhs = np.repeat(b, len(q))
    r = linprog(-np.ones(3), A_ub=rows, b_ub=rhs, bounds=[(0, None)] * 3, method="highs")
    if not unique_check or r.status != 0:
        return r, None
    unique = True
    for k in range(3):
        ends = []
        for sign in (1, -1):
            c = np.zeros(3)
            c[k] = sign
            s = linprog(c, A_ub=rows, b_ub=rhs, A_eq=np.ones((1, 3)), b_eq=[-r.fun], bounds=[(0, None)] * 3,
                        method="highs")
            ends.append(sign * s.fun if s.status == 0 else np.nan)
        unique = unique and abs(ends[0] - ends[1]) <= 1e-7 * max(1.0, abs(r.x[k]))
    return r, unique
