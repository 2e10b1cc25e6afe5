"""Ctrl-C during long calls (docs/python.md "Interrupting"; numerics/interrupt.h): a real SIGINT
sent to the process while gmcc runs a Monte Carlo of 10^9 samples or a synthetic experiment raises KeyboardInterrupt long before the call would end (each would take a minute or
more), Python's own SIGINT handler is back afterwards, and the module then answers as before
(no state left behind). A SIGINT during a call too short to see it is not lost: Python raises
it when the call returns."""

import os
import signal
import threading
import time

import pytest

import gmcc

SQUARE = [[1, 1, 1], [3, 1, 1], [1, 3, 1], [3, 3, 1], [2, 2, 3]]


def interrupt_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def interrupted(call):
    """Run call() with a SIGINT 0.3 s in; the seconds until KeyboardInterrupt came. Python's own
    handler is put in place first: a test runner started in the background of a shell inherits
    SIGINT ignored, and then Python installs none."""
    inherited = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        start = time.monotonic()
        timer = interrupt_after(0.3)
        try:
            with pytest.raises(KeyboardInterrupt):
                call()
        finally:
            timer.cancel()
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # Python's handler restored
        return time.monotonic() - start
    finally:
        signal.signal(signal.SIGINT, inherited)


def test_monte_carlo_stops_and_the_module_answers_as_before():
    fs = gmcc.feasible_set(SQUARE, [[1, 1, 1], [2, 1, 1]])
    before = gmcc.mean_3d(fs, method="monte-carlo", samples=100000, seed=7)
    # 10^9 samples take about a minute; the interrupt lands within 2^16 samples of the signal.
    took = interrupted(lambda: gmcc.mean_3d(fs, method="monte-carlo", samples=10**9, seed=7))
    assert took < 30
    after = gmcc.mean_3d(fs, method="monte-carlo", samples=100000, seed=7)
    assert after.map == before.map and after.samples_kept == before.samples_kept


def test_experiment_stops():
    # 90,000 scenes per cell (3.96 million records, under Python's cap): minutes uninterrupted.
    took = interrupted(lambda: gmcc.reproduce_synthetic(scenes=90000, threads=2))
    assert took < 30
    small = gmcc.reproduce_synthetic(scenes=2, max_surfaces=2, frame=False)
    assert len(small) == 4 * 2 * 2  # lights × surface counts × scenes: a whole run after it


def test_a_signal_no_check_saw_is_raised_when_the_call_returns():
    fs = gmcc.feasible_set(SQUARE, [[1, 1, 1], [2, 1, 1]])
    # The closed form at 2^19 bits takes about a second and has no check: the SIGINT at 0.3 s
    # is held by gmcc's handler and handed to Python as the call returns.
    took = interrupted(lambda: gmcc.mean_3d(fs, precision=2**19))
    assert took < 60
    assert gmcc.mean_3d(fs).map is not None
