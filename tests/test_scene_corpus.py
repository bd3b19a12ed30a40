"""Every corpus/bodies/**/*.json scene (polyccd/1): polyccd's scene API against the case's
`expect` block, which tests/tools/make_body_corpus.py wrote from the independent body oracle
(tests/oracle/oracle_body.py), never from polyccd.

Checked (formats.md, EXPECT; docs/python.md, Scenes): collides; first_contact
(an exact rational is reported exactly; an enclosure [lo, hi] must meet the expected
one and be no wider than the case's time tolerance, and must not claim to be exact);
pairs (every body pair in contact; for two bodies, the one pair exactly when they
collide); features (the touching features the oracle found unambiguous must be among
the reported contacts of that pair, which must be one of the scene's first pairs).
Each case is also run with threads=2 and with broad_phase="brute" and "range": the answers
must be identical. A last test goes beyond EXPECT and asks the oracle itself: every reported
pair's enclosure must hold that pair's exact first time, and every reported contact must
really touch then (for mesh-mesh at t* > 0 and sphere sets: exactly the oracle's set).
This file needs polyccd.check: without it every case FAILS (no skip).
"""
import json
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest

import oracle
import oracle_body
from helpers import summary
import polyccd
import polyccd.apps
from oracle_hull import in_hull

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "bodies"
FILES = sorted(CORPUS.rglob("*.json"))
DEFAULT_TOLERANCE = Fraction(1, 10 ** 12)


def exact(x):
    """An exact number of formats.md (JSON numbers were read as Decimal)."""
    if isinstance(x, bool):
        raise ValueError(x)
    return Fraction(x) if not isinstance(x, str) else Fraction(x.strip())


def read(path):
    with open(path) as fh:
        return json.load(fh, parse_float=Decimal)


def run(path, **kw):
    doc = read(path)
    tol = exact(doc.get("options", {}).get("time_tolerance", "1e-12"))
    bodies, _options, _expect = polyccd.apps.load_scene(str(path))
    return doc, tol, bodies, polyccd.check(bodies, time_tolerance=tol, **kw)


def check_time(ct, want, tol, what):
    """ct: a reported ContactTime; want: a Fraction or (lo, hi)."""
    assert ct is not None, "%s: no contact time reported" % what
    assert ct.lo <= ct.hi, "%s: lo > hi in %r" % (what, ct)
    if isinstance(want, Fraction):
        assert ct.exact == want and ct.lo == want and ct.hi == want, (
            "%s: expected exactly %s, got %r" % (what, want, ct))
    else:
        lo, hi = want
        assert ct.exact is None, "%s: t* is irrational (in (%s, %s)), got exact %r" % (
            what, lo, hi, ct)
        assert ct.lo <= hi and lo <= ct.hi, (
            "%s: enclosure [%s, %s] misses the expected (%s, %s)" % (what, ct.lo, ct.hi, lo, hi))
        assert ct.hi - ct.lo <= tol, "%s: enclosure wider than %s: %r" % (what, tol, ct)


def expected_time(expect):
    fc = expect.get("first_contact")
    if fc is None:
        return None
    if isinstance(fc, list):
        lo, hi = exact(fc[0]), exact(fc[1])
        assert lo < hi
        return lo, hi
    return exact(fc)


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_polyccd_meets_expectation(path):
    doc, tol, bodies, res = run(path)
    expect = doc["expect"]
    names = [b["name"] for b in doc["bodies"]]
    assert res.collides == expect["collides"], "collides: expected %s, got %r" % (
        expect["collides"], res)
    if not expect["collides"]:
        assert res.first_contact is None and not res.pairs, res
        return
    want = expected_time(expect)
    if want is not None:
        check_time(res.first_contact, want, tol, "first_contact")
    got_pairs = sorted(tuple(sorted(p.names, key=names.index)) for p in res.pairs)
    if "pairs" in expect:
        want_pairs = sorted(tuple(sorted(p, key=names.index)) for p in expect["pairs"])
    else:
        assert len(names) == 2, "a scene of more than two bodies needs expect.pairs"
        want_pairs = [tuple(names)]
    assert got_pairs == want_pairs, "pairs: expected %s, got %s" % (want_pairs, got_pairs)
    assert res.first, "no first pair reported"
    for p in res.first:
        if want is not None:
            check_time(p.first_contact, want, tol, "first pair %s" % (p.names,))
    for f in expect.get("features", []):
        na, nb = f["bodies"]
        fa, fb = (f["a"][0], int(f["a"][1])), (f["b"][0], int(f["b"][1]))
        pr = [p for p in res.first if set(p.names) == {na, nb}]
        assert pr, "features: pair %s is not among the first pairs %s" % (
            (na, nb), [p.names for p in res.first])
        p = pr[0]
        oriented = (fa, fb) if p.names == (na, nb) else (fb, fa)
        got = [(c.a, c.b) for c in p.contacts]
        assert oriented in got, "features: %s of %s not among the contacts %s" % (
            oriented, p.names, got)


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_threads_and_broad_phases_agree(path):
    _, tol, bodies, res = run(path)
    base = summary(res)
    for kw in ({"threads": 2}, {"broad_phase": "brute"}, {"threads": 2, "broad_phase": "brute"},
               {"broad_phase": "range"}, {"threads": 2, "broad_phase": "range"},
               {"broad_phase": "bvh"}, {"threads": 2, "broad_phase": "bvh"},
               {"threads": 3, "broad_phase": "bvh"}):
        other = summary(polyccd.check(bodies, time_tolerance=tol, **kw))
        assert other == base, "%s differs from threads=1, boxes:\n%r\n%r" % (kw, other, base)


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_pair_call_equals_scene_call(path):
    """Two-body cases: check() is one pccd_pair_solve call; the same bodies solved as a
    pccd_scene give the same answer and the same work counters, for 1-3 threads."""
    from test_scene_property import scene_call
    doc, tol, bodies, base = run(path)
    if len(bodies) != 2:
        pytest.skip("a scene of %d bodies (check() uses a pccd_scene)" % len(bodies))
    for threads in (1, 2, 3):
        got = polyccd.check(bodies, time_tolerance=tol, threads=threads)
        via = scene_call(bodies, time_tolerance=tol, threads=threads)
        assert summary(got) == summary(via) == summary(base), threads
        assert got.stats == via.stats, threads


def test_corpus_is_big_enough():
    cats = {}
    for p in FILES:
        cats[p.parent.name] = cats.get(p.parent.name, 0) + 1
    assert len(FILES) >= 45 and len(cats) >= 5 and min(cats.values()) >= 5, cats


# ---------------------------------------------------------------- against the oracle itself

def _holds(G, A, B, fa, fb, t):
    """Exactly: feature fa of body A and fb of body B touch at the oracle time t (in the
    frame of A, tests/oracle/oracle_body.py predicates)."""
    ev = oracle_body.Ev(t, record=False)

    def pts(tag, body, f):
        kind, k = f
        if kind == "vertex":
            return [(tag, k)]
        if kind == "edge":
            return [(tag, v) for v in body.edges[k]]
        if kind == "triangle":
            return [(tag, v) for v in body.triangles[k]]
        return [(tag, k)]                        # sphere: its centre
    pa, pb = pts("A", A, fa), pts("B", B, fb)
    kinds = (fa[0], fb[0])
    if kinds == ("vertex", "triangle"):
        return G.point_in_triangle(ev, pa[0], *pb)
    if kinds == ("triangle", "vertex"):
        return G.point_in_triangle(ev, pb[0], *pa)
    if kinds == ("edge", "edge"):
        return G.segments_meet(ev, pa[0], pa[1], pb[0], pb[1])
    if kinds == ("sphere", "sphere"):
        return G.balls_meet(ev, pa[0], pb[0])
    if "sphere" in kinds:
        (c, _), other = ((pa[0], None), pb) if kinds[0] == "sphere" else ((pb[0], None), pa)
        other = list(other) + [other[-1]] * (3 - len(other))   # a vertex / edge as a triangle
        return G.ball_meets_triangle(ev, c, *other)
    if kinds == ("triangle", "triangle"):
        if not (isinstance(t, Fraction) and t == 0):
            return False
        P = [oracle_body.world_at(A, A.vertices[v], 0) for _, v in pa]
        Q = [oracle_body.world_at(B, B.vertices[v], 0) for _, v in pb]
        return in_hull([tuple(x - y for x, y in zip(p, q)) for p in P for q in Q], (0, 0, 0))
    raise AssertionError("unknown feature kinds %r" % (kinds,))


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_every_pair_and_contact_against_the_oracle(path):
    """Stronger than EXPECT: every reported pair's enclosure holds the oracle's exact time
    of that pair, and every reported contact really touches at that time; for two meshes
    (t* > 0) and two sphere sets the contacts are exactly the oracle's touching set."""
    doc, tol, bodies, res = run(path)
    ans = oracle_body.solve_scene(doc)
    assert sorted(p.bodies for p in res.pairs) == sorted(ans.pairs), (
        [p.bodies for p in res.pairs], sorted(ans.pairs))
    for p in res.pairs:
        a = ans.pairs[p.bodies]
        ct = p.first_contact
        assert oracle.time_in(a.first, ct.lo, ct.hi), (p.names, oracle.describe(a.first), ct)
        assert (ct.exact is not None) == isinstance(a.first, Fraction), (p.names, ct)
        A, B = ans.bodies[p.bodies[0]], ans.bodies[p.bodies[1]]
        G = oracle_body.Pair(A, B)
        got = set()
        for c in p.contacts:
            assert _holds(G, A, B, c.a, c.b, a.first), (
                "%s: reported contact %s-%s does not touch at t* = %s"
                % (p.names, c.a, c.b, oracle.describe(a.first)))
            got.add((c.a, c.b))
        t0 = isinstance(a.first, Fraction) and a.first == 0
        if (A.kind == B.kind == "mesh" and not t0) or A.kind == B.kind == "spheres":
            assert got == set(a.touching), (p.names, sorted(got), a.touching)
