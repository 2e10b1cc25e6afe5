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
"""

from __future__ import annotations

import os as _os

from . import _core
from ._core import (  # noqa: F401  (re-exported result classes)
    Canonical,
    Canonical3,
    CanonicalLearner2,
    CanonicalLearner3,
    ConvexSet,
    ConvexSet3,
    Constraint,
    Crule3d,
    ErrorStatistics,
    Estimate3,
    ImageColours,
    ImageSelection3,
    MapEstimate,
    Recovery,
    RuleErrors,
    SceneResult,
    Selection,
    Selection3,
    Truth,
)
from ._records import records_frame as _records_frame

__version__: str = _core.__version__
__commit__: str = _core.__commit__
__commit_date__: str = _core.__commit_date__

__all__ = [
    "__version__", "__commit__", "__commit_date__",
    "Canonical", "Canonical3", "CanonicalLearner2", "CanonicalLearner3", "ConvexSet", "ConvexSet3",
    "Constraint", "Crule3d", "ErrorStatistics", "Estimate3", "ImageColours", "ImageSelection3",
    "MapEstimate", "Recovery", "RuleErrors", "SceneResult", "Selection", "Selection3", "Truth",
    "rules", "prepare_canonical", "canonical_gamut", "feasible_set", "select", "read_image", "image_colours",
    "select_maps", "max_area", "mean_2d", "mean_3d", "worst_case_map_deg",
    "worst_case_illuminant_deg", "map_angular_error_deg", "illuminant_angular_error_deg",
    "reproduction_angular_error_deg", "illuminant_map", "illumination_constraint", "crule_3d",
    "prepare_canonical_3d", "estimate_3d", "benchmark",
    "error_statistics", "summarise", "reproduce_synthetic", "reproduce_camera",
    "reproduce_gehler_shi", "data_dir",
]

_OPTIONS = ("expand", "expand_policy", "illuminants", "canonical_illuminant", "on_empty", "mean3d",
            "precision", "order", "samples", "seed", "illuminant_worst_case", "nonpositive_blue")

# Parameter descriptions several functions share, spliced into their docstrings where a line
# holds only the marker ``@name@`` (numpydoc layout: 4 spaces before a name, 8 before its text).
_DOC_PARTS = {
    "canonical_options": """\
    expand : int, float, Fraction or str, default 0
        Enlarge G_c by this factor under ``expand_policy`` (the paper's "expanded by 10%", §4,
        is ``expand="0.1"``; a float 0.1 is the double nearest 1/10, not 1/10).
    expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
        How G_c is expanded; ``'multiplicative'`` keeps chromaticities positive.
    illuminants : array_like of shape (k, 3), optional
        Plausible lights r, g, b: F is intersected with their maps, Finlayson's illumination
        constraint C (Finlayson 1996 §5). Default None: no constraint.
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c: the illuminant-space errors and worst cases are taken for it.
    on_empty : {'none', 'grow-canonical', 'min-violation'}, default 'none'
        The recovery policy when F is empty (docs/cli.md "gmcc select").
    mean3d : {'analytic', 'quadrature', 'monte-carlo'}, default 'analytic'
        The route to the 3-D mean (mean_3d).
    precision : int, default 0
        analytic: the working precision in bits (0: automatic, else 53 to 1048576).
    order : int, default 12
        quadrature: Gauss–Legendre points per direction (1 to 256).
    samples : int, default 1000000
        monte-carlo: the number of sample points.
    seed : int, default 1
        monte-carlo: the seed of its mt19937_64 generator.
    illuminant_worst_case : bool, default True
        Also compute each rule's worst case in illuminant space (docs/derivations.md §3.2).
    nonpositive_blue : {'drop', 'reject'}, default 'drop'
        A colour with b <= 0 has no chromaticity: dropped and counted, or refused (ValueError).
""",
    "pixel_rules": """\
    mask : numpy.ndarray of bool, shape (H, W), optional
        True for the pixels to use (default None: every pixel).
    black_level : int or float, default 0
        Subtracted from every raw sample; negative results become 0.
    saturation : int or float, optional
        A pixel with any raw channel >= it is dropped (default None: none is).
    dark : int or float, default 0
        A pixel with a channel below it (after the black level) is dropped.
    dark_fraction, bright_fraction : int, float, Fraction or str, optional
        A pixel with a channel below ``dark_fraction``·M, or above ``bright_fraction``·M, is
        dropped; M is the image's largest value after the black level (exact fractions, e.g.
        ``Fraction(5, 255)``). Default None: no such rule.
    pixel_rule : {'none', 'gijsenij'}, default 'none'
        ``'gijsenij'``: Gijsenij et al. (2010)'s rule, the fractions 5/255 and 245/255 (not
        with ``dark_fraction`` or ``bright_fraction``).
""",
    "records": """\
    data : str, optional
        The folder of the spectral data (default None: ``data_dir()``).
    frame : bool, optional
        True: a pandas DataFrame (ImportError without pandas); False: a numpy structured array;
        None (the default): a DataFrame when pandas imports, else the structured array.
""",
    "scene_records": """\
    Returns
    -------
    pandas.DataFrame or numpy.ndarray
        One record per scene, in the order light, surface count, scene: ``light``,
        ``surfaces``, ``scene``, ``kind`` (of F), ``area`` (F's, as a double), ``drawn`` (the
        surfaces' indices, space-separated) and for each rule (``max_area``, ``mean_2d``,
        ``mean_3d``, then the CRULE rules) its map ``*_map_x``, ``*_map_y`` and errors in
        degrees ``*_error_deg`` (map space, the paper's), ``*_worst_case_deg``,
        ``*_illuminant_error_deg`` (recovery) and ``*_reproduction_error_deg``; NaN where the
        rule gave no map (or, for the last two, a map with a component <= 0). The same records
        as ``gmcc reproduce ... --scenes-out`` (docs/reproduction.md "Per-scene records").
""",
}


def _whole(name, value, lo, hi):
    """`value` as an int in [lo, hi], or a ValueError / TypeError naming the argument (instead of
    the extension's raw signature dump)."""
    if isinstance(value, bool) or not isinstance(value, int) and not hasattr(value, "__index__"):
        raise TypeError(f"{name}: expected an integer, got {type(value).__name__} {value!r}")
    value = value.__index__()
    if not lo <= value <= hi:
        raise ValueError(f"{name}: must be an integer from {lo} to {hi}, not {value}")
    return value  # numpy integers too (they have __index__)


# Most scene records an experiment may return from Python: every record is kept (416 bytes in the
# array, more while the run holds its own), where the command line streams them to --scenes-out.
_MAX_RECORDS = 4 * 10**6


def _experiment_counts(min_surfaces, max_surfaces, scenes, seed, threads, lights):
    counts = (_whole("min_surfaces", min_surfaces, 1, 2**31 - 1), _whole("max_surfaces", max_surfaces, 1, 2**31 - 1),
              _whole("scenes", scenes, 1, 10**6), _whole("seed", seed, 0, 2**64 - 1),
              _whole("threads", threads, 0, 256))
    records = len(lights) * max(counts[1] - counts[0] + 1, 0) * counts[2]
    if records > _MAX_RECORDS:
        raise ValueError(f"scenes: {records} scene records would be kept in memory, more than the "
                         f"{_MAX_RECORDS} a Python run returns; run larger studies with gmcc reproduce "
                         "--scenes-out (records streamed to the file) or in shards (--shard, gmcc merge)")
    return counts


def _doc(f):
    """Splice the shared parameter descriptions (_DOC_PARTS) into f's docstring (none under
    python -OO)."""
    for name, text in _DOC_PARTS.items():
        if f.__doc__:
            f.__doc__ = f.__doc__.replace("    @" + name + "@\n", text)
    return f


@_doc
def prepare_canonical(canonical, *, expand=0, expand_policy="none", illuminants=None,
                      canonical_illuminant=(1, 1, 1), on_empty="none", mean3d="analytic",
                      precision=0, order=12, samples=1000000, seed=1, illuminant_worst_case=True,
                      nonpositive_blue="drop") -> Canonical:
    """Prepare the canonical side once for many images: G_c and the options of select.

    The perspective chromaticities (r/b, g/b) of the canonical colours and their exact hull
    G_c (Finlayson & Hordley 1999 eq. 10; prepare_canonical.h), expanded as asked, with
    Finlayson's illumination constraint C when ``illuminants`` are given. The options are
    those of ``gmcc select`` (docs/cli.md "gmcc select") and travel with the result to every
    select and feasible_set call.

    Parameters
    ----------
    canonical : array_like of shape (n, 3), or sequence of rows r, g, b
        The canonical colours: each channel finite and >= 0 (a float is the exact rational of
        its value, a str is read as the command line reads a file).
    @canonical_options@

    Returns
    -------
    Canonical
        G_c (``.gamut``), C (``.constraint``) and the counts; immutable and thread-safe.

    Raises
    ------
    ValueError
        A bad colour or option, naming the argument and the row (0-based).
    TypeError
        An argument of the wrong type (e.g. a bool where a number belongs).
    """
    return _core.prepare_canonical(
        canonical, expand=expand, expand_policy=expand_policy, illuminants=illuminants,
        canonical_illuminant=canonical_illuminant, on_empty=on_empty, mean3d=mean3d,
        precision=precision, order=order, samples=samples, seed=seed,
        illuminant_worst_case=illuminant_worst_case, nonpositive_blue=nonpositive_blue)


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


def canonical_gamut(canonical, *, expand=0, expand_policy="none",
                    nonpositive_blue="drop") -> ConvexSet:
    """The canonical gamut G_c of a set of canonical colours, exactly.

    The exact convex hull of the colours' perspective chromaticities (r/b, g/b) (Finlayson &
    Hordley 1999 eq. 10; canonical_gamut.h), expanded by ``expand`` under ``expand_policy``.

    Parameters
    ----------
    canonical : array_like of shape (n, 3), or sequence of rows r, g, b
        The canonical colours (channels finite and >= 0).
    expand : int, float, Fraction or str, default 0
        Enlarge G_c by this factor (``"0.1"``: exactly 10%).
    expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
        How G_c is expanded.
    nonpositive_blue : {'drop', 'reject'}, default 'drop'
        A colour with b <= 0 is dropped, or refused with ValueError.

    Returns
    -------
    ConvexSet
        G_c: a polygon, or a degenerate kind (segment, point, empty).

    Raises
    ------
    ValueError
        A bad colour or option, naming the argument and the row.
    TypeError
        An argument of the wrong type.
    """
    return _core.prepare_canonical(canonical, expand=expand, expand_policy=expand_policy,
                                   nonpositive_blue=nonpositive_blue).gamut


@_doc
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
    """
    choices = {k: options[k] for k in _SCENE_CHOICES if k in options} if isinstance(canonical, Canonical) else {}
    return _core.select_prepared(_prepared(canonical, options, choices_allowed=True), image, truth, mask,
                                 black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule,
                                 choices)


@_doc
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
    """
    scene = _core.feasible_prepared(_prepared(canonical, options), image, mask, black_level,
                                    saturation, dark, dark_fraction, bright_fraction, pixel_rule)
    return scene.feasible_set


def read_image(path, *, black_level=None, saturation=None):
    """Read a linear camera image: PNG, TIFF or a camera raw file, as the command line does.

    camera_image.h and raw_file.h (docs/conventions.md §8, "Camera raw files"): PNG and TIFF are
    read as stored (no gamma, no colour conversion); a raw file (DNG, CR2, NEF, ARW, … by
    extension) through LibRaw without demosaicing, white balance, colour matrix or gamma, each
    2×2 Bayer quad one pixel (2·(R − k), (G₁ − k) + (G₂ − k), 2·(B − k)), saturated quads set to
    65535 in every channel (Finlayson & Hordley 1999 §2 assume linear sensor responses).

    Parameters
    ----------
    path : str or os.PathLike
        The image file.
    black_level : int, optional
        A raw file: replaces its own black levels (every photosite). PNG and TIFF: returned in
        ``rules`` as given (absent: 0).
    saturation : int, optional
        A raw file: its white level, replacing its own. PNG and TIFF: returned in ``rules``.

    Returns
    -------
    image : numpy.ndarray
        The pixels, shape (H, W, 3), dtype uint16 (a raw file: H and W half the mosaic's).
    rules : dict
        ``black_level`` and ``saturation`` to pass to the pixel rules of ``image_colours``,
        ``estimate_3d``, ``select`` or a learner's ``add`` as ``**rules`` (a raw file: 0 and
        65535, its black level being subtracted already).
    info : dict
        ``bits`` (8 or 16) and ``raw``: None, or for a raw file (by its extension, or a TIFF of
        raw sensor data by its content) its ``pattern`` (e.g. 'RGGB'), ``black`` (the level at
        each of the quad's four positions, in the pattern's order), ``black_min``, ``black_max``,
        ``white``, ``camera`` and ``saturated`` (quads).

    Raises
    ------
    ValueError
        The file cannot be read, is not a PNG, TIFF or raw file gmcc reads (the message names
        the file and the problem), or a level is out of range.
    """
    out = _core.read_image(_os.fspath(path), black_level, saturation)
    rules = {"black_level": out["black_level"], "saturation": out["saturation"]}
    return out["image"], rules, {"bits": out["bits"], "raw": out["raw"]}


@_doc
def image_colours(image, *, mask=None, black_level=0, saturation=None, dark=0,
                  dark_fraction=None, bright_fraction=None, pixel_rule="none",
                  colour_set="hull", prefilter=0) -> ImageColours:
    """The colours the geometry takes from a linear camera image, after the pixel rules.

    The pixel rules of docs/conventions.md §8 (image_pixels.h), Gijsenij, Gevers & van de
    Weijer (2010)'s dark and bright rule among them, and the reduction to the colours
    the feasible set depends on: the chromaticity hull's vertices for the 2-D route
    (Finlayson & Hordley 1999 eqs. 7–9 need only those), the 3-D hull's for the 3-D route.

    Parameters
    ----------
    image : numpy.ndarray, shape (H, W, 3)
        Linear samples: integers 0..65535 (the exact integer route), or floats, where each
        sample minus the black level must be exact in double (else ValueError).
    @pixel_rules@
    colour_set : {'hull', 'distinct', 'hull-3d'}, default 'hull'
        ``'hull'``: the chromaticity lifts (x, y, 1) of the chromaticity hull's vertices, all
        the 2-D route depends on (read them as ``.chromaticity_lifts``; ``.colours`` refuses
        them, since they are not pixel colours); ``'distinct'``: every distinct pixel colour;
        ``'hull-3d'``: the pixel colours on their exact 3-D hull.
    prefilter : int or float, default 0
        A Gaussian pre-filter's sigma in pixels (integer images; 0 for none): the kept pixels'
        colours are taken from the smoothed image (computed in double, taken exactly).

    Returns
    -------
    ImageColours
        The colours, what they are (``colour_set``) and the pixel counts.

    Raises
    ------
    ValueError
        A bad image, mask or rule (a negative or non-finite sample, a mask of the wrong shape,
        ``pixel_rule='gijsenij'`` with a fraction), naming the argument and the pixel.
    TypeError
        An argument of the wrong type.
    """
    return _core.image_colours(image, mask, black_level, saturation, dark, dark_fraction,
                               bright_fraction, pixel_rule, colour_set, prefilter)


def rules() -> list:
    """The selection rules on the 2-D feasible set, in report order (Finlayson & Hordley 1999 §3).

    Returns
    -------
    list of str
        Their names, ``['max_area', 'mean_2d', 'mean_3d']``: the keys of ``select_maps``' and
        ``SceneResult.selections``' dicts, and the names of SceneResult's and Truth's per-rule
        attributes.
    """
    return _core.rules()


def select_maps(feasible_set, *, mean3d="analytic", precision=0, order=12, samples=1000000,
                seed=1, canonical_illuminant=None) -> dict:
    """The three selection rules on a feasible set, each with its worst cases.

    max-area, 2-D mean and 3-D mean of F (Finlayson & Hordley 1999 §3; select_maps.h), each
    with its map-space worst case (§4) and, given ``canonical_illuminant``, its worst case in
    illuminant space (docs/derivations.md §3.2).

    Parameters
    ----------
    feasible_set : ConvexSet
        F, e.g. from feasible_set.
    mean3d : {'analytic', 'quadrature', 'monte-carlo'}, default 'analytic'
        The route to the 3-D mean.
    precision : int, default 0
        analytic: the working precision in bits (0: automatic).
    order : int, default 12
        quadrature: points per direction.
    samples : int, default 1000000
        monte-carlo: sample points.
    seed : int, default 1
        monte-carlo: the generator's seed.
    canonical_illuminant : sequence of 3 numbers, optional
        The canonical light c; given, each rule's illuminant-space worst case too.

    Returns
    -------
    dict of str to Selection or None
        ``{'max_area': ..., 'mean_2d': ..., 'mean_3d': ...}``; the values are None when F is
        empty.

    Raises
    ------
    ValueError
        A bad option or canonical light.
    TypeError
        ``feasible_set`` is not a ConvexSet, or an option of the wrong type.
    """
    return _core.select_maps(feasible_set, mean3d=mean3d, precision=precision, order=order,
                             samples=samples, seed=seed, canonical_illuminant=canonical_illuminant)


def max_area(feasible_set) -> MapEstimate:
    """The max-area map of a feasible set, exactly.

    argmax m1·m2 over F, the map that makes the corrected image as colourful as possible
    (Finlayson & Hordley 1999 §3.1; Forsyth 1990's maximum-volume map in perspective;
    max_area.h, docs/derivations.md §2).

    Parameters
    ----------
    feasible_set : ConvexSet
        F, not empty.

    Returns
    -------
    MapEstimate
        The rule's map, exact (``.exact``, Fractions).

    Raises
    ------
    ValueError
        F is empty.
    TypeError
        ``feasible_set`` is not a ConvexSet.
    """
    return _core.max_area(feasible_set)


def mean_2d(feasible_set) -> MapEstimate:
    """The 2-D mean of a feasible set, its centroid, exactly.

    The centroid of F in the perspective plane (Finlayson & Hordley 1999 §3.2; mean_2d.h).

    Parameters
    ----------
    feasible_set : ConvexSet
        F, not empty.

    Returns
    -------
    MapEstimate
        The rule's map, exact (``.exact``, Fractions).

    Raises
    ------
    ValueError
        F is empty.
    TypeError
        ``feasible_set`` is not a ConvexSet.
    """
    return _core.mean_2d(feasible_set)


def mean_3d(feasible_set, *, method="analytic", precision=0, order=12, samples=1000000,
            seed=1) -> MapEstimate:
    """The 3-D mean of a feasible set by one route, with its error statement.

    The centroid of (cone over F) ∩ unit ball, projected back to the plane (Finlayson &
    Hordley 1999 §3.2; mean_3d.h, docs/math.md §2). Irrational in general: the nearest double
    with its error bound.

    Parameters
    ----------
    feasible_set : ConvexSet
        F, not empty.
    method : {'analytic', 'quadrature', 'monte-carlo'}, default 'analytic'
        ``'analytic'``: the closed form, certified enclosure; ``'quadrature'``: Duffy–Gauss–
        Legendre; ``'monte-carlo'``: the paper's sampling.
    precision : int, default 0
        analytic: the working precision in bits (0: automatic, else 53 to 1048576).
    order : int, default 12
        quadrature: Gauss–Legendre points per direction (1 to 256).
    samples : int, default 1000000
        monte-carlo: the number of sample points.
    seed : int, default 1
        monte-carlo: the seed of its mt19937_64 generator.

    Returns
    -------
    MapEstimate
        The map as doubles with ``error_bound``, ``error_bounds`` and (analytic) ``enclosure``.

    Raises
    ------
    ValueError
        F is empty, or a bad option.
    TypeError
        ``feasible_set`` is not a ConvexSet, or an option of the wrong type.
    """
    return _core.mean_3d(feasible_set, method=method, precision=precision, order=order,
                         samples=samples, seed=seed)


def worst_case_map_deg(feasible_set, map) -> float:
    """The largest map-space angle between a map and any map of a feasible set, degrees.

    The worst case of Finlayson & Hordley (1999) §4, attained at a vertex of F
    (docs/derivations.md §3.1; worst_case.h).

    Parameters
    ----------
    feasible_set : ConvexSet
        F, not empty.
    map : sequence of 2 numbers
        The perspective map (m1, m2), taken exactly.

    Returns
    -------
    float
        Degrees.

    Raises
    ------
    ValueError
        F is empty, or a bad map.
    TypeError
        An argument of the wrong type.
    """
    return _core.worst_case_map_deg(feasible_set, map)


def worst_case_illuminant_deg(feasible_set, map, canonical_illuminant=(1, 1, 1)) -> float:
    """The largest illuminant-space angle between a map's light and any light of F, degrees.

    The worst case of Finlayson & Hordley (1999) §4 measured between the illuminants c ⊘ m
    (docs/derivations.md §3.2; worst_case_illuminant.h).

    Parameters
    ----------
    feasible_set : ConvexSet
        F, not empty, every vertex with both components > 0.
    map : sequence of 2 numbers
        The perspective map (m1, m2), both > 0.
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c.

    Returns
    -------
    float
        Degrees.

    Raises
    ------
    ValueError
        F is empty or touches an axis, or a component of ``map`` is <= 0.
    TypeError
        An argument of the wrong type.
    """
    return _core.worst_case_illuminant_deg(feasible_set, map, canonical_illuminant)


def map_angular_error_deg(estimate, truth) -> float:
    """The paper's map-space angular error between two perspective maps, degrees.

    The angle between (m1, m2, 1) and (t1, t2, 1) (Finlayson & Hordley 1999 §4;
    angular_error.h), certified to about one ulp.

    Parameters
    ----------
    estimate : sequence of 2 numbers
        The estimated map (m1, m2), taken exactly.
    truth : sequence of 2 numbers
        The true map (t1, t2), taken exactly.

    Returns
    -------
    float
        Degrees.

    Raises
    ------
    ValueError
        A map that is not two finite numbers.
    TypeError
        An argument of the wrong type.
    """
    return _core.map_angular_error_deg(estimate, truth)


def illuminant_angular_error_deg(estimate, truth, canonical_illuminant=(1, 1, 1)) -> float:
    """The recovery (illuminant-space) angular error of a map against the true map, degrees.

    The angle between the illuminants c ⊘ (m, 1) the two maps imply (Hordley & Finlayson 2006;
    docs/math.md §3; angular_error.h).

    Parameters
    ----------
    estimate : sequence of 2 numbers
        The estimated map, both components > 0.
    truth : sequence of 2 numbers
        The true map, both components > 0.
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c.

    Returns
    -------
    float
        Degrees.

    Raises
    ------
    ValueError
        A component <= 0, or a bad number.
    TypeError
        An argument of the wrong type.
    """
    return _core.illuminant_angular_error_deg(estimate, truth, canonical_illuminant)


def reproduction_angular_error_deg(estimate, truth) -> float:
    """The reproduction angular error of a map against the true map, degrees.

    The angle between the white corrected by the estimate and white (Finlayson & Zakizadeh
    2014; docs/math.md §3; angular_error.h); it does not depend on the canonical light.

    Parameters
    ----------
    estimate : sequence of 2 numbers
        The estimated map, both components > 0.
    truth : sequence of 2 numbers
        The true map, both components > 0.

    Returns
    -------
    float
        Degrees.

    Raises
    ------
    ValueError
        A component <= 0, or a bad number.
    TypeError
        An argument of the wrong type.
    """
    return _core.reproduction_angular_error_deg(estimate, truth)


def illuminant_map(light, canonical_illuminant=(1, 1, 1)):
    """The perspective map of a light: c ⊘ e as (d1/d3, d2/d3), exactly.

    The map that takes colours under the light e to the canonical light c (Finlayson 1996 §5;
    illumination_constraint.h).

    Parameters
    ----------
    light : sequence of 3 numbers
        The light e = (r, g, b), every channel > 0.
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c.

    Returns
    -------
    tuple of (Fraction, Fraction)
        The map, exact.

    Raises
    ------
    ValueError
        A channel <= 0, or a bad number.
    TypeError
        An argument of the wrong type.
    """
    return _core.illuminant_map(light, canonical_illuminant)


def illumination_constraint(illuminants, canonical_illuminant=(1, 1, 1)) -> ConvexSet:
    """Finlayson's illumination constraint C: the hull of a set of lights' maps, exactly.

    C = conv{c ⊘ e_j} in perspective, the maps of plausible lights (Finlayson 1996 §5;
    illumination_constraint.h).

    Parameters
    ----------
    illuminants : array_like of shape (k, 3)
        The plausible lights e_j, every channel > 0.
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c.

    Returns
    -------
    ConvexSet
        C.

    Raises
    ------
    ValueError
        A light with a channel <= 0 (naming its row), or a bad number.
    TypeError
        An argument of the wrong type.
    """
    return _core.illumination_constraint(illuminants, canonical_illuminant)


def crule_3d(canonical, image, *, black="include") -> Crule3d:
    """Forsyth's CRULE in 3-D on colours: F3, its volume, max-volume and centroid.

    The exact polytope F3 of diagonal maps (d1, d2, d3) taking every image colour into the
    canonical gamut (Forsyth 1990 §3; crule_3d.h, docs/math.md §1b), with the max-volume and
    centroid selections (Barnard, Cardei & Funt 2002) and their worst cases.

    Parameters
    ----------
    canonical : array_like of shape (n, 3), or ImageColours
        The canonical colours (an ImageColours must hold pixel colours).
    image : array_like of shape (m, 3), or ImageColours
        The image colours (an ImageColours must hold pixel colours).
    black : {'include', 'exclude'}, default 'include'
        Whether black (0, 0, 0) joins the canonical gamut.

    Returns
    -------
    Crule3d
        F3, its volume and the two selections.

    Raises
    ------
    ValueError
        Bad colours, chromaticity lifts, or an unknown ``black``.
    TypeError
        An argument of the wrong type.
    """
    return _core.crule_3d(canonical, image, black=black)


def prepare_canonical_3d(canonical, *, black="include") -> Canonical3:
    """A 3-D canonical gamut G_c3 prepared once for many images.

    The exact half-spaces of the hull of the canonical colours (Forsyth 1990 §3;
    feasible_set_3d.h), for estimate_3d.

    Parameters
    ----------
    canonical : array_like of shape (n, 3), or ImageColours
        Pixel colours under the canonical light (e.g. ``CanonicalLearner3.gamut()``). An
        ImageColours of chromaticity lifts is refused.
    black : {'include', 'exclude'}, default 'include'
        Whether black (0, 0, 0) joins the hull (with it F3 is never empty).

    Returns
    -------
    Canonical3
        G_c3, immutable and thread-safe.

    Raises
    ------
    ValueError
        Bad colours, chromaticity lifts, or an unknown ``black``.
    TypeError
        An argument of the wrong type.
    """
    return _core.prepare_canonical_3d(canonical, black=black)


@_doc
def estimate_3d(canonical, image, truth=None, *, rules=None, centroid="certified",
                canonical_illuminant=(1, 1, 1), illuminants=None, mask=None, black_level=0, saturation=None,
                dark=0, dark_fraction=None, bright_fraction=None, pixel_rule="none",
                colour_set="hull-3d") -> Estimate3:
    """3-D gamut mapping on one image: F3 and the rules max-volume, centroid and max-trace.

    The exact feasible set F3 of diagonal maps taking the image's pixel colours into the
    canonical gamut (Forsyth 1990 §3, on whole images as Gijsenij, Gevers & van de Weijer
    2010 §3; estimate_3d.h), and the three rules with the light each implies
    (docs/photographs.md §3).

    Parameters
    ----------
    canonical : Canonical3
        From prepare_canonical_3d or CanonicalLearner3.prepare.
    image : numpy.ndarray (H, W, 3), ImageColours, or array_like (n, 3)
        An image goes through the pixel rules below; an ImageColours must hold pixel colours
        (chromaticity lifts are refused); colours are taken as they are.
    truth : sequence of 3 numbers, optional
        The true light (every channel > 0): ``truth_in_feasible`` and each rule's
        ``recovery_error_deg`` and ``map_error_deg``.
    rules : iterable of str, optional
        Of 'max_volume', 'centroid', 'max_trace' (default None: all three).
    centroid : {'certified', 'exact'}, default 'certified'
        The centroid as a certified double, or in Q (max-volume and max-trace are exact).
    canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
        The canonical light c; a map d implies the light c ⊘ d.
    illuminants : iterable of sequences of 3 numbers, optional
        Plausible lights (every channel > 0): F3 is intersected with the cone of their maps
        c ⊘ l (the illumination constraint in 3-D, Barnard's ECRULE; docs/math.md §1e), and
        every rule, worst case and truth test reads F3 ∩ cone.
    @pixel_rules@
    colour_set : {'hull-3d', 'distinct'}, default 'hull-3d'
        The colours an image is reduced to ('hull' gives chromaticity lifts: refused).

    Returns
    -------
    Estimate3
        F3, its kind, each rule's ImageSelection3 and the pixel counts. F3's vertices in lowest
        terms are made on the first read of ``feasible_set`` (the rules do not need them:
        docs/math.md §1b "The lazy form").

    Raises
    ------
    ValueError
        Bad image, colours, truth or option (an unknown rule, chromaticity lifts, an image with
        no usable pixel), naming the argument.
    TypeError
        An argument of the wrong type (e.g. ``canonical`` not a Canonical3).
    """
    return _core.estimate_3d(canonical, image, truth, rules=rules, centroid=centroid,
                             canonical_illuminant=canonical_illuminant, illuminants=illuminants, mask=mask,
                             black_level=black_level, saturation=saturation, dark=dark,
                             dark_fraction=dark_fraction, bright_fraction=bright_fraction,
                             pixel_rule=pixel_rule, colour_set=colour_set)


def benchmark(images, truths, *, folds=None, folds_file=None, methods=None, intensity="max",
              black="include", threads=0, black_level=None, saturation=None, dark=0,
              dark_fraction=None, bright_fraction=None, pixel_rule="none", edge_sigma=1.0, frame=True):
    """Benchmark every gamut method and baseline on a dataset of linear images, fold by fold.

    ``gmcc benchmark`` from Python (benchmark.h; docs/photographs.md §6): every image is
    estimated by canonical gamuts (2-D and 3-D) learned only from the other folds' images, by
    the 3-D rules (Forsyth 1990 §3; Gijsenij, Gevers & van de Weijer 2010 §3), the paper's 2-D
    rules (Finlayson & Hordley 1999 §3) and the baselines, all on the same kept pixels; the
    numbers are the command line's.

    Parameters
    ----------
    images : str or os.PathLike
        The folder the truth table's image paths are relative to.
    truths : str or os.PathLike
        The truth table, ``image,r,g,b[,black_level][,saturation][,mask][,chart]``.
    folds : int, optional
        K folds (2 or more): the image on data line i (from 0) is in fold i mod K.
    folds_file : str or os.PathLike, optional
        ``image,fold``: the dataset's own split (give this or ``folds``).
    methods : list of str, optional
        Methods by name (default None: the eleven pixel gamut methods and baselines). The
        edge-based gamut methods of Gijsenij, Gevers & van de Weijer (2010 §4), each with
        max-trace, are asked for by name: ``gm3d-edge1-max-trace``, ``gm3d-edge2-max-trace``
        (1st- and 2nd-order derivative gamuts), ``gm3d-1jet-max-trace`` (pixel and 1st-order
        feasible sets intersected), ``gm3d-2jet-max-trace`` (and the 2nd order); and each gamut
        rule with the illumination constraint of the fold's training lights:
        ``gm3d-max-trace-constrained``, ``gm3d-max-volume-constrained``,
        ``gm3d-centroid-constrained``, ``gm2d-max-area-constrained``, ``gm2d-mean-2d-constrained``,
        ``gm2d-mean-3d-constrained``; and ``gcie``, Finlayson, Hordley & Tastl's (2006)
        classification among the training lights (docs/photographs.md §7a, docs/math.md §1f).
    intensity : {'max', 'none'}, default 'max'
        How each training image is scaled before the 3-D union (``gmcc benchmark --intensity``):
        its largest white-balanced channel made 1, or as it is.
    black : {'include', 'exclude'}, default 'include'
        Whether black joins the 3-D canonical gamut.
    threads : int, default 0
        Worker threads; 0 for the machine's cores. The result does not depend on it.
    black_level : int, optional
        Subtracted from every sample (the truth table's column overrides it per image); absent:
        0 for PNG and TIFF, a camera raw file's own black levels (docs/conventions.md §8).
    saturation : int, optional
        Pixels with a raw channel >= it are dropped (the table's column overrides it); for a
        camera raw file, its white level (absent: the file's own).
    dark : int, default 0
        Pixels with a channel below it (after the black level) are dropped.
    dark_fraction, bright_fraction : int, float, Fraction or str, optional
        The dark and bright rules as fractions of the image's maximum (as image_colours).
    pixel_rule : {'none', 'gijsenij'}, default 'none'
        ``'gijsenij'``: Gijsenij et al. (2010)'s rule, the fractions 5/255 and 245/255.
    edge_sigma : float, default 1.0
        The Gaussian derivative scale in pixels, in (0, 64], of the edge-based methods and of
        the grey-edge baselines.
    frame : bool, default True
        Return pandas DataFrames (when pandas is installed) rather than lists of dicts.

    Returns
    -------
    summary : pandas.DataFrame or list of dict
        One row per method: method, images, answered, empty, unanswered_other (answered +
        empty + unanswered_other = images), and the recovery error's
        mean_deg, median_deg, trimean_deg, best25_deg, worst25_deg, p95_deg, max_deg (None when
        no image was answered), truth_in_feasible, worst_case_covers, worst_case_correlation.
    records : pandas.DataFrame or list of dict
        One row per image and method: image, fold, method, light, error_deg, answered,
        fallback, unanswered (why the method gave no light of its own, or None),
        feasible_kind, feasible_vertices, truth_in_feasible (decided exactly; None without a
        feasible set), worst_case_deg, worst_case_space ('illuminant' or 'map': the space the
        worst case bounds) and worst_case_space_error_deg (the error in that space).

    Raises
    ------
    ValueError
        A bad truth table, folds file or image (naming the file and line), neither or both of
        ``folds`` and ``folds_file``, an unknown method, a bad pixel rule or edge_sigma.
    TypeError
        An argument of the wrong type.
    """
    summary, records = _core.benchmark(
        str(images), str(truths), folds=folds,
        folds_file=None if folds_file is None else str(folds_file), methods=methods,
        intensity=intensity, black=black, threads=threads, black_level=black_level,
        saturation=saturation, dark=dark, dark_fraction=dark_fraction,
        bright_fraction=bright_fraction, pixel_rule=pixel_rule, edge_sigma=edge_sigma)
    if frame:
        try:
            import pandas
        except ImportError:
            return summary, records
        return pandas.DataFrame(summary), pandas.DataFrame(records)
    return summary, records


def error_statistics(values) -> ErrorStatistics:
    """The statistics the field reports for a list of angular errors.

    n, mean, standard error, median (Hordley & Finlayson 2006), trimean, best and worst 25%,
    95th percentile and maximum, each as defined in docs/reproduction.md "Statistics"
    (error_statistics.h; quantiles of Hyndman & Fan's type 7, numpy's default), the same
    function every experiment table uses (Finlayson & Hordley 1999 §4 report the mean).

    Parameters
    ----------
    values : array_like of float
        The errors, in the order the mean sums them; any shape (flattened).

    Returns
    -------
    ErrorStatistics
        The statistics (every one NaN, undefined, when ``values`` is empty; standard_error
        NaN for one value).

    Raises
    ------
    ValueError
        A value is NaN or infinite (naming its index).
    """
    return _core.error_statistics(values)


def summarise(records, rule="mean_3d", error="error_deg", by=("light", "surfaces")):
    """error_statistics of one rule's error per group of experiment records.

    The cells of the experiments' tables (Finlayson & Hordley 1999 §4, Figs. 3 and 5): the
    records of reproduce_synthetic, reproduce_camera or reproduce_gehler_shi grouped by the
    columns ``by``, over the scenes where the rule gave a map (empty feasible sets are left
    out, as in the paper), in the records' order (docs/reproduction.md "Statistics").

    Parameters
    ----------
    records : numpy.ndarray (structured) or pandas.DataFrame
        Records of an experiment.
    rule : str, default 'mean_3d'
        The rule or baseline: ``max_area``, ``mean_2d``, ``mean_3d``, ``crule_max_volume``,
        ``crule_centroid``, ``grey_world``, ``max_rgb``.
    error : str, default 'error_deg'
        Which error: ``error_deg`` (map space), ``worst_case_deg``, ``illuminant_error_deg``
        (recovery) or ``reproduction_error_deg``.
    by : sequence of str, default ('light', 'surfaces')
        The grouping columns (gehler-shi's table cells: ``('group', 'surfaces')``).

    Returns
    -------
    dict of tuple to ErrorStatistics
        One entry per group, keyed by the values of ``by``, in order of first appearance.

    Raises
    ------
    ValueError
        The records have no column ``rule + '_' + error`` or no column of ``by``.
    """
    import numpy as np
    column = rule + "_" + error
    if hasattr(records, "to_records"):
        records = records.to_records(index=False)
    keys = [tuple(r[k].item() if hasattr(r[k], "item") else r[k] for k in by) for r in records]
    values = np.asarray(records[column], dtype=float)
    out = {}
    for key in dict.fromkeys(keys):
        sel = np.array([k == key for k in keys]) & np.isfinite(values)
        out[key] = _core.error_statistics(values[sel])
    return out


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


@_doc
def reproduce_synthetic(*, lights=("D75", "D100", "P2856", "P15000"), canonical="D55",
                        min_surfaces=1, max_surfaces=11, scenes=500, seed=1, expand=0,
                        expand_policy="none", crule=False, threads=0, data=None, frame=None):
    """The synthetic experiment of Finlayson & Hordley (1999) §4, Fig. 3, one record per scene.

    ``gmcc reproduce synthetic`` (synthetic_experiment.h, gamut_experiment.h;
    docs/reproduction.md §1): narrow-band sensors at 610, 540 and 450 nm, the 1269 Munsell
    chips, scenes of n distinct chips under each test light, every rule scored against the
    true map. The same seed gives the same records, whatever ``threads``.

    Parameters
    ----------
    lights : sequence of str, default ('D75', 'D100', 'P2856', 'P15000')
        The test lights: CIE daylights ``D<cct/100>`` and Planckians ``P<kelvin>``.
    canonical : str, default 'D55'
        The canonical light.
    min_surfaces : int, default 1
        The smallest surface count n.
    max_surfaces : int, default 11
        The largest surface count n (``--surfaces``).
    scenes : int, default 500
        Seeded scenes per light and surface count.
    seed : int, default 1
        The run's seed (docs/reproduction.md "Scene generator").
    expand : int, float, Fraction or str, default 0
        Enlarge the canonical gamut by this factor (``"0.1"``: exactly 10%).
    expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
        How it is enlarged.
    crule : bool, default False
        Also Forsyth's 3-D CRULE (``crule_max_volume``, ``crule_centroid``; slow).
    threads : int, default 0
        Worker threads (0: all cores); the records do not depend on it.
    @records@

    @scene_records@

    Raises
    ------
    ValueError
        An unknown light, bad surface counts or expansion, unreadable data.
    TypeError
        An argument of the wrong type.
    """
    min_surfaces, max_surfaces, scenes, seed, threads = _experiment_counts(
        min_surfaces, max_surfaces, scenes, seed, threads, lights)
    result = _core.run_experiment("synthetic", data or data_dir(), canonical, list(lights), "sfu",
                                  min_surfaces, max_surfaces, scenes, seed, expand, expand_policy,
                                  crule, threads)
    return _records_frame(result["columns"], frame)


@_doc
def reproduce_camera(*, lights=("syl-50MR16Q", "solux-4700+3202"), canonical="solux-4700",
                     canonical_surfaces="sfu", min_surfaces=1, max_surfaces=11, scenes=500, seed=1,
                     expand=0, expand_policy="none", crule=False, threads=0, data=None, frame=None):
    """The camera analogue of Finlayson & Hordley (1999) §4, Fig. 5, one record per scene.

    ``gmcc reproduce camera`` (camera_experiment.h; docs/reproduction.md §2): the SONY
    DXC-930's sensitivities, a canonical gamut under ``canonical``, scenes of Macbeth patches
    under each SFU lab light in ``lights``. The diagonal model is only approximate here, so a
    feasible set may be empty (``kind`` "empty", NaN errors).

    Parameters
    ----------
    lights : sequence of str, default ('syl-50MR16Q', 'solux-4700+3202')
        The test lights, SFU lab lights by name.
    canonical : str, default 'solux-4700'
        The canonical light.
    canonical_surfaces : {'sfu', 'macbeth'}, default 'sfu'
        The canonical gamut's reflectances: all 1995 SFU surfaces, or the 24 Macbeth patches
        (``--canonical-surfaces sfu1995`` or ``macbeth``).
    min_surfaces : int, default 1
        The smallest surface count n.
    max_surfaces : int, default 11
        The largest surface count n (``--surfaces``).
    scenes : int, default 500
        Seeded scenes per light and surface count.
    seed : int, default 1
        The run's seed.
    expand : int, float, Fraction or str, default 0
        Enlarge the canonical gamut by this factor.
    expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
        How it is enlarged.
    crule : bool, default False
        Also Forsyth's 3-D CRULE (slow).
    threads : int, default 0
        Worker threads (0: all cores); the records do not depend on it.
    @records@

    @scene_records@

    Raises
    ------
    ValueError
        An unknown light or ``canonical_surfaces``, bad surface counts or expansion.
    TypeError
        An argument of the wrong type.
    """
    min_surfaces, max_surfaces, scenes, seed, threads = _experiment_counts(
        min_surfaces, max_surfaces, scenes, seed, threads, lights)
    result = _core.run_experiment("camera", data or data_dir(), canonical, list(lights),
                                  canonical_surfaces, min_surfaces, max_surfaces, scenes, seed, expand,
                                  expand_policy, crule, threads)
    return _records_frame(result["columns"], frame)


@_doc
def reproduce_gehler_shi(*, protocol="leave-one-out", cameras=("Canon1D", "Canon5D"), min_surfaces=1,
                         max_surfaces=11, scenes=5, seed=1, dark="0.002", clip="0.95",
                         exclude_patches=(), expand=0, expand_policy="none", mean3d="analytic",
                         threads=0, data=None, frame=None):
    """The real-camera test of Finlayson & Hordley (1999) §4, Fig. 5, on the Gehler–Shi charts.

    ``gmcc reproduce gehler-shi`` (gehler_shi_experiment.h; docs/reproduction.md §6): the
    measured ColorChecker patches of the 568 Gehler–Shi images with their ground-truth lights;
    every image is a test light, its scenes are k = ``min_surfaces`` … ``max_surfaces`` of its
    usable patches, scored by the three rules and by grey world and max-RGB on the same
    scenes. Each camera is its own experiment. The options are the command line's, with
    Python names; the records are those of its ``--scenes-out``.

    Parameters
    ----------
    protocol : {'leave-one-out', 'paper'}, default 'leave-one-out'
        ``'leave-one-out'``: image i's canonical gamut is every other same-camera image's
        usable patches, each divided by its own light; ``'paper'``: one whitish daylight chart
        per camera, yellowish and bluish test groups.
    cameras : sequence of str, or str, default ('Canon1D', 'Canon5D')
        The cameras, in report order (``--cameras``; a str is split at commas).
    min_surfaces : int, default 1
        The smallest patch count k (1 to 24).
    max_surfaces : int, default 11
        The largest patch count k (``--surfaces``; 1 to 24). An image with fewer usable
        patches than k draws no scenes at k.
    scenes : int, default 5
        Seeded scenes per image and patch count.
    seed : int, default 1
        The run's seed (docs/reproduction.md "Scene generator").
    dark : int, float, Fraction or str, default '0.002'
        A patch with a channel <= it is dropped as near-black (a str is exact: 1/500).
    clip : int, float, Fraction or str, default '0.95'
        A patch with a channel >= it is dropped as clipped (above ``dark``).
    exclude_patches : iterable of int, default ()
        Patch numbers 1–24 left out of every image, canonical gamuts and scenes alike (e.g.
        19–24, the achromatic row).
    expand : int, float, Fraction or str, default 0
        Enlarge every canonical gamut by this factor.
    expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
        How it is enlarged.
    mean3d : {'analytic', 'quadrature', 'monte-carlo'}, default 'analytic'
        The route to the 3-D mean.
    threads : int, default 0
        Worker threads (0: all cores); the records do not depend on it.
    @records@

    Returns
    -------
    pandas.DataFrame or numpy.ndarray
        One record per scene, in the order image, patch count, scene: ``light`` (the image's
        name), ``group`` (its table row: the camera, or with ``protocol='paper'`` the camera
        and light group, e.g. "Canon5D bluish"), ``surfaces``, ``scene``, ``kind`` (of F),
        ``area``, ``drawn`` (patch numbers 1–24, space-separated), then for each rule
        (``max_area``, ``mean_2d``, ``mean_3d``) its map ``*_map_x``, ``*_map_y``,
        ``*_error_deg``, ``*_worst_case_deg``, ``*_illuminant_error_deg`` (the recovery
        error), ``*_reproduction_error_deg`` and ``*_truth_in_feasible_set`` (False where F is
        empty), and for each baseline (``grey_world``, ``max_rgb``), scored in every scene, its
        map and the same errors but the worst case. Errors are NaN where there is no map. The
        table's cells are ``summarise(records, rule, by=('group', 'surfaces'))``.

    Raises
    ------
    ValueError
        An unknown protocol or camera, ``dark`` not below ``clip``, a patch number outside
        1–24, bad surface counts or expansion, or unreadable data (naming the file and line).
    TypeError
        An argument of the wrong type.
    """
    if isinstance(cameras, str):
        cameras = cameras.split(",")
    result = _core.run_gehler_shi(data or data_dir(), protocol, list(cameras), dark, clip,
                                  list(exclude_patches), min_surfaces, max_surfaces, scenes, seed,
                                  expand, expand_policy, mean3d, threads)
    return _records_frame(result["columns"], frame)
