"""polyccd.solve_linear_many (pccd_solve_linear_batch_d) against single solve_linear calls:
every entry must be the single call's answer (collides, stage, exactness; the time as the
outward-rounded doubles of the single call's exact enclosure), for 1 and 2 threads, with
and without a time, on the shared public queries, simulation-like random steps, crossings
that miss or graze (test_linear_filter_oracle's generators) and small-integer queries
full of ties, touching boxes and coplanar motion.
"""
import math
import os
import random
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import polyccd
from polyccd.apps import _csv
import test_linear_filter_oracle as crossings

QUERY_DIR = Path(os.environ.get("POLYCCD_QUERY_DIR", Path(__file__).resolve().parents[2] / "shared/data/ccd-queries"))


def _random_steps(kind, n, seed):
    rng = np.random.default_rng(seed)
    size = 10 ** rng.uniform(-2, 0, (n, 1, 1))
    t0 = rng.uniform(-1, 1, (n, 4, 3)) * size
    t1 = t0 + rng.uniform(-1, 1, (n, 4, 3)) * size * 10 ** rng.uniform(-3, 0, (n, 1, 1))
    return t0, t1


def _small_integers(kind, n, seed):
    rng = np.random.default_rng(seed)
    return (rng.integers(-1, 2, (n, 4, 3)).astype(float), rng.integers(-1, 2, (n, 4, 3)).astype(float))


def _crossings(kind, n, seed):
    make = crossings._vertex_face if kind == "vertex-face" else crossings._edge_edge
    pairs = [make(random.Random(f"batch:{seed}:{i}"), ("miss", "graze", "hit")[i % 3]) for i in range(n)]
    return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])


def _shared(kind):
    files = sorted(QUERY_DIR.rglob(f"{kind}/*.csv")) if QUERY_DIR.is_dir() else []
    if not files:
        pytest.skip(f"no shared {kind} queries under {QUERY_DIR}")
    t0, t1 = [], []
    for path in files:
        qs = _csv.read_csv(path, kind)
        keep = [i for i in range(len(qs.truth)) if i not in qs.inexact]
        t0.append(np.asarray(qs.t0)[keep])
        t1.append(np.asarray(qs.t1)[keep])
    return np.concatenate(t0), np.concatenate(t1)


def _rounded_down(x, q):
    """x is the largest double <= the rational q."""
    return Fraction(x) <= q < Fraction(math.nextafter(x, math.inf))


def _rounded_up(x, q):
    return Fraction(math.nextafter(x, -math.inf)) < q <= Fraction(x)


def _same_as_single(kind, t0, t1, threads, want_time):
    npts = 4 if kind in ("vertex-face", "edge-edge") else 3 if kind == "vertex-edge" else 2
    t0, t1 = np.ascontiguousarray(t0[:, :npts]), np.ascontiguousarray(t1[:, :npts])
    b = polyccd.solve_linear_many(kind, t0, t1, time_tolerance="1e-6", want_time=want_time,
                                  threads=threads)
    assert len(b) == len(t0)
    bad = []
    for k in range(len(t0)):
        r = polyccd.solve_linear(kind, t0[k], t1[k], time_tolerance="1e-6", want_time=want_time)
        ok = (b.collides[k] == r.collides and b.stage[k] == r.stage
              and b.exact[k] == (r.collides and r.first_contact.exact is not None))
        if r.collides:
            ok = ok and _rounded_down(b.lo[k], r.first_contact.lo) and _rounded_up(b.hi[k], r.first_contact.hi)
        else:
            ok = ok and math.isnan(b.lo[k]) and math.isnan(b.hi[k])
        if not ok:
            bad.append((k, r, b.collides[k], b.stage[k], b.lo[k], b.hi[k], b.exact[k]))
    assert bad == [], f"{len(bad)} of {len(t0)} differ, first: {bad[0]}"
    return b


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("want_time", [True, False])
@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge", "vertex-edge", "vertex-vertex"])
def test_batch_equals_single_calls(kind, want_time, threads):
    for seed, make in enumerate((_random_steps, _small_integers)):
        _same_as_single(kind, *make(kind, 700, seed), threads, want_time)
    if kind in ("vertex-face", "edge-edge"):
        b = _same_as_single(kind, *_crossings(kind, 600, 7), threads, want_time)
        assert b.collides.any() and not b.collides.all()


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge"])
def test_batch_equals_single_calls_on_the_shared_queries(kind, threads):
    b = _same_as_single(kind, *_shared(kind), threads, True)
    assert b.collides.any()


def test_empty_batch():
    z = np.zeros((0, 4, 3))
    b = polyccd.solve_linear_many("vertex-face", z, z)
    assert len(b) == 0 and b.lo.shape == (0,)


def test_batch_errors_name_the_place():
    t0, t1 = _random_steps("vertex-face", 5, 1)
    t1[3, 2, 1] = math.inf
    with pytest.raises(polyccd.InputError, match=r"^t1\[3\]\[2\]\[1\]: "):
        polyccd.solve_linear_many("vertex-face", t0, t1)
    with pytest.raises(polyccd.InputError, match=r"^t0: expected shape \(n, 4, 3\)"):
        polyccd.solve_linear_many("vertex-face", t0[:, :3], t1)
    with pytest.raises(polyccd.InputError, match=r"^t1: expected shape"):
        polyccd.solve_linear_many("vertex-face", t0, t1[:4])
    with pytest.raises(polyccd.InputError, match=r"^opt\.threads: 0 is outside 1\.\.1024"):
        polyccd.solve_linear_many("vertex-face", t0, t0, threads=0)
    with pytest.raises(polyccd.InputError, match="sphere-sphere"):
        polyccd.solve_linear_many("sphere-sphere", t0[:, :2], t0[:, :2])
    with pytest.raises(polyccd.InputError, match=r"^config\.time_tolerance: "):
        polyccd.solve_linear_many("vertex-face", t0, t0, time_tolerance="-1")
