"""Every corpus/solids/*.json scene (polyccd/1 with solid meshes): polyccd against the
case's `expect` block and against the independent solid oracle itself
(tests/oracle/oracle_solid.py: exact ray parity in Fractions over the body oracle), for
every broad phase and 1-2 threads, in decide mode, through the on-line Index, and with
the solids taken as surfaces (then the answer must be the surface oracle's).
tests/tools/make_solid_corpus.py wrote the expectations from the oracle and checks that
they equal the answers reasoned out by hand.
"""
import json
from fractions import Fraction
from pathlib import Path

import pytest

import oracle
import oracle_body
import oracle_solid
from helpers import summary
import polyccd
import polyccd.apps

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "solids"
FILES = sorted(CORPUS.glob("*.json"))
IDS = [p.stem for p in FILES]


def read(path):
    with open(path) as fh:
        return json.load(fh)


def surfaces(bodies):
    """The same bodies with every solid mesh taken as its surface."""
    out = []
    for b in bodies:
        shape = b.shape
        if isinstance(shape, polyccd.Mesh) and shape.solid:
            shape = polyccd.Mesh(shape.exact_vertices(), shape.triangles)
        out.append(polyccd.Body(shape, b.motion, b.name))
    return out


def agrees(res, pairs, first, what):
    """res (a SceneResult) has exactly the oracle's pairs {(i, j): time} and first time."""
    assert res.collides == bool(pairs), (what, res)
    assert sorted(p.bodies for p in res.pairs) == sorted(pairs), (what, res)
    for p in res.pairs:
        ct = p.first_contact
        assert oracle.time_in(pairs[p.bodies], ct.lo, ct.hi), (what, p.names, ct)
        assert (ct.exact is not None) == isinstance(pairs[p.bodies], Fraction), (what, ct)
    if pairs:
        assert oracle.time_in(first, res.first_contact.lo, res.first_contact.hi), (what, res)


def test_corpus_has_the_cases():
    assert len(FILES) >= 20


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_solid_case_meets_expectation_and_oracle(path):
    doc = read(path)
    bodies, _, _ = polyccd.apps.load_scene(str(path))
    expect = doc["expect"]
    ans = oracle_solid.solve(doc)
    res = polyccd.check(bodies)
    assert res.collides == expect["collides"] == ans.collides, res
    if expect["collides"]:
        assert res.first_contact.exact == Fraction(expect["first_contact"]), res
        names = [b["name"] for b in doc["bodies"]]
        assert sorted(list(p.names) for p in res.pairs) == sorted(
            sorted(p, key=names.index) for p in expect["pairs"])
    agrees(res, ans.pairs, ans.first, "solid")
    # A contained pair reports ("solid", 0) with a point the oracle finds inside, alone,
    # or its surface contacts at t = 0 when the surfaces touch then (the static pass
    # comes first); a pair not contained never reports a solid.
    parsed = ans.surface.bodies
    for p in res.pairs:
        solid_contacts = [c for c in p.contacts if "solid" in (c.a[0], c.b[0])]
        if p.bodies not in ans.contained or not solid_contacts:
            assert not solid_contacts, p
            continue
        (c,) = p.contacts
        solid_side = 0 if c.a == ("solid", 0) else 1
        assert (c.a, c.b)[solid_side] == ("solid", 0), c
        kind, k = (c.a, c.b)[1 - solid_side]
        S, Q = parsed[p.bodies[solid_side]], parsed[p.bodies[1 - solid_side]]
        point = Q.vertices[k] if kind == "vertex" else Q.centers[k]
        assert kind == ("vertex" if Q.kind == "mesh" else "sphere")
        verts = [oracle_body.world_at(S, v, 0) for v in S.vertices]
        assert oracle_solid.winding(verts, S.triangles, oracle_body.world_at(Q, point, 0)) != 0


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_solid_case_every_phase_thread_and_mode(path):
    bodies, _, _ = polyccd.apps.load_scene(str(path))
    base = summary(polyccd.check(bodies))
    for kw in ({"threads": 2}, {"broad_phase": "brute"}, {"broad_phase": "boxes"},
               {"broad_phase": "range"}, {"broad_phase": "bvh", "threads": 2}):
        assert summary(polyccd.check(bodies, **kw)) == base, kw
    ans = oracle_solid.solve(read(path))
    decided = polyccd.check(bodies, first_contact=False)
    assert decided.collides == ans.collides
    if len(bodies) == 2:
        for stored, query in ((0, 1), (1, 0)):
            got = polyccd.Index(bodies[stored]).query(bodies[query])
            assert got.collides == ans.collides, (stored, query)
            if ans.collides:
                assert oracle.time_in(ans.first, got.first_contact.lo, got.first_contact.hi)
    # A minimum separation: a contained pair is at distance 0, so it stays a contact.
    near = polyccd.check(bodies, min_distance=Fraction(1, 1000))
    for ij in ans.contained:
        assert ij in [p.bodies for p in near.pairs]


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_solid_case_as_surfaces_is_the_surface_answer(path):
    bodies, _, _ = polyccd.apps.load_scene(str(path))
    surface = oracle_solid.solve(read(path)).surface
    res = polyccd.check(surfaces(bodies))
    agrees(res, {ij: p.first for ij, p in surface.pairs.items()}, surface.first, "surface")


def test_corpus_files_are_what_the_generator_writes():
    """The files hold the generator's cases and expectations (its hand answers checked
    against the oracle), so a case edited by hand fails here."""
    import make_solid_corpus as gen
    assert sorted(name for name, _, _ in gen.CASES) == IDS
    for name, bodies, want in gen.CASES:
        assert (CORPUS / (name + ".json")).read_text() == gen.build(name, bodies, want), name
