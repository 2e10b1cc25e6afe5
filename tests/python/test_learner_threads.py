"""CanonicalLearner3 and CanonicalLearner2 shared by many Python threads (issue 42): add() and
gamut() release the GIL, and 8 threads adding to one learner at once crashed it (SIGSEGV, a heap
corruption abort or a double free). Each learner now takes its own lock: the learner fed from 8
threads at once ends with every image counted and the same gamut as one fed the same images in
one thread (a hull does not depend on the order of its points)."""

import random
import threading

import gmcc


def colour_sets(seed, n, size):
    rng = random.Random(seed)
    return [[[rng.randint(1, 4000), rng.randint(1, 4000), rng.randint(1, 4000)] for _ in range(size)] for _ in range(n)]


def feed(learner, sets, light, threads):
    """Add every set to `learner`, the sets dealt round-robin to `threads` threads started together,
    each also reading the gamut as it goes."""
    barrier = threading.Barrier(threads)
    errors = []

    def work(k):
        try:
            barrier.wait()
            for i in range(k, len(sets), threads):
                learner.add(sets[i], light)
                if i % 5 == 0:
                    learner.gamut()
        except Exception as e:  # noqa: BLE001 - reported below
            errors.append(e)

    pool = [threading.Thread(target=work, args=(k,)) for k in range(threads)]
    for t in pool:
        t.start()
    for t in pool:
        t.join()
    assert errors == []


def test_learner3_from_eight_threads():
    sets = colour_sets(42, 160, 40)
    shared, alone = gmcc.CanonicalLearner3(intensity="none"), gmcc.CanonicalLearner3(intensity="none")
    feed(shared, sets, [2, 3, 5], threads=8)
    feed(alone, sets, [2, 3, 5], threads=1)
    assert shared.images == alone.images == len(sets)
    assert shared.contributing == alone.contributing
    assert shared.gamut() == alone.gamut()


def test_learner2_from_eight_threads():
    sets = colour_sets(43, 160, 40)
    shared, alone = gmcc.CanonicalLearner2(), gmcc.CanonicalLearner2()
    feed(shared, sets, [2, 3, 5], threads=8)
    feed(alone, sets, [2, 3, 5], threads=1)
    assert shared.images == alone.images == len(sets)
    assert sorted(shared.gamut()) == sorted(alone.gamut())
