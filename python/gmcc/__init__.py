"""gmcc — gamut-mapping colour constancy with exact geometry, from Python.

A thin layer over the C++ library (docs/python.md): the canonical gamut, the feasible set of
perspective diagonal maps (Finlayson & Hordley 1999 eqs. 7–9, in perspective), the selection
rules max-area, 2-D mean and 3-D mean (§3) with their worst cases (§4), Forsyth's 3-D CRULE,
the paper's synthetic experiment and the statistics the field reports.

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
    SceneResult,
    Selection,
    Selection3,
    Truth,
    TruthErrors,
)
from ._records import records_frame as _records_frame

__version__: str = _core.__version__
__commit__: str = _core.__commit__
__commit_date__: str = _core.__commit_date__

__all__ = [
    "__version__", "__commit__", "__commit_date__",
    "Canonical", "Canonical3", "CanonicalLearner2", "CanonicalLearner3", "ConvexSet", "ConvexSet3",
    "Constraint", "Crule3d", "ErrorStatistics", "Estimate3", "ImageColours", "ImageSelection3",
    "MapEstimate", "Recovery", "SceneResult", "Selection", "Selection3", "Truth",
    "TruthErrors",
    "prepare_canonical", "canonical_gamut", "feasible_set", "select", "image_colours",
    "select_maps", "max_area", "mean_2d", "mean_3d", "worst_case_map_deg",
    "worst_case_illuminant_deg", "map_angular_error_deg", "illuminant_angular_error_deg",
    "reproduction_angular_error_deg", "illuminant_map", "illumination_constraint", "crule_3d",
    "prepare_canonical_3d", "estimate_3d", "benchmark",
    "error_statistics", "summarise", "reproduce_synthetic", "reproduce_camera", "data_dir",
]

_OPTIONS = ("expand", "expand_policy", "illuminants", "canonical_illuminant", "on_empty", "mean3d",
            "precision", "order", "samples", "seed", "illuminant_worst_case", "nonpositive_blue")


def prepare_canonical(canonical, **options) -> Canonical:
    """Prepare the canonical side once for many images (select_scene.h, prepare_canonical.h).

    ``canonical``: the canonical colours, an N×3 array or rows r,g,b (each channel finite and
    >= 0; a float is taken as the exact rational of its value). The perspective chromaticities
    (Finlayson & Hordley 1999 eq. 10) and their exact hull G_c, expanded by ``expand`` under
    ``expand_policy`` (``none``, ``centroid-clip``, ``multiplicative``; §4's "expanded by 10%"
    is ``expand=0.1`` — give ``"0.1"`` or ``Fraction(1, 10)`` for exactly 1/10).

    Options (keyword only, the command line's, docs/cli.md "gmcc select"):
    ``illuminants`` (plausible lights: Finlayson's illumination constraint F ∩ C),
    ``canonical_illuminant`` (c, default (1, 1, 1)), ``on_empty`` (``none``,
    ``grow-canonical``, ``min-violation``), ``mean3d`` (``analytic``, ``quadrature``,
    ``monte-carlo``) with ``precision``, ``order``, ``samples``, ``seed``,
    ``illuminant_worst_case`` (default True), ``nonpositive_blue`` (``drop`` or ``reject``).

    Raises ValueError / TypeError naming the argument and row (0-based) for bad input.
    """
    return _core.prepare_canonical(canonical, **options)


def _prepared(canonical, options) -> Canonical:
    if isinstance(canonical, Canonical):
        if options:
            raise TypeError("options (%s) belong to prepare_canonical; a prepared Canonical "
                            "already has them" % ", ".join(sorted(options)))
        return canonical
    return _core.prepare_canonical(canonical, **options)


def canonical_gamut(canonical, *, expand=0, expand_policy="none",
                    nonpositive_blue="drop") -> ConvexSet:
    """The canonical gamut G_c: the exact hull of the canonical colours' perspective
    chromaticities (Finlayson & Hordley 1999 eq. 10; canonical_gamut.h), expanded by
    ``expand`` under ``expand_policy`` (``none``, ``centroid-clip``, ``multiplicative``).
    Returns a ConvexSet (a polygon, or a degenerate kind)."""
    return _core.prepare_canonical(canonical, expand=expand, expand_policy=expand_policy,
                                   nonpositive_blue=nonpositive_blue).gamut


def select(canonical, image, truth=None, *, mask=None, black_level=0, saturation=None, dark=0,
           dark_fraction=None, bright_fraction=None, pixel_rule="none", **options) -> SceneResult:
    """The select pipeline on one image (select_scene.h; ``gmcc select``): the feasible set F
    of perspective diagonal maps (Finlayson & Hordley 1999 eqs. 7–9; ∩ C with
    ``illuminants``), the recovery policy when F is empty, the three selection rules (§3) with
    their worst cases (§4), and with ``truth`` (the true light's r,g,b) each rule's errors.

    ``canonical``: a Canonical from prepare_canonical (then no options), or canonical colours
    with the options of prepare_canonical. ``image``: an N×3 array or rows r,g,b of colours, or
    an H×W×3 image array (integer samples 0..65535, or floats) with the pixel rules ``mask``
    (bool H×W, True for pixels to use), ``black_level`` (subtracted, clamped at 0) and
    ``saturation`` (pixels with a raw channel >= it are dropped), and the dark and bright rules
    of image_colours (``dark``, ``dark_fraction``, ``bright_fraction``, ``pixel_rule``;
    docs/conventions.md §8).

    An empty or degenerate F is a result (``result.kind``), not an exception.
    """
    return _core.select_prepared(_prepared(canonical, options), image, truth, mask, black_level,
                                 saturation, dark, dark_fraction, bright_fraction, pixel_rule)


def feasible_set(canonical, image, *, mask=None, black_level=0, saturation=None, dark=0,
                 dark_fraction=None, bright_fraction=None, pixel_rule="none",
                 **options) -> ConvexSet:
    """The feasible set F of perspective diagonal maps alone (Finlayson & Hordley 1999 eqs.
    7–9 in perspective; feasible_set.h), ∩ C with ``illuminants``, with the recovery policy
    ``on_empty``: an exact ConvexSet (polygon, segment, point or empty). Arguments as select."""
    scene = _core.feasible_prepared(_prepared(canonical, options), image, mask, black_level,
                                    saturation, dark, dark_fraction, bright_fraction, pixel_rule)
    return scene.feasible_set


def image_colours(image, *, mask=None, black_level=0, saturation=None, dark=0,
                  dark_fraction=None, bright_fraction=None, pixel_rule="none",
                  colour_set="hull", prefilter=0) -> ImageColours:
    """The colours the geometry takes from a linear camera image (image_pixels.h;
    docs/conventions.md §8).

    Parameters
    ----------
    image : numpy.ndarray, shape (H, W, 3)
        Linear samples: integers 0..65535 (the exact integer route), or floats, where each
        sample minus the black level must be exact in double (else ValueError).
    mask : numpy.ndarray of bool, shape (H, W), optional
        True for the pixels to use.
    black_level : int or float
        Subtracted from every channel, clamped at 0.
    saturation : int or float, optional
        Pixels with a raw channel >= it are dropped.
    dark : int or float
        Pixels with a channel (after the black level) below it are dropped.
    dark_fraction, bright_fraction : number, optional
        Pixels with a channel below ``dark_fraction``·M, or above ``bright_fraction``·M, are
        dropped; M is the image's largest value after the black level (exact fractions,
        e.g. ``Fraction(5, 255)``).
    pixel_rule : {'none', 'gijsenij'}
        ``'gijsenij'``: Gijsenij et al. (2010)'s rule, fractions 5/255 and 245/255.
    colour_set : {'hull', 'distinct', 'hull-3d'}
        ``'hull'``: the chromaticity lifts (x, y, 1) of the chromaticity hull's vertices, all
        the 2-D route depends on (read them as ``.chromaticity_lifts``; ``.colours`` refuses
        them, since they are not pixel colours); ``'distinct'``: every distinct pixel colour;
        ``'hull-3d'``: the pixel colours on their exact 3-D hull.
    prefilter : number
        A Gaussian pre-filter's sigma in pixels (integer images; 0 for none): the kept pixels'
        colours are taken from the smoothed image (computed in double, taken exactly).

    Returns
    -------
    ImageColours
        The colours, what they are (``colour_set``) and the pixel counts."""
    return _core.image_colours(image, mask, black_level, saturation, dark, dark_fraction,
                               bright_fraction, pixel_rule, colour_set, prefilter)


def select_maps(feasible_set, *, mean3d="analytic", precision=0, order=12, samples=1000000,
                seed=1, canonical_illuminant=None) -> dict:
    """max-area, 2-D mean and 3-D mean of a feasible set (Finlayson & Hordley 1999 §3,
    select_maps.h), each with its map-space worst case (§4) and, given
    ``canonical_illuminant``, its illuminant-space worst case. Returns
    {'max_area': Selection, 'mean_2d': ..., 'mean_3d': ...}, values None when F is empty."""
    return _core.select_maps(feasible_set, mean3d=mean3d, precision=precision, order=order,
                             samples=samples, seed=seed, canonical_illuminant=canonical_illuminant)


def max_area(feasible_set) -> MapEstimate:
    """The max-area map of F (Finlayson & Hordley 1999 §3.1, max_area.h): exact."""
    return _core.max_area(feasible_set)


def mean_2d(feasible_set) -> MapEstimate:
    """The 2-D mean of F, its centroid (Finlayson & Hordley 1999 §3.2, mean_2d.h): exact."""
    return _core.mean_2d(feasible_set)


def mean_3d(feasible_set, *, method="analytic", precision=0, order=12, samples=1000000,
            seed=1) -> MapEstimate:
    """The 3-D mean of F (Finlayson & Hordley 1999 §3.2; mean_3d.h, docs/math.md §2) by one
    route: ``analytic`` (closed form, certified enclosure; ``precision`` forces the bits),
    ``quadrature`` (Duffy–Gauss–Legendre of ``order`` points per direction) or
    ``monte-carlo`` (the paper's sampling: ``samples`` points, generator mt19937_64 seeded with
    ``seed``). Irrational in general: the nearest double with its error bound."""
    return _core.mean_3d(feasible_set, method=method, precision=precision, order=order,
                         samples=samples, seed=seed)


def worst_case_map_deg(feasible_set, map) -> float:
    """The largest map-space angle, in degrees, between ``map`` and any map of F (Finlayson &
    Hordley 1999 §4; worst_case.h). ``map`` is taken exactly."""
    return _core.worst_case_map_deg(feasible_set, map)


def worst_case_illuminant_deg(feasible_set, map, canonical_illuminant=(1, 1, 1)) -> float:
    """The same in illuminant space (docs/derivations.md §3.2; worst_case_illuminant.h): F and
    ``map`` need components > 0."""
    return _core.worst_case_illuminant_deg(feasible_set, map, canonical_illuminant)


def map_angular_error_deg(estimate, truth) -> float:
    """The paper's map-space angular error between two perspective maps, in degrees (§4;
    angular_error.h): the angle between (m1, m2, 1) and (t1, t2, 1)."""
    return _core.map_angular_error_deg(estimate, truth)


def illuminant_angular_error_deg(estimate, truth, canonical_illuminant=(1, 1, 1)) -> float:
    """The recovery (illuminant-space) angular error of a map against the true map, degrees
    (Hordley & Finlayson 2006; angular_error.h). Components > 0."""
    return _core.illuminant_angular_error_deg(estimate, truth, canonical_illuminant)


def reproduction_angular_error_deg(estimate, truth) -> float:
    """The reproduction angular error (Finlayson & Zakizadeh 2014; angular_error.h), degrees."""
    return _core.reproduction_angular_error_deg(estimate, truth)


def illuminant_map(light, canonical_illuminant=(1, 1, 1)):
    """The perspective map of a light e: c ⊘ e as (d1/d3, d2/d3), exact (Fraction, Fraction)
    (Finlayson 1996 §5; illumination_constraint.h)."""
    return _core.illuminant_map(light, canonical_illuminant)


def illumination_constraint(illuminants, canonical_illuminant=(1, 1, 1)) -> ConvexSet:
    """C = conv{c ⊘ e_j}: the plausible maps of a set of lights (Finlayson 1996 §5;
    illumination_constraint.h), an exact ConvexSet."""
    return _core.illumination_constraint(illuminants, canonical_illuminant)


def crule_3d(canonical, image, *, black="include") -> Crule3d:
    """Forsyth's (1990) CRULE in 3-D (crule_3d.h): the exact polytope F3 of diagonal maps
    (d1, d2, d3), its volume, and the max-volume and centroid selections with their worst cases.
    ``black``: ``include`` (0 in the canonical gamut, the default) or ``exclude``."""
    return _core.crule_3d(canonical, image, black=black)


def prepare_canonical_3d(canonical, *, black="include") -> Canonical3:
    """A 3-D canonical gamut G_c3 prepared once for many images (feasible_set_3d.h;
    Forsyth 1990 §3).

    Parameters
    ----------
    canonical : array_like of shape (n, 3), or ImageColours
        Pixel colours under the canonical light (e.g. ``CanonicalLearner3.gamut()``). An
        ImageColours of chromaticity lifts is refused (ValueError).
    black : {'include', 'exclude'}
        Whether black (0, 0, 0) joins the hull (with it F3 is never empty).

    Returns
    -------
    Canonical3
    """
    return _core.prepare_canonical_3d(canonical, black=black)


def estimate_3d(canonical, image, truth=None, *, rules=None, centroid="certified",
                canonical_illuminant=(1, 1, 1), mask=None, black_level=0, saturation=None,
                dark=0, dark_fraction=None, bright_fraction=None, pixel_rule="none",
                colour_set="hull-3d") -> Estimate3:
    """3-D gamut mapping on one image (estimate_3d.h; Forsyth 1990, Gijsenij et al. 2010):
    the exact feasible set F3 of diagonal maps taking the image's pixel colours into the
    canonical gamut, and the rules max-volume, centroid and max-trace with the light each
    implies (docs/photographs.md §3).

    Parameters
    ----------
    canonical : Canonical3
        From prepare_canonical_3d or CanonicalLearner3.prepare.
    image : numpy.ndarray (H, W, 3), ImageColours, or array_like (n, 3)
        An image goes through the pixel rules (arguments as image_colours; ``colour_set``
        'hull-3d' or 'distinct'); an ImageColours must hold pixel colours (chromaticity lifts
        are refused); colours are taken as they are.
    truth : array_like of 3 numbers, optional
        The true light: each rule's ``recovery_error_deg``.
    rules : iterable of str, optional
        Of 'max_volume', 'centroid', 'max_trace' (default all).
    centroid : {'certified', 'exact'}
        The centroid as a certified double, or in Q (max-volume and max-trace are exact).
    canonical_illuminant : array_like of 3 numbers
        The canonical light c; a map d implies the light c ⊘ d.

    Returns
    -------
    Estimate3
    """
    return _core.estimate_3d(canonical, image, truth, rules=rules, centroid=centroid,
                             canonical_illuminant=canonical_illuminant, mask=mask,
                             black_level=black_level, saturation=saturation, dark=dark,
                             dark_fraction=dark_fraction, bright_fraction=bright_fraction,
                             pixel_rule=pixel_rule, colour_set=colour_set)


def benchmark(images, truths, *, folds=None, folds_file=None, methods=None, intensity="max",
              black="include", threads=0, black_level=0, saturation=None, dark=0,
              dark_fraction=None, bright_fraction=None, pixel_rule="none", frame=True):
    """A colour-constancy dataset benchmark (benchmark.h; ``gmcc benchmark``,
    docs/photographs.md §6): every image estimated by canonical gamuts learned only from the
    other folds' images, by every gamut method and baseline on the same pixels.

    Parameters
    ----------
    images : str
        The folder the truth table's image paths are relative to.
    truths : str
        The truth table, ``image,r,g,b[,black_level][,saturation][,mask][,chart]``.
    folds : int, optional
        K folds: the image on data line i (from 0) is in fold i mod K.
    folds_file : str, optional
        ``image,fold``: the dataset's own split (give this or ``folds``).
    methods : list of str, optional
        A subset of the benchmark's methods (default all).
    intensity, black : str
        The 3-D canonical gamut's learning, as ``gmcc benchmark --intensity``, ``--black``.
    threads : int
        Worker threads; 0 for the machine's cores. The result does not depend on it.
    black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule
        The run's pixel rules, as image_colours (the truth table's columns override them per
        image).
    frame : bool
        Return pandas DataFrames (when pandas is installed) rather than lists of dicts.

    Returns
    -------
    (summary, records)
        One row per method (images, answered, empty, mean/median/trimean/best25/worst25/p95/max
        of the recovery error in degrees, truth_in_feasible, worst_case_covers,
        worst_case_correlation), and one row per image and method (image, fold, method, light,
        error_deg, answered, fallback, feasible_kind, feasible_vertices, truth_in_feasible,
        worst_case_deg).
    """
    summary, records = _core.benchmark(
        str(images), str(truths), folds=folds,
        folds_file=None if folds_file is None else str(folds_file), methods=methods,
        intensity=intensity, black=black, threads=threads, black_level=black_level,
        saturation=saturation, dark=dark, dark_fraction=dark_fraction,
        bright_fraction=bright_fraction, pixel_rule=pixel_rule)
    if frame:
        try:
            import pandas
        except ImportError:
            return summary, records
        return pandas.DataFrame(summary), pandas.DataFrame(records)
    return summary, records


def error_statistics(values) -> ErrorStatistics:
    """The statistics the field reports for a list of angular errors (error_statistics.h,
    docs/reproduction.md "Statistics"): n, mean, standard_error, median, trimean, best25,
    worst25, p95, max. NaN or infinite values raise ValueError."""
    return _core.error_statistics(values)


def summarise(records, rule="mean_3d", error="error_deg", by=("light", "surfaces")):
    """error_statistics of one rule's error per group of experiment records (the rows of
    reproduce_synthetic, structured array or DataFrame): {group key: ErrorStatistics}, over the
    scenes where the rule gave a map (empty feasible sets are left out, as in the paper)."""
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
    """The folder of gmcc's shipped spectral data: $GMCC_DATA_DIR, else the source tree's data/
    recorded at build time, else data/ installed next to the package."""
    env = _os.environ.get("GMCC_DATA_DIR")
    if env:
        return env
    here = _os.path.dirname(__file__)
    for candidate in (_os.path.join(here, "data"), getattr(_core, "__data_dir__", "")):
        if candidate and _os.path.isfile(_os.path.join(candidate, "munsell_matt_1269_joensuu_5nm.csv")):
            return candidate
    raise FileNotFoundError("gmcc's spectral data not found: set GMCC_DATA_DIR to the data/ folder")


def reproduce_synthetic(*, lights=("D75", "D100", "P2856", "P15000"), canonical="D55",
                        min_surfaces=1, max_surfaces=11, scenes=500, seed=1, expand=0,
                        expand_policy="none", crule=False, threads=0, data=None, frame=None):
    """The synthetic experiment of Finlayson & Hordley (1999) §4, Fig. 3 (synthetic_experiment.h,
    gamut_experiment.h; ``gmcc reproduce synthetic``): narrow-band sensors at 610, 540 and
    450 nm, the 1269 Munsell chips, canonical light ``canonical``, ``scenes`` seeded scenes per
    test light and surface count n = ``min_surfaces`` … ``max_surfaces``. ``expand`` /
    ``expand_policy`` enlarge the canonical gamut; ``crule`` adds Forsyth's 3-D CRULE
    (``crule_max_volume``, ``crule_centroid``; slow). The same seed gives the same records,
    whatever ``threads``.

    Returns one record per scene — light, surfaces, scene, kind, area, drawn (the surfaces'
    0-based indices, space-separated) and for each rule (max_area, mean_2d, mean_3d) its map
    (``*_map_x``, ``*_map_y``), ``*_error_deg``, ``*_worst_case_deg``,
    ``*_illuminant_error_deg``, ``*_reproduction_error_deg`` (NaN where the rule gave no map) —
    as a pandas DataFrame when pandas is installed (``frame=None`` or True), else (or with
    ``frame=False``) a numpy structured array."""
    result = _core.run_experiment("synthetic", data or data_dir(), canonical, list(lights), "sfu",
                                  min_surfaces, max_surfaces, scenes, seed, expand, expand_policy,
                                  crule, threads)
    return _records_frame(result["columns"], frame)


def reproduce_camera(*, lights=("syl-50MR16Q", "solux-4700+3202"), canonical="solux-4700",
                     canonical_surfaces="sfu", min_surfaces=1, max_surfaces=11, scenes=500, seed=1,
                     expand=0, expand_policy="none", crule=False, threads=0, data=None, frame=None):
    """The camera analogue of Finlayson & Hordley (1999) §4, Fig. 5 (camera_experiment.h;
    ``gmcc reproduce camera``): the SONY DXC-930's sensitivities, the canonical gamut of the SFU
    reflectances (``canonical_surfaces="sfu"``) or the 24 Macbeth patches (``"macbeth"``) under
    ``canonical``, scenes of Macbeth patches under each SFU lab light in ``lights``. The diagonal
    model is only approximate here, so a feasible set may be empty (``kind`` "empty", NaN
    errors). Records as reproduce_synthetic."""
    result = _core.run_experiment("camera", data or data_dir(), canonical, list(lights),
                                  canonical_surfaces, min_surfaces, max_surfaces, scenes, seed, expand,
                                  expand_policy, crule, threads)
    return _records_frame(result["columns"], frame)
