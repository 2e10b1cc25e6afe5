"""The selection layer (gmcc/selection/; docs/architecture.md "Layers"): the rules on a feasible
set (max-area, 2-D mean, 3-D mean; Finlayson & Hordley 1999 §3) with their worst cases (§4), the
angular errors, the ``gmcc select`` pipeline on one scene, and Forsyth's CRULE in 3-D.

The functions the extension defines are re-exported as they are (signatures, defaults and
docstrings in python/src/docstrings.h); ``select`` is Python: it routes the options between the
canonical side and the scene.
"""

from __future__ import annotations

from ._core import (  # noqa: F401  (re-exported)
    Crule3d,
    MapEstimate,
    Recovery,
    RuleErrors,
    SceneResult,
    Selection,
    Selection3,
    Truth,
    crule_3d,
    illuminant_angular_error_deg,
    map_angular_error_deg,
    max_area,
    mean_2d,
    mean_3d,
    reproduction_angular_error_deg,
    rules,
    select_maps,
    worst_case_illuminant_deg,
    worst_case_map_deg,
)
from . import _core
from ._doc import doc as _doc
from .geometry import Canonical, _SCENE_CHOICES, _prepared

__all__ = ["Crule3d", "MapEstimate", "Recovery", "RuleErrors", "SceneResult", "Selection", "Selection3", "Truth",
           "rules", "select", "select_maps", "max_area", "mean_2d", "mean_3d", "worst_case_map_deg",
           "worst_case_illuminant_deg", "map_angular_error_deg", "illuminant_angular_error_deg",
           "reproduction_angular_error_deg", "crule_3d"]


@_doc()
def select(canonical, image, truth=None, *, mask=None, black_level=0, saturation=None, dark=0,
           dark_fraction=None, bright_fraction=None, pixel_rule="none", **options) -> SceneResult:
    """Select a map for one image: feasible set, the three rules, worst cases, truth errors.

    The ``gmcc select`` pipeline (select_scene.h): the feasible set F of perspective diagonal
    maps (Finlayson & Hordley 1999 eqs. 7–9; ∩ C with ``illuminants``), the recovery policy
    when F is empty, the selection rules max-area, 2-D mean and 3-D mean (§3) with their worst
    cases (§4), and with ``truth`` each rule's errors against the true light. An empty or
    degenerate F is a result (``result.kind``), not an exception.

    Parameters
    ----------
    canonical : Canonical, or array_like of shape (n, 3)
        A Canonical from prepare_canonical (then only the per-scene ``options``), or the
        canonical colours, prepared here with ``options``.
    image : array_like of shape (n, 3), or numpy.ndarray of shape (H, W, 3)
        The image's colours (rows r, g, b), or a linear image (integer samples 0..65535 take
        the exact integer route; float samples are taken as the exact doubles) reduced by the
        pixel rules below (docs/conventions.md §8).
    truth : sequence of 3 numbers, optional
        The true light r, g, b (every channel > 0): the result's ``truth`` report.
    @pixel_rules@
    **options
        The keyword options of prepare_canonical, when ``canonical`` is colours. With a
        prepared Canonical, only the per-scene choices ``mean3d``, ``precision``, ``order``,
        ``samples``, ``seed`` and ``illuminant_worst_case``, for this call (the others keep the
        Canonical's).

    Returns
    -------
    SceneResult
        F, the three selections with their worst cases, the truth report and pixel counts.

    Raises
    ------
    ValueError
        Bad colours, image, truth or option, naming the argument, the row and the channel.
    TypeError
        An argument of the wrong type, or a canonical-side option given with a prepared
        Canonical.

    Examples
    --------
    >>> canonical = gmcc.prepare_canonical([[1, 1, 1], [2, 1, 1], [1, 2, 1], [2, 2, 1]])
    >>> r = gmcc.select(canonical, [[1, 1, 1], [3, 2, 2]], truth=(1, 1, 1))
    >>> r.kind, r.max_area.exact, r.truth.in_feasible_set
    ('polygon', (Fraction(4, 3), Fraction(2, 1)), True)
    """
    choices = {k: options[k] for k in _SCENE_CHOICES if k in options} if isinstance(canonical, Canonical) else {}
    return _core.select_prepared(_prepared(canonical, options, choices_allowed=True), image, truth, mask,
                                 black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule,
                                 choices)
