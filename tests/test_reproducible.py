"""The same bytes out for any rounding mode, thread count, broad phase and repeat, on
random scenes and index queries (issue 15, item 2).

tests/test_rounding_modes.py covers the primitive queries (the shared set and the
corpus) under the four modes; tests/test_scene_property.py compares the broad phases
and thread counts with brute force under round-to-nearest. Here every combination of
caller rounding mode x threads x broad phase x repeat must give exactly the answer of
the reference run (round-to-nearest, one thread, "auto"): collides, every exact time
bound, features, pairs and their order (scene summaries without float approximations:
a float made under FE_UPWARD may differ in its last bit; the Fractions may not).

POLYCCD_REPRO_COUNT changes the number of random scenes (default 12).
"""
import os
import random

import pytest

import polyccd as P
from test_rounding_modes import under
from test_scene_property import SEED, random_scene, summary

COUNT = int(os.environ.get("POLYCCD_REPRO_COUNT", "12"))
MODES = ("nearest", "downward", "upward", "towardzero")
PHASES = ("auto", "boxes", "brute", "range", "bvh")


def scenes():
    return [random_scene(random.Random(SEED * 7919 + k)) for k in range(COUNT)]


@pytest.fixture(scope="module")
def cases():
    out = []
    for bodies in scenes():
        for all_contacts in (False, True):
            ref = summary(P.check(bodies, all_contacts=all_contacts, time_tolerance="1e-9"))
            out.append((bodies, all_contacts, ref))
    return out


def test_the_scenes_are_not_trivial(cases):
    assert sum(1 for _, _, ref in cases if ref[0]) >= len(cases) // 4


@pytest.mark.parametrize("mode", MODES)
def test_scenes_give_the_same_bytes(cases, mode):
    for k, (bodies, all_contacts, ref) in enumerate(cases):
        for phase in PHASES:
            for threads in (1, 3):
                got = under(mode, lambda: summary(P.check(
                    bodies, all_contacts=all_contacts, threads=threads, broad_phase=phase,
                    time_tolerance="1e-9")))
                assert got == ref, (k, all_contacts, mode, phase, threads)


@pytest.mark.parametrize("mode", MODES)
def test_index_queries_give_the_same_bytes(mode):
    for k, bodies in enumerate(scenes()):
        ix = P.Index(bodies[0])
        ref = [summary(ix.query(b, all_contacts=True, time_tolerance="1e-9")) for b in bodies[1:]]
        for threads in (1, 3):
            one = [under(mode, lambda: summary(ix.query(b, all_contacts=True, threads=threads,
                                                        time_tolerance="1e-9")))
                   for b in bodies[1:]]
            many = under(mode, lambda: [summary(r) for r in ix.query_many(
                bodies[1:], all_contacts=True, threads=threads, time_tolerance="1e-9")])
            assert one == ref and many == ref, (k, mode, threads)


def corpus_scenes():
    from pathlib import Path
    from polyccd.apps import _corpus
    out = []
    for path in sorted((Path(__file__).resolve().parents[1] / "corpus").glob("**/*.json")):
        what, case = _corpus.read_case(path)
        if what == "scene":
            out.append((path.name, case))
    return out


@pytest.fixture(scope="module")
def corpus_refs():
    from polyccd.apps import _corpus
    cases = corpus_scenes()
    return [(name, case, all_contacts,
             summary(_corpus.solve_scene_case(case, all_contacts=all_contacts)))
            for name, case in cases for all_contacts in (False, True)]


@pytest.mark.parametrize("mode", MODES)
def test_corpus_scenes_give_the_same_bytes(corpus_refs, mode):
    """Every scene of corpus/ (its own tolerance, all contacts too) on 3 threads under
    each mode gives the bytes of round-to-nearest on one thread."""
    from polyccd.apps import _corpus
    assert len(corpus_refs) > 100
    for name, case, all_contacts, ref in corpus_refs:
        got = under(mode, lambda: summary(_corpus.solve_scene_case(
            case, all_contacts=all_contacts, threads=3)))
        assert got == ref, (name, all_contacts, mode)
