"""Steps with polynomial per-vertex paths (pccd_step_set_paths_d; check_step(paths=)).

Checked against things not written here:
  - hand cases with known answers (a vertex on a parabola meeting a static triangle at
    t = 1/2 transversally, tangentially (a double root), missing it by 2^-40, and at the
    irrational t = 1/sqrt(2), checked by squaring the Fraction bounds; within a minimum
    distance 3/4 at t = 1/4);
  - brute force over every primitive pair of random small meshes on random cubic paths
    (and a straight obstacle), each pair solved alone by polyccd.solve on its exact
    Fraction trajectories: the set of touching pairs, each pair's time, the first time;
  - straight paths given as degree-1 coefficients give the answers of V0, V1;
  - bad input names its place.
"""
import random
from fractions import Fraction as F
from itertools import combinations

import numpy as np
import pytest

import polyccd as P

TRI = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)


def vertex_over_triangle(z_coeffs):
    """A vertex at (0.25, 0.25, z(t)) over the static triangle z = 0 (as one path mesh)."""
    c = np.zeros((len(z_coeffs), 4, 3))
    c[0, 0] = (0.25, 0.25, 0)
    c[0, 1:] = TRI
    for k, z in enumerate(z_coeffs):
        c[k, 0, 2] += z
    return c


def test_hand_cases_with_known_times():
    faces = np.array([[1, 2, 3]])
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1, 0, -4]))
    assert r.collides and r.first_contact.exact == F(1, 2)  # 1 - 4 t^2 = 0
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1, -4, 4]))
    assert r.collides and r.first_contact.exact == F(1, 2)  # (1 - 2 t)^2: grazing
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1 + 2.0 ** -40, -4, 4]))
    assert not r.collides and r.stepsize == 1.0  # (1 - 2 t)^2 + 2^-40 > 0
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1, 0, -2]))
    lo, hi = r.first_contact.lo, r.first_contact.hi  # 1 - 2 t^2 = 0 at 1/sqrt(2)
    assert r.first_contact.exact is None and lo * lo <= F(1, 2) <= hi * hi
    assert hi - lo < F(1, 10 ** 9)
    assert r.stepsize <= 2 ** -0.5 and F(r.stepsize) <= hi
    assert list(r.contacts.kind) == ["vertex-face"] and r.contacts.indices.tolist() == [[0, 0, 0, 0]]
    # within 3/4 of the face when 1 - 4 t^2 = 3/4, at t = 1/4; never within 1/4 of it
    # on z = 1 - t^2 / 8 >= 7/8
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1, 0, -4]),
                     min_distance="3/4")
    assert r.first_contact.exact == F(1, 4)
    r = P.check_step(None, None, faces, points=[0], paths=vertex_over_triangle([1, 0, -0.125]),
                     min_distance="1/4")
    assert not r.collides


def random_mesh(rng, n):
    """A strip of 2 (n - 1) triangles over 2 n vertices (a cloth ribbon), on cubic paths."""
    faces = []
    for i in range(n - 1):
        a, b, c, d = 2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3
        faces += [[a, b, c], [b, d, c]]
    coef = np.zeros((4, 2 * n, 3))
    for i in range(2 * n):
        coef[0, i] = (i // 2, i % 2, 0)
        for k in range(1, 4):
            coef[k, i] = [rng.randint(-6, 6) / 4 for _ in range(3)]
    return coef, np.array(faces)


def trajectory(coef, i):
    """Point i of coefficient array coef as Fraction trajectories, one list per axis."""
    return [[F(float(coef[k, i, a])) for k in range(coef.shape[0])] for a in range(3)]


def brute_force(coef, faces, obstacle=None):
    """Every pair solved alone: {(kind, mesh a, a, mesh b, b): Result} of touching pairs."""
    paths = {(0, i): trajectory(coef, i) for i in range(coef.shape[1])}
    meshes = [(0, faces)]
    if obstacle is not None:
        V0, V1, of = obstacle
        for i in range(len(V0)):
            paths[(1, i)] = [[F(float(V0[i, a])), F(float(V1[i, a])) - F(float(V0[i, a]))] for a in range(3)]
        meshes.append((1, of))
    edges = {m: sorted({tuple(sorted((f[k], f[(k + 1) % 3]))) for f in fs for k in range(3)}) for m, fs in meshes}
    out = {}

    def solve(kind, key, pts):
        r = P.solve(kind, [paths[p] for p in pts], time_tolerance="1e-9")
        if r.collides:
            out[key] = r

    for (ma, _), (mb, fb) in [(meshes[0], meshes[0])] + [(x, y) for x in meshes for y in meshes if x != y]:
        verts = {int(v) for f in meshes[ma][1] for v in f}
        for v in verts:
            for j, f in enumerate(fb):
                if ma == mb and v in f:
                    continue
                solve("vertex-face", ("vertex-face", ma, v, mb, j), [(ma, v)] + [(mb, int(x)) for x in f])
    pairs = [(m, i, e) for m, _ in meshes for i, e in enumerate(edges[m])]
    for (ma, i, ea), (mb, j, eb) in combinations(pairs, 2):
        if ma == mb and (ma == 1 or set(ea) & set(eb)):  # obstacles: against the mesh only
            continue
        solve("edge-edge", ("edge-edge", ma, i, mb, j), [(ma, ea[0]), (ma, ea[1]), (mb, eb[0]), (mb, eb[1])])
    return out, edges


def reported(r):
    """{(kind, mesh a, a, mesh b, b): (lo, hi)} of a check_step result; edge-edge pairs
    ordered as the brute force's (mesh, edge) order."""
    out = {}
    for kind, idx, lo, hi in zip(r.contacts.kind, r.contacts.indices.tolist(), r.contacts.lo, r.contacts.hi):
        ma, a, mb, b = idx
        if kind == "edge-edge" and (mb, b) < (ma, a):
            ma, a, mb, b = mb, b, ma, a
        out[(kind, ma, a, mb, b)] = (lo, hi)
    return out


@pytest.mark.parametrize("seed", range(6))
def test_random_cubic_paths_equal_brute_force(seed):
    rng = random.Random(seed)
    coef, faces = random_mesh(rng, 3)
    obstacle = None
    if seed % 2:  # a straight, moving obstacle triangle crossing the ribbon
        V0 = np.array([[0.5, -1, 1], [1.5, -1, 1], [1, 2, 1]], dtype=float)
        obstacle = (V0, V0 - [0, 0, 2.5], np.array([[0, 1, 2]]))
    want, edges = brute_force(coef, faces, obstacle)
    obs = [] if obstacle is None else [obstacle]
    r = P.check_step(None, None, faces, paths=coef, obstacles=obs, all_contacts=True, threads=2)
    got = reported(r)
    # the step numbers edges as the brute force does (sorted sides of the faces)
    assert [e.tolist() for e in r.edges] == [[list(e) for e in edges[m]] for m in sorted(edges)]
    assert set(got) == set(want), (set(got) ^ set(want))
    for key, res in want.items():
        lo, hi = got[key]
        assert F(lo) <= res.first_contact.hi and res.first_contact.lo <= F(hi), key
    assert r.collides == bool(want)
    if want:
        first_lo = min(x.first_contact.lo for x in want.values())
        first_hi = min(x.first_contact.hi for x in want.values())
        assert r.first_contact.lo <= first_hi and first_lo <= r.first_contact.hi
        assert P.collision_free_stepsize(None, None, faces, paths=coef, obstacles=obs) == r.stepsize
        assert F(r.stepsize) <= r.first_contact.hi
    decide = P.check_step(None, None, faces, paths=coef, obstacles=obs, first_contact=False)
    assert decide.collides == bool(want)


@pytest.mark.parametrize("seed", range(3))
def test_straight_paths_as_coefficients_answer_as_positions(seed):
    rng = random.Random(100 + seed)
    coef, faces = random_mesh(rng, 4)
    V0 = coef[0]
    V1 = V0 + np.array([[rng.randint(-8, 8) / 8 for _ in range(3)] for _ in V0])
    lin = np.stack([V0, V1 - V0])  # exact: small dyadics
    a = P.check_step(V0, V1, faces, all_contacts=True)
    b = P.check_step(None, None, faces, paths=lin, all_contacts=True)
    assert a.collides == b.collides and a.stepsize == b.stepsize
    assert reported(a).keys() == reported(b).keys()
    if a.collides:
        assert (a.first_contact.exact is None) == (b.first_contact.exact is None)
        assert a.first_contact.lo <= b.first_contact.hi and b.first_contact.lo <= a.first_contact.hi
    # and a straight step after a path step on the same (cached) handle is straight again
    assert P.check_step(V0, V1, faces, all_contacts=True).stepsize == a.stepsize


def test_bad_paths_name_their_place():
    faces = np.array([[1, 2, 3]])
    c = vertex_over_triangle([1, 0, -4])
    with pytest.raises(P.InputError, match="paths: give V0 and V1 as None"):
        P.check_step(c[0], c[0], faces, paths=c)
    with pytest.raises(P.InputError, match=r"coeffs: expected shape \(k, n, 3\)"):
        P.check_step(None, None, faces, paths=c[:, :, :2])
    bad = c.copy()
    bad[2, 3, 1] = np.nan
    with pytest.raises(P.InputError, match=r"coeffs\[2\]\[3\]\[1\]: .*NaN"):
        P.check_step(None, None, faces, paths=bad)
    with pytest.raises(P.InputError, match=r"ncoeffs: 9 is outside 1\.\.8"):
        P.check_step(None, None, faces, paths=np.zeros((9, 4, 3)))
    with pytest.raises(P.InputError, match=r"faces\[0\]\[2\]: index 3 out of range"):
        P.check_step(None, None, faces, paths=c[:, :3])
