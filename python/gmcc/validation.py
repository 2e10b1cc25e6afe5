"""The validation layer (gmcc/validation/; docs/architecture.md "Layers"): the paper's experiments
(Finlayson & Hordley 1999 §4: synthetic, camera and Gehler–Shi charts), the dataset benchmark of
docs/photographs.md §6, and the statistics the field reports.

``error_statistics`` and ``benchmark`` are the extension's, re-exported as they are (signatures,
defaults and docstrings in python/src/docstrings.h); the experiments and ``summarise`` are Python:
they check the run's size and return the records as a structured array or a DataFrame.
"""

from __future__ import annotations

from ._core import ErrorStatistics, benchmark, error_statistics  # noqa: F401  (re-exported)
from . import _core
from ._doc import doc as _doc
from ._records import records_frame as _records_frame
from .input import data_dir

__all__ = ["ErrorStatistics", "error_statistics", "summarise", "benchmark", "reproduce_synthetic",
           "reproduce_camera", "reproduce_gehler_shi"]

# Parameter and return descriptions the experiments share (spliced by _doc).
_RECORD_PARTS = {
    "surface_counts": """\
min_surfaces : int, default 1
    The smallest surface count n.
max_surfaces : int, default 11
    The largest surface count n (``--surfaces``).
scenes : int, default 500
    Seeded scenes per light and surface count.
""",
    "expand_policy": """\
expand_policy : {'none', 'centroid-clip', 'multiplicative'}, default 'none'
    How it is enlarged.
""",
    "run": """\
threads : int, default 0
    Worker threads (0: all cores); the records do not depend on it.
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


@_doc(**_RECORD_PARTS)
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
    @surface_counts@
    seed : int, default 1
        The run's seed (docs/reproduction.md "Scene generator").
    expand : int, float, Fraction or str, default 0
        Enlarge the canonical gamut by this factor (``"0.1"``: exactly 10%).
    @expand_policy@
    crule : bool, default False
        Also Forsyth's 3-D CRULE (``crule_max_volume``, ``crule_centroid``; slow).
    @run@

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


@_doc(**_RECORD_PARTS)
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
    @surface_counts@
    seed : int, default 1
        The run's seed.
    expand : int, float, Fraction or str, default 0
        Enlarge the canonical gamut by this factor.
    @expand_policy@
    crule : bool, default False
        Also Forsyth's 3-D CRULE (slow).
    @run@

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


@_doc(**_RECORD_PARTS)
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
    @expand_policy@
    mean3d : {'analytic', 'quadrature', 'monte-carlo'}, default 'analytic'
        The route to the 3-D mean.
    @run@

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
