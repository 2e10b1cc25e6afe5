#pragma once
/// \file docstrings.h
/// The numpy-style docstrings of gmcc's functions that the extension defines and the package
/// re-exports as they are (docs/python.md "Layout"): each function's parameters, defaults and
/// docs are said once, here beside its binding's py::arg list, which gives the signature. A
/// parameter list several functions share is one macro (pixel_rules, ...), spliced by
/// string-literal concatenation; the pure-Python wrappers (select, feasible_set, reproduce_*)
/// read the shared ones from gmcc._core._doc_parts.

#include <string>

namespace gmcc::python::doc {

/// The 3-D mean routes' parameters (canonical_options, mean_3d).
inline const std::string mean3d_parameters = R"doc(precision : int, default 0
    analytic: the working precision in bits (0: automatic, else 53 to 1048576).
order : int, default 12
    quadrature: Gauss–Legendre points per direction (1 to 256).
samples : int, default 1000000
    monte-carlo: the number of sample points.
seed : int, default 1
    monte-carlo: the seed of its mt19937_64 generator.
)doc";

/// The options of the canonical side (prepare_canonical; select and feasible_set forward them).
inline const std::string canonical_options = R"doc(expand : int, float, Fraction or str, default 0
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
)doc" + mean3d_parameters + R"doc(illuminant_worst_case : bool, default True
    Also compute each rule's worst case in illuminant space (docs/derivations.md §3.2).
nonpositive_blue : {'drop', 'reject'}, default 'drop'
    A colour with b <= 0 has no chromaticity: dropped and counted, or refused (ValueError).
)doc";

/// The pixel rules (image_colours, estimate_3d, select, feasible_set, the learners' add).
inline const std::string pixel_rules = R"doc(mask : numpy.ndarray of bool, shape (H, W), optional
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
)doc";

/// prepare_canonical's docstring.
inline const std::string prepare_canonical = std::string(R"doc(Prepare the canonical side once for many images: G_c and the options of select.

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
)doc") +
    canonical_options + R"doc(
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
)doc";

/// canonical_gamut's docstring.
inline const std::string canonical_gamut = R"doc(The canonical gamut G_c of a set of canonical colours, exactly.

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

Examples
--------
>>> G = gmcc.canonical_gamut([[1, 1, 1], [2, 1, 1], [1, 2, 1], [2, 2, 1]])
>>> G.kind, G.area
('polygon', Fraction(1, 1))
>>> G.vertices[1]
(Fraction(2, 1), Fraction(1, 1))
)doc";

/// image_colours's docstring.
inline const std::string image_colours = std::string(R"doc(The colours the geometry takes from a linear camera image, after the pixel rules.

The pixel rules of docs/conventions.md §8 (image_pixels.h), Gijsenij, Gevers & van de
Weijer (2010)'s dark and bright rule among them, and the reduction to the colours
the feasible set depends on: the chromaticity hull's vertices for the 2-D route
(Finlayson & Hordley 1999 eqs. 7–9 need only those), the 3-D hull's for the 3-D route.

Parameters
----------
image : numpy.ndarray, shape (H, W, 3)
    Linear samples: integers 0..65535 (the exact integer route), or floats, where each
    sample minus the black level must be exact in double (else ValueError).
)doc") +
    pixel_rules + R"doc(colour_set : {'hull', 'distinct', 'hull-3d'}, default 'hull'
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
)doc";

/// read_image's docstring.
inline const std::string read_image = R"doc(Read a linear camera image: PNG, TIFF or a camera raw file, as the command line does.

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
)doc";

/// rules's docstring.
inline const std::string rules = R"doc(The selection rules on the 2-D feasible set, in report order (Finlayson & Hordley 1999 §3).

Returns
-------
list of str
    Their names, ``['max_area', 'mean_2d', 'mean_3d']``: the keys of ``select_maps``' and
    ``SceneResult.selections``' dicts, and the names of SceneResult's and Truth's per-rule
    attributes.
)doc";

/// select_maps's docstring.
inline const std::string select_maps = R"doc(The three selection rules on a feasible set, each with its worst cases.

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
)doc";

/// An example's feasible set: G_c of four colours, an image of two (a polygon of area 1/3).
inline const std::string example_feasible_set = R"doc(>>> F = gmcc.feasible_set([[1, 1, 1], [2, 1, 1], [1, 2, 1], [2, 2, 1]], [[1, 1, 1], [3, 2, 2]])
)doc";

/// The parameters, returns and raises of the exact rules on F (max_area, mean_2d), then their
/// example's F.
inline const std::string exact_rule_on_F = R"doc(Parameters
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

Examples
--------
)doc" + example_feasible_set;

/// max_area's docstring.
inline const std::string max_area = std::string(R"doc(The max-area map of a feasible set, exactly.

argmax m1·m2 over F, the map that makes the corrected image as colourful as possible
(Finlayson & Hordley 1999 §3.1; Forsyth 1990's maximum-volume map in perspective;
max_area.h, docs/derivations.md §2).

)doc") + exact_rule_on_F + R"doc(>>> gmcc.max_area(F).exact
(Fraction(4, 3), Fraction(2, 1))
)doc";

/// mean_2d's docstring.
inline const std::string mean_2d = std::string(R"doc(The 2-D mean of a feasible set, its centroid, exactly.

The centroid of F in the perspective plane (Finlayson & Hordley 1999 §3.2; mean_2d.h).

)doc") + exact_rule_on_F + R"doc(>>> gmcc.mean_2d(F).exact
(Fraction(7, 6), Fraction(3, 2))
)doc";

/// mean_3d's docstring.
inline const std::string mean_3d = R"doc(The 3-D mean of a feasible set by one route, with its error statement.

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
)doc" + mean3d_parameters + R"doc(
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
)doc";

/// The attributes every 3-D rule's answer has (Selection3, ImageSelection3): its map as doubles,
/// exactly where rational, and the bound on the doubles.
inline const std::string map3_attributes = R"doc(map : tuple of (float, float, float)
    The map (d1, d2, d3) as doubles.
exact : tuple of (Fraction, Fraction, Fraction) or None
    The exact map where it is rational, else None.
error_bound : float
    A rigorous bound on the largest component's distance from the true value.
)doc";

/// The returns of the angles in degrees, and the head of their errors: each adds its own
/// ValueError cases.
inline const std::string returns_degrees = R"doc(Returns
-------
float
    Degrees.

Raises
------
ValueError
)doc";

/// worst_case_map_deg's docstring.
inline const std::string worst_case_map_deg = std::string(R"doc(The largest map-space angle between a map and any map of a feasible set, degrees.

The worst case of Finlayson & Hordley (1999) §4, attained at a vertex of F
(docs/derivations.md §3.1; worst_case.h).

Parameters
----------
feasible_set : ConvexSet
    F, not empty.
map : sequence of 2 numbers
    The perspective map (m1, m2), taken exactly.

)doc" + returns_degrees + R"doc(    F is empty, or a bad map.
TypeError
    An argument of the wrong type.

Examples
--------
)doc") + example_feasible_set + R"doc(>>> round(gmcc.worst_case_map_deg(F, (1, 1)), 6)
19.471221
)doc";

/// worst_case_illuminant_deg's docstring.
inline const std::string worst_case_illuminant_deg = R"doc(The largest illuminant-space angle between a map's light and any light of F, degrees.

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

)doc" + returns_degrees + R"doc(    F is empty or touches an axis, or a component of ``map`` is <= 0.
TypeError
    An argument of the wrong type.
)doc";

/// map_angular_error_deg's docstring.
inline const std::string map_angular_error_deg = R"doc(The paper's map-space angular error between two perspective maps, degrees.

The angle between (m1, m2, 1) and (t1, t2, 1) (Finlayson & Hordley 1999 §4;
angular_error.h), certified to about one ulp.

Parameters
----------
estimate : sequence of 2 numbers
    The estimated map (m1, m2), taken exactly.
truth : sequence of 2 numbers
    The true map (t1, t2), taken exactly.

)doc" + returns_degrees + R"doc(    A map that is not two finite numbers.
TypeError
    An argument of the wrong type.

Examples
--------
>>> round(gmcc.map_angular_error_deg((1, 1), (2, 1)), 6)
19.471221
)doc";

/// The two maps of illuminant_angular_error_deg and reproduction_angular_error_deg.
inline const std::string error_maps = R"doc(Parameters
----------
estimate : sequence of 2 numbers
    The estimated map, both components > 0.
truth : sequence of 2 numbers
    The true map, both components > 0.
)doc";

/// Their returns and errors.
inline const std::string error_degrees = R"doc(
)doc" + returns_degrees + R"doc(    A component <= 0, or a bad number.
TypeError
    An argument of the wrong type.
)doc";

/// illuminant_angular_error_deg's docstring.
inline const std::string illuminant_angular_error_deg = std::string(R"doc(The recovery (illuminant-space) angular error of a map against the true map, degrees.

The angle between the illuminants c ⊘ (m, 1) the two maps imply (Hordley & Finlayson 2006;
docs/math.md §3; angular_error.h).

)doc") + error_maps + R"doc(canonical_illuminant : sequence of 3 numbers, default (1, 1, 1)
    The canonical light c.
)doc" + error_degrees;

/// reproduction_angular_error_deg's docstring.
inline const std::string reproduction_angular_error_deg = std::string(R"doc(The reproduction angular error of a map against the true map, degrees.

The angle between the white corrected by the estimate and white (Finlayson & Zakizadeh
2014; docs/math.md §3; angular_error.h); it does not depend on the canonical light.

)doc") + error_maps + error_degrees;

/// illuminant_map's docstring.
inline const std::string illuminant_map = R"doc(The perspective map of a light: c ⊘ e as (d1/d3, d2/d3), exactly.

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

Examples
--------
>>> gmcc.illuminant_map((2, 1, 1))
(Fraction(1, 2), Fraction(1, 1))
)doc";

/// illumination_constraint's docstring.
inline const std::string illumination_constraint = R"doc(Finlayson's illumination constraint C: the hull of a set of lights' maps, exactly.

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
)doc";

/// crule_3d's docstring.
inline const std::string crule_3d = R"doc(Forsyth's CRULE in 3-D on colours: F3, its volume, max-volume and centroid.

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
)doc";

/// The 3-D canonical side's black option and result (prepare_canonical_3d, a learner's prepare),
/// up to its ValueError's reasons.
inline const std::string black_3d_returns = R"doc(black : {'include', 'exclude'}, default 'include'
    Whether black (0, 0, 0) joins the hull (with it F3 is never empty).

Returns
-------
Canonical3
    G_c3, immutable and thread-safe.

Raises
------
ValueError
)doc";

/// prepare_canonical_3d's docstring.
inline const std::string prepare_canonical_3d = std::string(R"doc(A 3-D canonical gamut G_c3 prepared once for many images.

The exact half-spaces of the hull of the canonical colours (Forsyth 1990 §3;
feasible_set_3d.h), for estimate_3d.

Parameters
----------
canonical : array_like of shape (n, 3), or ImageColours
    Pixel colours under the canonical light (e.g. ``CanonicalLearner3.gamut()``). An
    ImageColours of chromaticity lifts is refused.
)doc") + black_3d_returns + R"doc(    Bad colours, chromaticity lifts, or an unknown ``black``.
TypeError
    An argument of the wrong type.
)doc";

/// estimate_3d's docstring.
inline const std::string estimate_3d = std::string(R"doc(3-D gamut mapping on one image: F3 and the rules max-volume, centroid and max-trace.

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
)doc") +
    pixel_rules + R"doc(colour_set : {'hull-3d', 'distinct'}, default 'hull-3d'
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
)doc";

/// benchmark's docstring.
inline const std::string benchmark = R"doc(Benchmark every gamut method and baseline on a dataset of linear images, fold by fold.

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
)doc";

/// error_statistics's docstring.
inline const std::string error_statistics = R"doc(The statistics the field reports for a list of angular errors.

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

Examples
--------
>>> s = gmcc.error_statistics([1.0, 2.0, 3.0, 4.0])
>>> s.n, s.mean, s.median, s.max
(4, 2.5, 2.5, 4.0)
)doc";

}  // namespace gmcc::python::doc
