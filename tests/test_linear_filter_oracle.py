"""The static filter of linear double queries (lib/pred/linear_filter.h, linear_crossing.h)
against the independent exact oracle (tests/oracle.py) on the queries it is built for:
simulation-like vertex-face and edge-edge steps whose primitives cross each other's plane
once, missing by a relative margin of 10^-1 to 10^-13 (the filter's "misses" verdict),
touching inside by 0 or 10^-1 to 10^-17 ("graze": the filter must leave those to the solver), or
well inside, plus boxes apart and planes never reached; with and without a time (without
one, certified transversal hits are answered by the filter too).

Every query is doubles at t = 0 and t = 1 (the positions of a planted configuration at a
time t_c, moved back and forth along random velocities in floating point: the oracle
judges the doubles exactly, whatever rounding did). polyccd.solve_linear must agree with
the oracle on `collides`, and on the first contact time when there is one.
"""
import random
from fractions import Fraction

import pytest

import oracle
import polyccd

COUNT = 300  # per kind and mode


def _vec(rng, scale):
    return [rng.uniform(-scale, scale) for _ in range(3)]


def _positions(rng, at_tc, tc, speed, crossing):
    """Doubles at t = 0 and t = 1 of points that pass through at_tc at time tc (up to
    rounding); the points listed in `crossing` get a clear downward z velocity, so
    they cross the plane z = 0 of the others there."""
    t0, t1 = [], []
    for i, p in enumerate(at_tc):
        v = _vec(rng, speed)
        if i in crossing:
            v[2] = -speed * rng.uniform(1, 3)
        else:
            v[2] *= 0.1
        t0.append([p[k] - tc * v[k] for k in range(3)])
        t1.append([p[k] + (1 - tc) * v[k] for k in range(3)])
    return t0, t1


def _graze(rng, s):
    """How far inside a grazing contact is planted: 0 (on the edge, up to the rounding of
    the positions) or s 10^-1 to s 10^-17 (below the filter's resolution)."""
    return 0.0 if rng.random() < 0.3 else s * 10 ** -rng.uniform(1, 17)


def _vertex_face(rng, mode):
    s = 10 ** rng.uniform(-2, 0)
    tri = [[0.0, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s, 0.0]]
    margin = s * 10 ** -rng.uniform(1, 13)
    if mode in ("miss", "graze"):  # just beyond (inside) the hypotenuse, or the edge x = 0
        m = margin if mode == "miss" else -_graze(rng, s)
        u = rng.uniform(0.1, 0.9)
        v = [u * s + m, (1 - u) * s + m, 0.0] if rng.random() < 0.5 else [-m, u * s, 0.0]
    else:  # inside
        u, w = rng.uniform(0.05, 0.45), rng.uniform(0.05, 0.45)
        v = [u * s, w * s, 0.0]
    d = s * 10 ** rng.uniform(-3, -1)
    return _positions(rng, [v] + tri, rng.uniform(0.05, 0.95), d, crossing={0})


def _edge_edge(rng, mode):
    s = 10 ** rng.uniform(-2, 0)
    margin = s * 10 ** -rng.uniform(1, 13)
    a = [[0.0, 0.0, 0.0], [s, 0.0, 0.0]]
    x = rng.uniform(0.1, 0.9) * s
    if mode in ("miss", "graze"):  # b crosses the line of a just beyond (inside) a's end
        m = margin if mode == "miss" else -_graze(rng, s)
        x = s + m if rng.random() < 0.5 else -m
    b = [[x, -s / 2, 0.0], [x, s / 2, 0.0]]
    d = s * 10 ** rng.uniform(-3, -1)
    t0, t1 = _positions(rng, a + b, rng.uniform(0.05, 0.95), d, crossing={2, 3})
    for p in (2, 3):  # b moves as one piece through the plane of a
        t0[p][2], t1[p][2] = t0[2][2], t1[2][2]
    if rng.random() < 0.5:  # the grazing end on either segment of the query
        t0, t1 = t0[2:] + t0[:2], t1[2:] + t1[:2]
    return t0, t1


@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge"])
@pytest.mark.parametrize("mode", ["miss", "graze", "hit"])
@pytest.mark.parametrize("want_time", [True, False])
def test_filter_agrees_with_the_oracle(kind, mode, want_time):
    make = _vertex_face if kind == "vertex-face" else _edge_edge
    bad, stages = [], {}
    for i in range(COUNT):
        rng = random.Random(f"linear-filter:{kind}:{mode}:{i}")
        t0, t1 = make(rng, mode)
        got = polyccd.solve_linear(kind, t0, t1, want_time=want_time)
        stages[got.stage] = stages.get(got.stage, 0) + 1
        pts = [[[Fraction(a[k]), Fraction(b[k]) - Fraction(a[k])] for k in range(3)]
               for a, b in zip(t0, t1)]
        want = oracle.solve(kind, pts)
        if got.collides != want.collides:
            bad.append((i, t0, t1, got.collides, want.collides))
        elif not want_time:
            pass
        elif want.collides and oracle.is_rational(want.first):
            if got.first_contact.exact != want.first:
                bad.append((i, t0, t1, got.first_contact, want.first))
        elif want.collides and not oracle.time_in(want.first, got.first_contact.lo, got.first_contact.hi):
            bad.append((i, t0, t1, got.first_contact, oracle.describe(want.first)))
    assert bad == [], f"{len(bad)} disagreements, first: {bad[0]}"
    # The misses must be decided without the exact stage for the filter to matter.
    if mode == "miss":
        assert stages.get("exact", 0) < COUNT // 10, stages


@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge"])
@pytest.mark.parametrize("want_time,tolerance",
                         [(True, "1e-12"), (True, "1e-6"), (True, "1e-20"), (False, "1e-12")])
def test_filter_answers_equal_the_staged_solver(kind, want_time, tolerance):
    """The filter's answers (misses and certified hits) are the staged solver's: the same
    query through polyccd.solve (pccd_query_solve, which has no filter) gives the same
    collides, enclosure, exactness and features (the stage may differ)."""
    make = _vertex_face if kind == "vertex-face" else _edge_edge
    bad = 0
    for i in range(COUNT):
        rng = random.Random(f"linear-filter-same:{kind}:{i}")
        t0, t1 = make(rng, ("miss", "graze", "hit")[i % 3])
        got = polyccd.solve_linear(kind, t0, t1, time_tolerance=tolerance, want_time=want_time)
        pts = [[[Fraction(a[k]), Fraction(b[k]) - Fraction(a[k])] for k in range(3)]
               for a, b in zip(t0, t1)]
        ref = polyccd.solve(kind, pts, time_tolerance=tolerance, want_time=want_time)
        if (got.collides, got.first_contact, got.features) != (ref.collides, ref.first_contact, ref.features):
            bad += 1
            first = (i, got, ref)
        elif want_time and got.collides and got.first_contact.hi - got.first_contact.lo > Fraction(tolerance):
            bad += 1  # tolerances below the doubles' resolution: the exact stage must finish
            first = (i, got, "wider than the tolerance")
    assert bad == 0, f"{bad} differ, first: {first}"


@pytest.mark.parametrize("kind", ["vertex-face", "edge-edge"])
def test_certified_hits_at_rational_times_are_exact(kind):
    """Transversal hits whose first time is a rational a / (a + b) (a point, or a whole
    edge, crossing the plane z = 0 of the others from z = a to z = -b): the filter's hit
    path must hand the rational time to the solver's exact search (its modular test must
    not call such a cubic irrational), so solve_linear reports it exactly, like the
    staged solver and the oracle."""
    for i in range(200):
        rng = random.Random(f"linear-filter-rational:{kind}:{i}")
        s = 2.0 ** rng.randint(-6, 3)
        a, b = rng.randint(1, 40), rng.randint(1, 40)
        want = Fraction(a, a + b)
        if kind == "vertex-face":
            u, w = rng.randint(1, 8), rng.randint(1, 8)  # inside the triangle (0,0) (20,0) (0,20)
            tri = [[0.0, 0.0, 0.0], [20 * s, 0.0, 0.0], [0.0, 20 * s, 0.0]]
            t0 = [[u * s, w * s, a * s]] + tri
            t1 = [[u * s, w * s, -b * s]] + tri
        else:
            x = rng.randint(1, 19)  # b crosses the open edge a = (0,0)-(20,0) at (x, 0)
            ea = [[0.0, 0.0, 0.0], [20 * s, 0.0, 0.0]]
            t0 = ea + [[x * s, -s, a * s], [x * s, s, a * s]]
            t1 = ea + [[x * s, -s, -b * s], [x * s, s, -b * s]]
        got = polyccd.solve_linear(kind, t0, t1, time_tolerance="1e-6")
        pts = [[[Fraction(p[k]), Fraction(q[k]) - Fraction(p[k])] for k in range(3)]
               for p, q in zip(t0, t1)]
        assert oracle.solve(kind, pts).first == want
        assert got.collides and got.first_contact.exact == want, (i, got)
