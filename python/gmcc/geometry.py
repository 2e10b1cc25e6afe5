"""The geometry layer (gmcc/geometry/; docs/architecture.md "Layers"): canonical gamuts, the
feasible set F of perspective diagonal maps (Finlayson & Hordley 1999 eqs. 7–10), lights as maps
and Finlayson's illumination constraint C, and the exact convex sets they are.

The functions the extension defines are re-exported as they are: their signatures, defaults and
docstrings are the binding's (python/src/docstrings.h). ``feasible_set`` is Python: it routes the
canonical side's options (prepare_canonical) or takes a prepared Canonical.
"""

from __future__ import annotations

from ._core import (  # noqa: F401  (re-exported)
    Canonical,
    Constraint,
    ConvexSet,
    ConvexSet3,
    canonical_gamut,
    illuminant_map,
    illumination_constraint,
    prepare_canonical,
)
from . import _core
from ._doc import doc as _doc

__all__ = ["Canonical", "Constraint", "ConvexSet", "ConvexSet3", "prepare_canonical", "canonical_gamut",
           "feasible_set", "illuminant_map", "illumination_constraint"]

# The per-scene choices (select_scene.h SceneChoices): a select call may give them with a prepared
# Canonical, for that call only; every other option belongs to the canonical side.
_SCENE_CHOICES = ("mean3d", "precision", "order", "samples", "seed", "illuminant_worst_case")


def _prepared(canonical, options, choices_allowed=False) -> Canonical:
    if isinstance(canonical, Canonical):
        fixed = sorted(k for k in options if not (choices_allowed and k in _SCENE_CHOICES))
        if fixed:
            raise TypeError("options (%s) belong to prepare_canonical; a prepared Canonical "
                            "already has them" % ", ".join(fixed))
        return canonical
    return _core.prepare_canonical(canonical, **options)


@_doc()
def feasible_set(canonical, image, *, mask=None, black_level=0, saturation=None, dark=0,
                 dark_fraction=None, bright_fraction=None, pixel_rule="none",
                 **options) -> ConvexSet:
    """The feasible set F of perspective diagonal maps of one image, alone.

    The maps taking every image chromaticity into G_c (Finlayson & Hordley 1999 eqs. 7–9 in
    perspective; feasible_set.h), ∩ C with ``illuminants`` (Finlayson 1996 §5), after the
    recovery policy ``on_empty``; no selection is made.

    Parameters
    ----------
    canonical : Canonical, or array_like of shape (n, 3)
        A Canonical from prepare_canonical (then no ``options``), or the canonical colours.
    image : array_like of shape (n, 3), or numpy.ndarray of shape (H, W, 3)
        The image's colours, or a linear image reduced by the pixel rules below.
    @pixel_rules@
    **options
        The keyword options of prepare_canonical, when ``canonical`` is colours.

    Returns
    -------
    ConvexSet
        F, exactly: a polygon, segment, point or empty.

    Raises
    ------
    ValueError
        Bad colours, image or option, naming the argument and the row.
    TypeError
        An argument of the wrong type, or ``options`` given with a prepared Canonical.

    Examples
    --------
    >>> F = gmcc.feasible_set([[1, 1, 1], [2, 1, 1], [1, 2, 1], [2, 2, 1]], [[1, 1, 1], [3, 2, 2]])
    >>> F.kind, F.area
    ('polygon', Fraction(1, 3))
    """
    scene = _core.feasible_prepared(_prepared(canonical, options), image, mask, black_level,
                                    saturation, dark, dark_fraction, bright_fraction, pixel_rule)
    return scene.feasible_set
