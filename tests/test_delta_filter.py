"""The separating-direction filter of a minimum distance (lib/pred/delta_filter.h).

It may answer "no contact within delta" (stage "bounds") before the staged solver runs,
in pccd_solve_linear_d, the batch and pccd_query_solve alike. Checked here:
  - queries built so that their minimum distance over [0, 1] is known exactly (a
    Pythagorean normal |n| in {3, 7, 9, 11}, so the distance s |n| is rational; checked
    again with the Fraction distance oracle, tests/oracle/oracle_distance.py) at delta
    equal to it, just above and just below (relative 2^-40), tilted, scaled and offset
    so that the filter's doubles round: the answer is "contact" exactly when the minimum
    distance is <= delta; a filter that separated on rounded doubles fails here;
  - every path (single call, batch, exact polynomial query) gives the same answer AND
    stage, on those cases and on the shared query set at two deltas;
  - on the shared query set, every query the filter decides is more than delta apart at
    every sampled time (the oracle, exact).
"""
import os
import random
from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest

import oracle_distance as OD
import polyccd as P

QUERY_DIR = Path(os.environ.get("POLYCCD_QUERY_DIR",
                                Path(__file__).resolve().parents[2] / "shared/data/ccd-queries"))
NORMALS = [((1, 2, 2), 3), ((2, 3, 6), 7), ((1, 4, 8), 9), ((4, 4, 7), 9), ((2, 6, 9), 11),
           ((6, 6, 7), 11), ((-2, 1, 2), 3), ((3, -6, 2), 7)]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def comb(*terms):
    """sum of c * v over (c, v) terms, componentwise in Fractions."""
    return tuple(sum(F(c) * v[a] for c, v in terms) for a in range(3))


def built_case(rng, kind):
    """(kind, points at t = 0, points at t = 1, D): the first primitive approaches the
    second along the normal n from 2 D to D (its closest points interior throughout), so
    the minimum distance over [0, 1] is D, reached at t = 1 only."""
    n, length = rng.choice(NORMALS)
    u = cross(n, (1, 0, 0))  # no normal here is along x
    v = cross(n, u)
    # A 30-bit scale: the filter's cross products and dot products round (their exact
    # values need about 70 bits), yet every coordinate is a double: an integer below
    # 2^53 times 2^-(e + 4) (the built points are multiples of 1/16, at most 32 in size).
    e = rng.randint(20, 60)
    scale = F(rng.randint(2 ** 29, 2 ** 30) | 1, 2 ** e)
    offset = tuple(F(rng.randint(-2 ** 50, 2 ** 50), 2 ** (e + 4)) for _ in range(3))
    s = F(rng.randint(1, 8), 16)  # distance s |n| at t = 1, 2 s |n| at t = 0
    slide = F(rng.randint(-2, 2), 16)  # along the first primitive's own direction

    def place(p):
        return tuple(offset[a] + scale * p[a] for a in range(3))

    def first(h, t):  # the moving side at height h along n, slid by t * slide
        if kind == "vertex-face":
            return [comb((F(1, 4) + t * slide, u), (F(1, 4), v), (h, n))]
        if kind == "edge-edge":
            return [comb((F(-1, 2) + t * slide, u), (h, n)), comb((F(1, 2) + t * slide, u), (h, n))]
        if kind == "vertex-edge":
            return [comb((t * slide, u), (h, n))]
        return [comb((h, n))]

    zero = (0, 0, 0)
    second = {"vertex-face": [zero, u, v],
              "edge-edge": [comb((F(-1, 2), v)), comb((F(1, 2), v))],
              "vertex-edge": [comb((F(-1, 2), u)), comb((F(1, 2), u))],
              "vertex-vertex": [zero]}[kind]
    p0 = [place(p) for p in first(2 * s, 0) + second]
    p1 = [place(p) for p in first(s, 1) + second]
    return kind, p0, p1, s * length * scale


def as_doubles(points):
    out = np.array([[float(x) for x in p] for p in points], dtype=np.float64)
    assert all(F(float(x)) == x for p in points for x in p), "a built coordinate is no double"
    return out


def trajectories(p0, p1):
    return [[[F(a), F(b) - F(a)] for a, b in zip(x0, x1)] for x0, x1 in zip(p0, p1)]


def same_everywhere(kind, t0, t1, delta):
    """The single call's answer, after checking the exact query and the batch agree."""
    got = P.solve_linear(kind, t0, t1, min_distance=delta)
    assert P.solve(kind, trajectories(t0, t1), min_distance=delta) == got
    batch = P.solve_linear_many(kind, t0[None], t1[None], min_distance=delta, threads=1)
    assert bool(batch.collides[0]) == got.collides and batch.stage[0] == got.stage
    return got


@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge", "vertex-edge", "vertex-vertex"])
def test_built_distances_at_just_inside_and_just_outside_delta(kind):
    rng = random.Random(hash(kind) % 1000 + 2026)
    filtered = 0
    for _ in range(40):
        kind, p0, p1, D = built_case(rng, kind)
        t0, t1 = as_doubles(p0), as_doubles(p1)
        pts = trajectories(p0, p1)
        # the construction, checked by the oracle: D at t = 1, 2 D at t = 0, above D between
        assert OD.distance2(kind, pts, F(1)) == D * D
        assert OD.distance2(kind, pts, F(0)) == 4 * D * D
        assert all(OD.distance2(kind, pts, F(k, 8)) > D * D for k in range(8))
        for delta, contact in ((D, True), (D * (1 + F(1, 2 ** 40)), True),
                               (D * (1 - F(1, 2 ** 40)), False), (D / 2, False)):
            r = same_everywhere(kind, t0, t1, str(delta))
            assert r.collides == contact, (kind, p0, p1, delta)
            if contact:
                # within delta first at t = 1 (delta = D) or just before it
                assert r.first_contact.hi <= 1 and r.first_contact.lo > F(1, 2)
                assert (r.first_contact.exact == 1) == (delta == D)
            filtered += r.stage == "bounds"
    # the tilted normals need the filter's certificate (no axis separates at D / 2)
    assert filtered >= 20, filtered


def load_public():
    files = sorted(QUERY_DIR.rglob("*.csv"))
    if not files:
        pytest.skip(f"no public queries under {QUERY_DIR}")
    out = {"vertex-face": ([], []), "edge-edge": ([], [])}
    for path in files:
        rows = [[int(c) for c in line.split(",")] for line in path.read_text().split() if line]
        for i in range(0, len(rows), 8):
            pts = [[F(r[0], r[1]), F(r[2], r[3]), F(r[4], r[5])] for r in rows[i:i + 8]]
            out[path.parent.name][0].append(pts[:4])
            out[path.parent.name][1].append(pts[4:])
    return out


@pytest.mark.parametrize("delta", [F(1, 2 ** 20), F(1, 2 ** 10)])
def test_public_queries_same_on_every_path_and_filtered_ones_apart(delta):
    rng = random.Random(5)
    decided = 0
    for kind, (a, b) in load_public().items():
        t0 = np.array([[[float(x) for x in p] for p in q] for q in a])
        t1 = np.array([[[float(x) for x in p] for p in q] for q in b])
        batch = P.solve_linear_many(kind, t0, t1, min_distance=delta, threads=2)
        for k in range(len(a)):
            got = P.solve_linear(kind, t0[k], t1[k], min_distance=delta)
            assert bool(batch.collides[k]) == got.collides and batch.stage[k] == got.stage
            if got.stage != "bounds" and rng.random() < 0.9:
                continue  # the exact query for every filtered one and a tenth of the rest
            assert P.solve(kind, trajectories(a[k], b[k]), min_distance=delta) == got
            if got.stage == "bounds":
                decided += 1
                assert not got.collides
                pts = trajectories(a[k], b[k])
                assert all(OD.distance2(kind, pts, F(j, 8)) > delta * delta for j in range(9))
    assert decided > 1000, decided  # most of the set is far from contact
