"""The on-line index (polyccd.Index) on every body-level corpus case (corpus/bodies):
two bodies against the case's expect block and brute force; more bodies: every ordered
pair (i, j), the stored body i and the query j, against brute force's entry of that
pair in the whole scene (test_index.py holds the random scenes and the rest).
"""
from pathlib import Path

import pytest

import polyccd as P
import polyccd.apps
from helpers import summary
from test_scene_corpus import check_time, exact, expected_time, read

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "bodies"
FILES = sorted(CORPUS.rglob("*.json"))

# ---------------------------------------------------------------- the body corpus

def _case(path):
    doc = read(path)
    tol = exact(doc.get("options", {}).get("time_tolerance", "1e-12"))
    bodies, _options, _expect = P.apps.load_scene(str(path))
    return doc, tol, bodies


def _pair_view(r, swap):
    """A one-pair SceneResult (or a scene's PairResult) as (names, time, contacts) with
    contacts as a sorted tuple; swap: exchange the two bodies' roles."""
    def t(ct):
        return (ct.lo, ct.hi, ct.exact)
    names = tuple(reversed(r.names)) if swap else r.names
    cs = [((c.b, c.a) if swap else (c.a, c.b)) + (t(c.first_contact),) for c in r.contacts]
    return names, t(r.first_contact), tuple(sorted(cs))


TWO = [p for p in FILES if len(read(p)["bodies"]) == 2]
MORE = [p for p in FILES if len(read(p)["bodies"]) > 2]


@pytest.mark.parametrize("path", TWO, ids=[str(p.relative_to(CORPUS)) for p in TWO])
def test_corpus_two_bodies(path):
    doc, tol, bodies = _case(path)
    expect = doc["expect"]
    names = [b.name for b in bodies]
    ix = P.Index(bodies[0])
    res = ix.query(bodies[1], time_tolerance=tol)
    # Against the case's expect block (the independent oracle's answer).
    assert res.collides == expect["collides"], res
    if not expect["collides"]:
        assert res.first_contact is None and res.pairs == () and res.first == ()
    else:
        want = expected_time(expect)
        if want is not None:
            check_time(res.first_contact, want, tol, "first_contact")
        assert [p.names for p in res.pairs] == [tuple(names)] and res.first == res.pairs
        assert res.pairs[0].bodies == (0, 1)
        got = [(c.a, c.b) for c in res.pairs[0].contacts]
        for f in expect.get("features", []):
            fa, fb = (f["a"][0], int(f["a"][1])), (f["b"][0], int(f["b"][1]))
            oriented = (fa, fb) if tuple(f["bodies"]) == tuple(names) else (fb, fa)
            assert oriented in got, (oriented, got)
    # Against brute force, every broad phase, both modes.
    for all_contacts in (False, True):
        want = summary(P.check(bodies, broad_phase="brute", all_contacts=all_contacts,
                               time_tolerance=tol))
        for broad_phase in ("auto", "range", "boxes", "brute"):
            got = summary(ix.query(bodies[1], broad_phase=broad_phase, all_contacts=all_contacts,
                                   time_tolerance=tol))
            assert got == want, (broad_phase, all_contacts)


@pytest.mark.parametrize("path", MORE, ids=[str(p.relative_to(CORPUS)) for p in MORE])
def test_corpus_every_pair_of_more_bodies(path):
    _doc, tol, bodies = _case(path)
    expect = P.apps.load_scene(str(path))[2]
    for all_contacts in (False, True):
        scene = P.check(bodies, broad_phase="brute", all_contacts=all_contacts, time_tolerance=tol)
        assert tuple(p.names for p in scene.pairs) == expect.pairs
        entry = {p.bodies: p for p in scene.pairs}
        for i in range(len(bodies)):
            ix = P.Index(bodies[i])
            for j in range(len(bodies)):
                if i == j:
                    continue
                res = ix.query(bodies[j], all_contacts=all_contacts, time_tolerance=tol)
                p = entry.get((min(i, j), max(i, j)))
                if p is None:
                    assert summary(res) == (False, None, (), ()), (i, j)
                    continue
                assert res.collides and len(res.pairs) == 1 and res.first == res.pairs, (i, j)
                got = res.pairs[0]
                assert got.bodies == (0, 1) and got.names == (bodies[i].name, bodies[j].name)
                assert res.first_contact == got.first_contact
                if i < j:  # the same orientation: identical, order of contacts included
                    assert got.contacts == p.contacts, (i, j, all_contacts)
                assert _pair_view(got, False) == _pair_view(p, i > j), (i, j, all_contacts)


def test_corpus_has_both_kinds():
    assert len(TWO) >= 40 and len(MORE) >= 5, (len(TWO), len(MORE))
