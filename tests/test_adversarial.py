"""The adversarial families of tests/bench/adversarial_families.py (issue 26: every box
meets every other, almost no feature pair is near) at small sizes: every broad phase
("range", "bvh", "boxes", "auto") gives exactly brute force's answer (collides, first
contact, pairs, touching features and their times) in first-contact and all-contacts
modes, with the apart and the hitting motions of each family. The families' docstring
states which pairs cannot touch (hit=False); there the answer must be "no contact".

auto chooses per body pair by estimated cost (lib/scene/auto_cost.h): range where a
sampled element's box meets many of the other body's boxes on each time piece (every box
meets every other here), bvh where it meets few. The larger cases (compared with bvh,
itself compared with brute force above) and the index cases take range: answers must
not depend on the choice.
"""
import math
import os
import sys

import pytest

import polyccd as P
from test_scene_corpus import summary

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench"))
import adversarial_families as af  # noqa: E402

METHODS = ("range", "bvh", "boxes", "auto")
TOL = "1e-9"


def answers(bodies, method, all_contacts):
    return summary(P.check(bodies, broad_phase=method, all_contacts=all_contacts, time_tolerance=TOL))


@pytest.mark.parametrize("family", af.FAMILIES)
@pytest.mark.parametrize("hit", [False, True])
@pytest.mark.parametrize("all_contacts", [False, True])
def test_every_method_equals_brute_force(family, hit, all_contacts):
    bodies = af.make(P, family, 24, hit)
    want = answers(bodies, "brute", all_contacts)
    assert want[0] is hit, f"{family}, hit={hit}: brute force says {want}"
    for m in METHODS:
        assert answers(bodies, m, all_contacts) == want, f"{family}, hit={hit}: {m} != brute force"


@pytest.mark.parametrize("family", ["slivers", "plates", "balls"])
@pytest.mark.parametrize("hit", [False, True])
def test_auto_by_evidence_equals_bvh(family, hit):
    bodies = af.make(P, family, 160, hit)  # 80 elements per body: auto takes range
    want = answers(bodies, "bvh", False)
    assert want[0] is hit
    for m in ("auto", "range"):
        assert answers(bodies, m, False) == want, f"{family}, hit={hit}: {m} != bvh"


def query_bodies(family, n):
    """The second body of a family split into one-triangle (or one-ball) query bodies."""
    stored, moving = af.make(P, family, n, True)
    shape, motion = moving.shape, moving.motion
    out = []
    if family == "balls":
        for c, r in zip(shape.centers, shape.radii):
            out.append(P.Body(P.Spheres([c], [r]), motion))
    else:
        for tri in shape.triangles:
            out.append(P.Body(P.Mesh([shape.vertices[i] for i in tri], [[0, 1, 2]]), motion))
    return stored, out


@pytest.mark.parametrize("family", af.FAMILIES)
def test_index_auto_equals_brute_force(family):
    stored, queries = query_bodies(family, 80)
    ix = P.Index(stored)
    for m in METHODS:
        got = [summary(r) for r in ix.query_many(queries, broad_phase=m, time_tolerance=TOL)]
        for q, g in zip(queries, got):
            assert g == summary(P.check([stored, q], broad_phase="brute", time_tolerance=TOL)), (
                f"{family}: index {m} != brute force")


@pytest.mark.parametrize("family", sorted(af.NORMAL))
@pytest.mark.parametrize("motion", ["axis", "general"])
def test_rotations_equal_brute_force(family, motion):
    """Body 1 turning about its planes' normal (apart by construction): range's exact
    fixed-axis conditions ("axis") and its general clauses ("general")."""
    bodies = af.make(P, family, 24, motion=motion)
    want = answers(bodies, "brute", False)
    assert want[0] is False, f"{family}, {motion}: touches: {want}"
    for m in METHODS:
        assert answers(bodies, m, False) == want, f"{family}, {motion}: {m} != brute force"


def fan(k, z0, side):
    """k triangles around the z axis, their common edge (0, 0, z0) (0, 0, z0 + 1), rims at
    the angles (2 j + side) pi / k on the 2^-4 grid (as adversarial_families.fans)."""
    V = [[0, 0, z0], [0, 0, z0 + 1]]
    for j in range(k):
        a = math.pi * (2 * j + side) / k
        V.append([round(4 * math.cos(a) * 16) / 16, round(4 * math.sin(a) * 16) / 16, z0 + 5])
    return P.Mesh(V, [[0, 1, 2 + j] for j in range(k)])


# The range phase's static pass goes by edges (lib/range/range_index.h,
# static_candidates): an edge of one triangle meeting the other, then every triangle
# on that edge. Cases built so that the pairs touching at t = 0 are known: two fans
# whose axis edges overlap at t = 0 (every triangle pair touches, on the axis); a point
# triangle (three equal indices: no edge of its own) inside a triangle, on its side,
# at its corner, and off it.
STATIC = {
    "fans overlapping": lambda: [P.Body(fan(6, 0, 0)),
                                 P.Body(fan(6, 0.5, 1), P.Motion(translation=[[0, 0], [0, 0], [0, 1]]))],
    "fans touching at an end": lambda: [P.Body(fan(5, 0, 0)), P.Body(fan(5, 1, 1))],
    "point triangles": lambda: [
        P.Body(P.Mesh([[0, 0, 0], [4, 0, 0], [0, 4, 0]], [[0, 1, 2]])),
        P.Body(P.Mesh([[1, 1, 0], [2, 0, 0], [0, 4, 0], [3, 3, 1]], [[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3]]),
               P.Motion(translation=[[0, 0], [0, 0], [0, 1]]))],
}


@pytest.mark.parametrize("case", sorted(STATIC))
@pytest.mark.parametrize("all_contacts", [False, True])
def test_static_pass_by_edges_equals_brute_force(case, all_contacts):
    bodies = STATIC[case]()
    want = answers(bodies, "brute", all_contacts)
    assert want[0] is True, f"{case}: brute force says apart"
    for m in METHODS:
        for pair in (bodies, bodies[::-1]):
            got = answers(pair, m, all_contacts)
            assert got == answers(pair, "brute", all_contacts), f"{case}: {m} != brute force"
