"""Input handling of the Python module: property tests (hypothesis) over dtypes, layouts,
values and shapes. A valid array must give exactly the result of the same values given as
Fractions (Python's Fraction(float) is the exact value of the double: an independent route); an
invalid one must raise ValueError or TypeError naming the argument (and the row), never crash."""

import math
import threading
import time
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import gmcc

CANONICAL = gmcc.prepare_canonical([[1, 1, 1], [3, 1, 1], [1, 3, 1], [2, 2, 1], ["1/2", 1, 1], [1, "0.5", 1]],
                                   illuminant_worst_case=False)

REAL_DTYPES = [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64,
               np.float16, np.float32, np.float64, ">f8", ">i4", "<u2"]


def exact_rows(a):
    """The exact values of an array's elements, by Python alone."""
    return [[Fraction(x.item()) if hasattr(x, "item") else Fraction(x) for x in row] for row in a]


def layouts(a):
    """The same values in other memory layouts: Fortran order, a strided view, a reversed view."""
    yield a
    yield np.asfortranarray(a)
    wide = np.zeros((a.shape[0], 6), dtype=a.dtype)
    wide[:, ::2] = a
    yield wide[:, ::2]
    yield a[::-1][::-1]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(dtype=st.sampled_from(REAL_DTYPES), data=st.data())
def test_valid_arrays_equal_their_exact_values(dtype, data):
    dt = np.dtype(dtype)
    if dt.kind == "f":
        elements = st.floats(min_value=0, max_value=1e4, allow_nan=False, allow_infinity=False,
                             width=8 * dt.itemsize)
    else:
        elements = st.integers(min_value=0, max_value=min(np.iinfo(dt).max, 10 ** 6))
    a = data.draw(hnp.arrays(dt, st.tuples(st.integers(1, 6), st.just(3)), elements=elements))
    exact = exact_rows(a.astype(np.float64) if dt.kind == "f" else a.astype(object))
    if all(row[2] == 0 for row in exact):
        with pytest.raises(ValueError, match="image"):
            gmcc.feasible_set(CANONICAL, a)
        return
    try:
        want = gmcc.feasible_set(CANONICAL, exact)
    except ValueError as e:  # e.g. an unbounded set: the array must say the same
        for view in layouts(a):
            with pytest.raises(ValueError) as got:
                gmcc.feasible_set(CANONICAL, view)
            assert str(got.value) == str(e)
        return
    for view in layouts(a):
        assert gmcc.feasible_set(CANONICAL, view) == want


@settings(max_examples=100, deadline=None)
@given(rows=st.integers(1, 5), row=st.data(), bad=st.sampled_from([math.nan, math.inf, -math.inf, -1.0, -1e-300]))
def test_bad_values_name_row_and_channel(rows, row, bad):
    a = np.ones((rows, 3))
    i = row.draw(st.integers(0, rows - 1))
    k = row.draw(st.integers(0, 2))
    a[i, k] = bad
    for value in (a, a.tolist()):
        with pytest.raises(ValueError) as e:
            gmcc.select(CANONICAL, value)
        assert str(e.value).startswith("image: row %d: channel %s" % (i, "rgb"[k]))
    with pytest.raises(ValueError, match=r"canonical: row %d: channel %s" % (i, "rgb"[k])):
        gmcc.prepare_canonical(a)


@pytest.mark.parametrize("value,error,message", [
    (np.zeros((0, 3)), ValueError, "image: no colours"),
    (np.zeros((3,)), ValueError, r"image: expected an N×3 array of colours r,g,b, got shape \(3,\)"),
    (np.zeros((2, 4)), ValueError, r"got shape \(2, 4\)"),
    (np.zeros((2, 3, 3, 1)), ValueError, "got shape"),
    (np.ones((2, 3), dtype=bool), TypeError, "bool"),
    (np.ones((2, 3), dtype=complex), TypeError, "complex"),
    (np.array([["1", "2", "3"]]), TypeError, "dtype"),
    (np.ones((2, 3), dtype=np.longdouble), TypeError, "float128"),
    ([], ValueError, "image: no colours"),
    ([[1, 2]], ValueError, "image: row 0: expected 3 values r,g,b, found 2"),
    ([[1, 2, 3], [1, 2]], ValueError, "image: row 1"),
    ([[1, 2, "x"]], ValueError, "image: row 0: channel b: 'x' is not a number"),
    ([[1, 2, "1/0"]], ValueError, "divides by zero"),
    ([[1, 2, None]], TypeError, "image: row 0: channel b: expected a number"),
    ([[1, True, 1]], TypeError, "image: row 0: channel g: a bool is not a number"),
    ([[1, 2, 10 ** 20000]], ValueError, "bits: at most 65536"),
    ([["1", "2", "1" * 101]], ValueError, "digits"),
    ("1,2,3", TypeError, "image: expected colours"),
    (None, TypeError, "image: expected colours"),
    (42, TypeError, "image: expected colours"),
    ([1, 2, 3], TypeError, "image: row 0: expected r,g,b"),
])
def test_bad_shapes_and_types(value, error, message):
    with pytest.raises(error, match=message):
        gmcc.select(CANONICAL, value)


def test_exact_kinds_of_numbers():
    """int, Fraction, str (read as text: 0.1 is 1/10), float (the double's value), numpy scalars
    and Decimal all give the exact values they stand for."""
    from decimal import Decimal
    want = gmcc.feasible_set(CANONICAL, [[Fraction(1, 10), Fraction(1, 5), 1]])
    assert gmcc.feasible_set(CANONICAL, [["0.1", "1/5", "1"]]) == want
    assert gmcc.feasible_set(CANONICAL, [[Decimal("0.1"), Decimal("0.2"), 1]]) == want
    assert gmcc.feasible_set(CANONICAL, [[np.int64(1), np.uint8(2), np.int16(10)]]) == want
    as_double = gmcc.feasible_set(CANONICAL, [[0.1, 0.2, 1.0]])
    assert as_double == gmcc.feasible_set(CANONICAL, [[Fraction(0.1), Fraction(0.2), 1]])
    assert as_double != want
    assert gmcc.feasible_set(CANONICAL, [[np.float32(0.5), 0.25, 1]]) == gmcc.feasible_set(
        CANONICAL, [["0.5", "0.25", "1"]])


def test_options_are_checked():
    for kwargs, message in [
        (dict(expand=-1, expand_policy="multiplicative"), "expand: must be >= 0"),
        (dict(expand="0.1"), "expand_policy: must be centroid-clip or multiplicative"),
        (dict(expand_policy="sideways"), "expand_policy"),
        (dict(mean3d="guess"), "mean3d"),
        (dict(order=0, mean3d="quadrature"), "order: must be from 1 to 256"),
        (dict(precision=20), "precision"),
        (dict(samples=0), "samples"),
        (dict(seed=-1), "seed"),
        (dict(on_empty="panic"), "on_empty"),
        (dict(nonpositive_blue="maybe"), "nonpositive_blue"),
        (dict(canonical_illuminant=(1, 0, 1)), "canonical_illuminant: every channel must be > 0"),
        (dict(illuminants=[[1, -1, 1]]), "illuminants: row 0: channel g is negative"),
        (dict(on_empty="grow-canonical", expand="0.1", expand_policy="centroid-clip"), "on_empty"),
    ]:
        with pytest.raises(ValueError, match=message):
            gmcc.prepare_canonical([[1, 1, 1], [2, 1, 1], [1, 2, 1]], **kwargs)
    with pytest.raises(TypeError, match="order: expected an int"):
        gmcc.prepare_canonical([[1, 1, 1]], order=2.5)
    with pytest.raises(TypeError, match="options"):
        gmcc.select(CANONICAL, [[1, 1, 1]], expand="0.1")
    with pytest.raises(ValueError, match="truth: every channel must be > 0"):
        gmcc.select(CANONICAL, [[1, 1, 1]], truth=(1, 1, 0))
    with pytest.raises(ValueError, match="nonpositive_blue='drop'"):
        gmcc.select([[1, 1, 1], [2, 1, 1], [1, 2, 1]], [[1, 1, 1], [1, 1, 0]], nonpositive_blue="reject")


def test_degenerate_results_are_results():
    empty = gmcc.select([[10, 10, 10], [11, 10, 10], [10, 11, 10]], [[1, 1, 1], [50, 1, 1]])
    assert empty.kind == "empty" and not empty.feasible_set and empty.max_area is None
    assert empty.feasible_set.vertices == [] and empty.feasible_set.area == 0
    assert empty.feasible_set.vertices_float.shape == (0, 2)
    point = gmcc.select([[1, 2, 1], [2, 4, 2]], [[1, 1, 1]])
    assert point.kind == "point" and point.feasible_set.vertices == [(Fraction(1), Fraction(2))]
    assert point.mean_3d.map == (1.0, 2.0)


@pytest.mark.parametrize("image,error,message", [
    (np.zeros((4, 4), np.uint16), ValueError, r"image: expected an N×3 array of colours r,g,b, got shape \(4, 4\)"),
    (np.zeros((4, 4, 4), np.uint16), ValueError, r"shape"),
    (np.full((2, 2, 3), 70000, np.int32), ValueError, r"image: pixel \(row 0, column 0\) channel r: 70000 is outside"),
    (np.full((2, 2, 3), -1, np.int16), ValueError, r"outside 0..65535"),
    # Unsigned 64-bit samples read as such: 2^64 - 1 is reported as itself, not as -1 (issue 30).
    (np.full((2, 2, 3), 2**64 - 1, np.uint64), ValueError, r"channel r: 18446744073709551615 is outside 0\.\.65535"),
    (np.full((2, 2, 3), 2**63 + 5, np.uint64), ValueError, r"channel r: 9223372036854775813 is outside"),
    (np.full((2, 2, 3), np.nan), ValueError, r"image: pixel \(row 0, column 0\) channel r: NaN"),
    (np.full((2, 2, 3), np.inf, np.float32), ValueError, r"infinity"),
    (np.full((2, 2, 3), -0.5), ValueError, r"negative"),
    (np.zeros((2, 2, 3), bool), TypeError, "dtype bool"),
    (np.zeros((0, 5, 3), np.uint16), ValueError, "no usable pixel"),
    (np.zeros((3, 3, 3), np.uint16), ValueError, "no usable pixel"),
])
def test_bad_images(image, error, message):
    with pytest.raises(error, match=message):
        gmcc.select(CANONICAL, image)


def test_bad_pixel_rules():
    img = np.ones((3, 4, 3), np.uint16)
    with pytest.raises(ValueError, match=r"mask: shape \(4, 3\) does not match"):
        gmcc.select(CANONICAL, img, mask=np.ones((4, 3), bool))
    with pytest.raises(TypeError, match="mask: expected dtype bool"):
        gmcc.select(CANONICAL, img, mask=np.ones((3, 4)))
    with pytest.raises(ValueError, match="black_level"):
        gmcc.select(CANONICAL, img, black_level=-1)
    with pytest.raises(ValueError, match="apply to an image"):
        gmcc.select(CANONICAL, [[1, 1, 1]], black_level=5)
    with pytest.raises(ValueError, match="not exact in double"):
        gmcc.select(CANONICAL, np.full((1, 1, 3), 1e17), black_level=1.0)


def test_threads_agree_with_serial():
    """Calls from many threads (the GIL released inside) give the serial results."""
    rng = np.random.default_rng(5)
    images = [rng.uniform(0.2, 1, (4, 3)) for _ in range(24)]
    serial = [gmcc.select(CANONICAL, i) for i in images]
    out = [None] * len(images)

    def work(k):
        for j in range(k, len(images), 4):
            out[j] = gmcc.select(CANONICAL, images[j])
    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(serial, out):
        assert a.feasible_set == b.feasible_set
        if a.mean_3d:
            assert a.mean_3d.map == b.mean_3d.map


def gaps_while(call):
    """Run `call` in a thread while this thread records time stamps in a loop; the largest gap
    between this thread's stamps within the call, and the call's duration."""
    started, done = threading.Event(), threading.Event()
    span = []

    def work():
        started.set()
        t0 = time.perf_counter()
        call()
        span.extend([t0, time.perf_counter()])
        done.set()
    t = threading.Thread(target=work)
    t.start()
    started.wait()
    stamps = []
    while not done.is_set():
        stamps.append(time.perf_counter())
    t.join()
    t0, t1 = span
    inside = [t0] + [x for x in stamps if t0 < x < t1] + [t1]
    return max(b - a for a, b in zip(inside, inside[1:])), t1 - t0


def test_the_gil_is_released_during_a_call():
    """While one thread is inside a long library call (a Monte Carlo 3-D mean), this thread
    keeps running Python: no gap in its progress comes near the call's length. (Were the GIL
    held, it could not run from the call's start to its end: one gap as long as the call. A
    comparison of two times of one run, not a timed assertion.)"""
    F = gmcc.feasible_set(CANONICAL, [[1, 1, 1]])
    gap, length = gaps_while(lambda: gmcc.mean_3d(F, method="monte-carlo", samples=5_000_000, seed=1))
    assert gap < length / 2, (gap, length)


def test_lights_in_every_form():
    """A light (truth, canonical_illuminant, an illuminant map) as a tuple, a 1-D array, one row,
    or the command line's text "r,g,b": the same exact light; bad ones named."""
    want = gmcc.select(CANONICAL, [[1, 1, 1]], truth=(Fraction(1), 2, "3")).truth.map
    for light in ("1,2,3", " 1, 2 ,3", np.array([1.0, 2.0, 3.0]), [[1, 2, 3]], np.array([1, 2, 3], np.uint8)):
        assert gmcc.select(CANONICAL, [[1, 1, 1]], truth=light).truth.map == want
    for light, message in [((1, 1), "truth: expected one light r,g,b \\(3 numbers\\), found 2"),
                           ("1,1", "found 2 in '1,1'"), ((1, 2, 0), "truth: every channel must be > 0"),
                           ("a,b,c", "truth: row 0: channel r: 'a' is not a number"),
                           ([[1, 2, 3], [1, 2, 3]], "truth: expected one light")]:
        with pytest.raises(ValueError, match=message):
            gmcc.select(CANONICAL, [[1, 1, 1]], truth=light)
    with pytest.raises(TypeError, match="truth"):
        gmcc.select(CANONICAL, [[1, 1, 1]], truth=5)


def pixel_rules_in_python(img, mask, black, saturation):
    """The pixel rules of docs/conventions.md §8, by Python alone, as exact colours."""
    out = []
    for y in range(img.shape[0]):
        for x in range(img.shape[1]):
            if mask is not None and not mask[y, x]:
                continue
            v = [Fraction(c.item()) for c in img[y, x]]
            if saturation is not None and any(c >= Fraction(saturation) for c in v):
                continue
            out.append([max(c - Fraction(black), Fraction(0)) for c in v])
    return out


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), dtype=st.sampled_from([np.uint8, np.uint16, np.int32, np.float32, np.float64]))
def test_images_equal_their_pixels_as_colours(data, dtype):
    """An H×W×3 image with a mask, black level and saturation gives the feasible set of its
    kept pixels listed as colours (the rules applied here in Python), or the same kind of error."""
    dt = np.dtype(dtype)
    h, w = data.draw(st.integers(1, 5)), data.draw(st.integers(1, 5))
    if dt.kind == "f":
        values = st.integers(0, 64).map(lambda k: k / 8)  # exact steps: black subtracts exactly
        black = data.draw(st.sampled_from([0, 0.5, 1.0]))
        saturation = data.draw(st.sampled_from([None, 6.0, 7.5]))
    else:
        values = st.integers(0, 250)
        black = data.draw(st.sampled_from([0, 3, 10]))
        saturation = data.draw(st.sampled_from([None, 200, 250]))
    img = data.draw(hnp.arrays(dt, (h, w, 3), elements=values))
    mask = data.draw(st.one_of(st.none(), hnp.arrays(np.bool_, (h, w))))
    if data.draw(st.booleans()):
        img = np.asfortranarray(img)
    listed = pixel_rules_in_python(img, mask, black, saturation)
    kwargs = dict(mask=mask, black_level=black, saturation=saturation)
    try:
        want = gmcc.feasible_set(CANONICAL, listed) if listed else None
    except ValueError:
        with pytest.raises(ValueError):
            gmcc.feasible_set(CANONICAL, img, **kwargs)
        return
    if want is None:
        with pytest.raises(ValueError, match="no usable pixel"):
            gmcc.feasible_set(CANONICAL, img, **kwargs)
        return
    assert gmcc.feasible_set(CANONICAL, img, **kwargs) == want
    counts = gmcc.image_colours(img, **kwargs).counts
    assert counts["kept"] == len(listed)
    assert counts["colours"] == len({tuple(c) for c in listed})


def test_colour_lists_are_capped_like_colour_files():
    # Issue 30: 10^7 colours took 5.9 GB before any work; the cap is the colour file's, 10^6,
    # checked before anything is converted (an array or a list of rows).
    too_many = np.ones((10**6 + 1, 3))
    for call in (lambda: gmcc.select(too_many, [[1, 1, 1]]), lambda: gmcc.select([[1, 1, 1], [2, 1, 1], [1, 2, 1]], too_many)):
        with pytest.raises(ValueError, match=r"1000001 colours, more than the 1000000"):
            call()
    with pytest.raises(ValueError, match=r"image: 1000001 colours"):
        gmcc.select([[1, 1, 1], [2, 1, 1], [1, 2, 1]], [[1, 1, 1]] * (10**6 + 1))
