"""polyccd.check_step against brute force over every primitive pair.

The oracle enumerates the pairs of the step's contract itself (every used vertex against
every face not holding it, every edge pair with no common vertex, points against edges
and points; the mesh against itself and each obstacle, obstacles not against each
other), solves every pair with polyccd.solve_linear_many (a batch: entry k is exactly
the single solve_linear call, polyccd.h) and then every touching pair again with single
solve_linear calls. The step must find exactly the touching pairs, their first time,
and the pairs touching first, for any broad phase outcome and thread count. A separate
check samples the step densely in time: no crossing of a vertex through a face before
the reported first time (floats with a safety margin, independent of polyccd).
"""
from fractions import Fraction

import numpy as np
import pytest

import polyccd

KIND_CODE = {"vertex-face": 0, "edge-edge": 1, "vertex-edge": 2, "vertex-vertex": 3}


def edges_of(faces):
    e = set()
    for f in faces:
        for k in range(3):
            a, b = int(f[k]), int(f[(k + 1) % 3])
            e.add((min(a, b), max(a, b)))
    return sorted(e)


def mesh_info(meshes):
    """(V0, V1, faces (m, 3), edges (k, 2), points, used vertices) of each mesh."""
    info = []
    for V0, V1, F, P in meshes:
        F = np.asarray(F, dtype=np.int64).reshape(-1, 3)
        E = np.array(edges_of(F), dtype=np.int64).reshape(-1, 2)
        P = np.array(sorted(set(int(x) for x in P)), dtype=np.int64)
        used = np.unique(np.concatenate([F.ravel(), E.ravel(), P]))
        info.append((np.asarray(V0, np.float64), np.asarray(V1, np.float64), F, E, P, used))
    return info


def product(n, m, same, chunk=400_000):
    """Index pairs (i, j) of range(n) x range(m) (with same: i < j only), in chunks."""
    rows = max(1, chunk // max(m, 1))
    for i0 in range(0, n, rows):
        i, j = np.meshgrid(np.arange(i0, min(n, i0 + rows)), np.arange(m), indexing="ij")
        i, j = i.ravel(), j.ravel()
        if same:
            i, j = i[i < j], j[i < j]
        yield i, j


def brute_pairs(meshes):
    """Chunks (kind, keys (n, 4): mesh_a, a, mesh_b, b, t0, t1 (n, npoints, 3)) of every
    pair of the contract, for meshes [(V0, V1, faces, points)], mesh 0 the step's mesh,
    the rest obstacles (checked against mesh 0 only)."""
    info = mesh_info(meshes)
    for ma, (A0, A1, FA, EA, PA, UA) in enumerate(info):
        for mb, (B0, B1, FB, EB, PB, UB) in enumerate(info):
            if ma != 0 and mb != 0:
                continue
            same = ma == mb
            # (kind, A's primitives as vertex rows, B's, keys of A, keys of B, i < j only)
            plan = [(0, UA[:, None], FB, UA, np.arange(len(FB)), False),
                    (2, PA[:, None], EB, PA, np.arange(len(EB)), False)]
            if ma <= mb:
                plan += [(1, EA, EB, np.arange(len(EA)), np.arange(len(EB)), same),
                         (3, PA[:, None], PB[:, None], PA, PB, same)]
            for kind, RA, RB, KA, KB, upper in plan:
                for i, j in product(len(RA), len(RB), upper):
                    va, vb = RA[i], RB[j]
                    if same:  # no common vertex within one mesh
                        keep = ~(va[:, :, None] == vb[:, None, :]).any(axis=(1, 2))
                        i, j, va, vb = i[keep], j[keep], va[keep], vb[keep]
                    if not len(i):
                        continue
                    keys = np.stack([np.full(len(i), ma), KA[i], np.full(len(i), mb), KB[j]], 1)
                    t0 = np.concatenate([A0[va], B0[vb]], axis=1)
                    t1 = np.concatenate([A1[va], B1[vb]], axis=1)
                    yield kind, keys, t0, t1


def brute_force(meshes, min_distance=0):
    """{(kind, indices): single-call Result} of every touching pair."""
    names = {v: k for k, v in KIND_CODE.items()}
    touching = {}
    for kind, keys, t0, t1 in brute_pairs(meshes):
        batch = polyccd.solve_linear_many(names[kind], t0, t1, want_time=False, threads=2,
                                          min_distance=min_distance or None)
        for k in np.flatnonzero(batch.collides):
            single = polyccd.solve_linear(names[kind], t0[k], t1[k], min_distance=min_distance or None)
            assert single.collides
            touching[(kind, tuple(int(x) for x in keys[k]))] = single
    return touching


def contact_keys(c):
    return {(KIND_CODE[k], tuple(int(x) for x in ix)) for k, ix in zip(c.kind, c.indices)}


def check_against_brute(meshes, min_distance=0, threads=(1, 2)):
    V0, V1, F, P = meshes[0]
    obstacles = [(m[0], m[1], m[2]) for m in meshes[1:]]
    truth = brute_force(meshes, min_distance)
    results = []
    for th in threads:
        full = polyccd.check_step(V0, V1, F, points=P, obstacles=obstacles, threads=th,
                                  min_distance=min_distance, all_contacts=True)
        first = polyccd.check_step(V0, V1, F, points=P, obstacles=obstacles, threads=th,
                                   min_distance=min_distance)
        decide = polyccd.check_step(V0, V1, F, points=P, obstacles=obstacles, threads=th,
                                    min_distance=min_distance, first_contact=False)
        assert full.collides == first.collides == decide.collides == bool(truth)
        assert contact_keys(full.contacts) == set(truth)
        assert contact_keys(decide.contacts) <= set(truth)
        for key, lo, hi in zip(sorted(contact_keys(full.contacts)), full.contacts.lo, full.contacts.hi):
            t = truth[key].first_contact
            assert lo <= t.hi and t.lo <= hi  # both enclose the same time
            if t.exact is not None:
                assert lo <= t.exact <= hi
        if truth:
            tc = first.first_contact
            lo_min = min(r.first_contact.lo for r in truth.values())
            hi_min = min(r.first_contact.hi for r in truth.values())
            assert tc.lo <= hi_min and lo_min <= tc.hi
            exact = [r.first_contact.exact for r in truth.values() if r.first_contact.exact is not None]
            if tc.exact is not None:
                assert tc.exact in exact and all(r.first_contact.hi >= tc.exact for r in truth.values())
                owners = {k for k, r in truth.items() if r.first_contact.exact == tc.exact}
                assert contact_keys(first.contacts) == owners
            assert first.stepsize <= tc.hi and Fraction(first.stepsize) <= (tc.exact or tc.hi)
            assert Fraction(np.nextafter(first.stepsize, 2.0)) > (tc.exact if tc.exact is not None else tc.lo)
            assert full.first_contact == tc
        else:
            assert first.stepsize == 1.0 and first.first_contact is None and len(first.contacts) == 0
        results.append((first.first_contact, first.stepsize, contact_keys(first.contacts),
                        contact_keys(full.contacts), full.stats["candidates"]))
    assert all(r == results[0] for r in results)  # the thread count changes nothing
    return truth, results[0]


def crossings_before(meshes, t_end, samples=64):
    """Vertex-face pairs of mesh 0 (and against obstacles) whose vertex crosses the
    face's plane strictly inside the face between two samples before t_end, in floats
    with margins (a certain contact there)."""
    V0, V1, F, _ = meshes[0]
    F = np.asarray(F)
    ts = np.linspace(0.0, float(t_end), samples)[:-1]
    found = []
    for fa, fb in zip(ts[:-1], ts[1:]):
        pa, pb = V0 + fa * (V1 - V0), V0 + fb * (V1 - V0)
        for P, Q in ((pa, pb),):
            n_a = np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]])
            n_b = np.cross(Q[F[:, 1]] - Q[F[:, 0]], Q[F[:, 2]] - Q[F[:, 0]])
            sa = np.einsum("fk,vfk->vf", n_a, P[:, None, :] - P[F[:, 0]][None])
            sb = np.einsum("fk,vfk->vf", n_b, Q[:, None, :] - Q[F[:, 0]][None])
            v, f = np.nonzero((sa * sb < 0) & (np.abs(sa) > 1e-9) & (np.abs(sb) > 1e-9))
            for vi, fi in zip(v, f):
                if vi in F[fi]:
                    continue
                s = sa[vi, fi] / (sa[vi, fi] - sb[vi, fi])  # the crossing's fraction
                t = fa + s * (fb - fa)
                X = V0 + t * (V1 - V0)
                a, b, c = X[F[fi]]
                # barycentric coordinates of the vertex's projection
                n = np.cross(b - a, c - a)
                nn = n @ n
                w = [np.cross(c - b, X[vi] - b) @ n / nn, np.cross(a - c, X[vi] - c) @ n / nn,
                     np.cross(b - a, X[vi] - a) @ n / nn]
                if min(w) > 1e-6:
                    found.append((vi, fi, t))
    return found


def grid(n, rng, scale=1.0):
    xs, ys = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
    V = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], 1) / n * scale
    V[:, 2] = rng.integers(-4, 5, len(V)) / 64.0
    F = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1
            F += [[a, b, c], [a, c, d]]
    return V, np.array(F)


def random_step(seed, n, fold=0.5):
    """A grid cloth whose two halves fold through each other (self contact), plus two
    particles and a static obstacle triangle under it."""
    rng = np.random.default_rng(seed)
    V0, F = grid(n, rng)
    V1 = V0.copy()
    half = V0[:, 0] > 0.5
    V1[half, 0] = 1.0 - V0[half, 0] + rng.integers(-2, 3, half.sum()) / 64.0
    V1[half, 2] += fold * rng.integers(1, 4) / 4
    V1[~half, 2] -= rng.integers(0, 3, (~half).sum()) / 32.0
    parts = np.array([[0.25, 0.5, 0.5], [0.75, 0.5, 0.5]])
    V0 = np.vstack([V0, parts])
    V1 = np.vstack([V1, parts + [[0.5, 0, -0.75], [-0.5, 0, -0.75]]])
    P = [len(V0) - 2, len(V0) - 1]
    ob = np.array([[-1.0, -1, -0.2], [3, -1, -0.2], [-1, 3, -0.2]])
    return [(V0, V1, F, P), (ob, ob, np.array([[0, 1, 2]]), [])]


@pytest.mark.parametrize("seed,n", [(1, 4), (2, 6), (3, 8)])
def test_random_folds_equal_brute_force(seed, n):
    meshes = random_step(seed, n)
    truth, (tc, stepsize, *_rest) = check_against_brute(meshes)
    assert truth  # the fold makes contacts
    assert crossings_before(meshes, tc.lo) == []


@pytest.mark.parametrize("seed", [4, 5])
def test_random_folds_with_min_distance(seed):
    meshes = random_step(seed, 5, fold=0.25)
    truth0, _ = check_against_brute(meshes)
    truth, _ = check_against_brute(meshes, min_distance="1/64")
    assert set(truth0) <= set(truth)  # touching is within any distance


def test_two_thousand_triangles_equal_brute_force():
    rng = np.random.default_rng(7)
    V0, F = grid(32, rng)  # 2,048 triangles
    V1 = V0 + rng.integers(-3, 4, V0.shape) / 256.0
    V1[:, 2] += np.where(V0[:, 0] > 0.5, rng.integers(0, 9, len(V0)) / 64.0, 0)
    meshes = [(V0, V1, F, [])]
    check_against_brute(meshes, threads=(1, 2))


def two_triangles(b0, b1):
    """Mesh 0: triangle A fixed in z = 0, triangle B (3 separate vertices) moving."""
    A = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    V0 = np.array(A + b0, dtype=np.float64)
    V1 = np.array(A + b1, dtype=np.float64)
    return [(V0, V1, np.array([[0, 1, 2], [3, 4, 5]]), [])]


CONSTRUCTED = {
    # B's vertex 3 on A's face at t = 0
    "touching-at-0": ([[0.25, 0.25, 0], [2, 2, 1], [2, 3, 1]], [[0.25, 0.25, 1], [2, 2, 2], [2, 3, 2]], 0),
    # B's vertex reaches A's face exactly at t = 1
    "touching-at-1": ([[0.25, 0.25, 1], [2, 2, 1], [2, 3, 1]], [[0.25, 0.25, 0], [2, 2, 1], [2, 3, 1]], 1),
    # B's vertex grazes A's vertex (1, 0, 0) in A's plane (touches at t = 1/2 only)
    "grazing": ([[2, 1, 0], [5, 5, 5], [5, 6, 5]], [[0, -1, 0], [5, 5, 5], [5, 6, 5]], Fraction(1, 2)),
    # coplanar: B slides in z = 0 into A, its vertex entering A's edge x = 0 at t = 1/4
    "coplanar": ([[-0.25, 0.25, 0], [-2, 0, 0], [-2, 1, 0]], [[0.75, 0.25, 0], [-1, 0, 0], [-1, 1, 0]], Fraction(1, 4)),
    # edge-edge crossing at t = 1/3: B's edge (4, 5) drops through A's edge (0, 1)
    "edge-edge": ([[5, 5, 5], [0.5, -1, 1], [0.5, 1, 1]], [[5, 5, 5], [0.5, -1, -2], [0.5, 1, -2]], Fraction(1, 3)),
    # no contact: B passes beside A
    "miss": ([[2, 2, 1], [3, 2, 1], [2, 3, 1]], [[2, 2, -1], [3, 2, -1], [2, 3, -1]], None),
}


@pytest.mark.parametrize("name", sorted(CONSTRUCTED))
def test_constructed_contacts(name):
    b0, b1, expected = CONSTRUCTED[name]
    meshes = two_triangles(b0, b1)
    truth, (tc, stepsize, first, *_rest) = check_against_brute(meshes)
    if expected is None:
        assert not truth and tc is None and stepsize == 1.0
    else:
        assert tc.exact == expected and stepsize == float(expected)


def test_shared_vertex_pairs_are_left_out():
    # Two faces sharing vertex 0 pass through each other (their common vertex stays):
    # only the pairs with no common vertex count.
    V0 = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 0.5, 1], [0.2, -0.3, 1]], dtype=np.float64)
    V1 = V0.copy()
    V1[3:, 2] = -1
    meshes = [(V0, V1, np.array([[0, 1, 2], [0, 3, 4]]), [])]
    truth, _ = check_against_brute(meshes)
    F = meshes[0][2]
    assert truth and all(k != 0 or ix[1] not in F[ix[3]] for k, ix in truth)


def test_positions_and_repeat_are_stable():
    meshes = random_step(9, 5)
    V0, V1, F, P = meshes[0]
    a = polyccd.check_step(V0, V1, F, points=P, all_contacts=True)
    b = polyccd.check_step(V0.tolist(), V1.tolist(), F.tolist(), points=P, all_contacts=True)
    assert a.first_contact == b.first_contact and contact_keys(a.contacts) == contact_keys(b.contacts)
    assert polyccd.collision_free_stepsize(V0, V1, F, points=P) == a.stepsize


TRI = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64)


@pytest.mark.parametrize("args,kwargs,message", [
    ((TRI[:, :2], TRI, [[0, 1, 2]]), {}, "v_t0: expected shape (n, 3), got (3, 2)"),
    ((TRI, TRI[:2], [[0, 1, 2]]), {}, "v_t1: expected shape (3, 3) like v_t0, got (2, 3)"),
    ((TRI, TRI, [[0, 1, 3]]), {}, "faces[0][2]: index 3 out of range (3 vertices)"),
    ((TRI, TRI, [[0, 1, -1]]), {}, "faces[0][2]: index -1 is not a valid 0-based index"),
    ((TRI, TRI, [[0, 1]]), {}, "faces[0]: expected 3 vertex indices, got 2"),
    ((TRI, TRI, [[0, 1, 1]]), {}, "faces[0]: repeats vertex 1 (a degenerate face)"),
    ((TRI, TRI, [[0, 1, 2]], [[0, 0]]), {}, "edges[0]: repeats vertex 0 (a degenerate edge)"),
    ((TRI, TRI, [[0, 1, 2]], [[0, 5]]), {}, "edges[0][1]: index 5 out of range (3 vertices)"),
    ((TRI, TRI, [[0, 1, 2]]), {"points": [7]}, "points[0]: index 7 out of range (3 vertices)"),
    ((TRI, TRI, [[0, 1, 2]]), {"points": [1, -2]}, "points[1]: index -2 is not a valid 0-based index"),
    ((TRI, np.where(TRI == 1, np.nan, TRI), [[0, 1, 2]]), {}, "v_t1[1][0]: NaN is not a finite number"),
    ((TRI, TRI, [[0, 1, 2]]), {"obstacles": [(TRI, [[0, 4, 1]])]},
     "obstacles[0].faces[0][1]: index 4 out of range (3 vertices)"),
    ((TRI, TRI, [[0, 1, 2]]), {"obstacles": [TRI]}, "obstacles[0]: expected (V, faces)"),
    ((TRI, TRI, [[0, 1, 2]]), {"threads": 0}, "opt.threads: 0 is outside 1..1024"),
    ((TRI, TRI, [[0, 1, 2]]), {"min_distance": -1}, "config.min_distance"),
])
def test_bad_input_names_the_place(args, kwargs, message):
    with pytest.raises(polyccd.InputError) as e:
        polyccd.check_step(*args, **kwargs)
    assert message in str(e.value)


def test_c_rejects_bad_mode_and_ranges():
    from polyccd._pccd import ffi, lib
    s = ffi.new("pccd_step **")
    assert lib.pccd_step_new(s) == 0
    step = ffi.gc(s[0], lib.pccd_step_free)
    assert lib.pccd_step_set_pair_check(step, 0, 0, 1) == lib.PCCD_EINVAL
    assert "i: 0 out of range (0 meshes)" in ffi.string(lib.pccd_last_error()).decode()
    opt = ffi.new("pccd_step_options *")
    lib.pccd_step_options_init(opt)
    opt.mode = 7
    r = ffi.new("pccd_step_report **")
    lib.pccd_step_report_new(r)
    rep = ffi.gc(r[0], lib.pccd_step_report_free)
    assert lib.pccd_step_solve(step, ffi.NULL, opt, rep) == lib.PCCD_EINVAL
    assert "opt.mode: 7" in ffi.string(lib.pccd_last_error()).decode()
    c = ffi.new("int *")
    assert lib.pccd_step_report_collides(rep, c) == lib.PCCD_ESTATE
    opt.mode = 0
    assert lib.pccd_step_solve(step, ffi.NULL, opt, rep) == 0  # an empty step is free
    assert lib.pccd_step_report_collides(rep, c) == 0 and c[0] == 0
    assert lib.pccd_step_set_positions_d(step, 0, ffi.NULL, ffi.NULL, 0) == lib.PCCD_EINVAL
    assert "mesh: 0 out of range (0 meshes)" in ffi.string(lib.pccd_last_error()).decode()


def test_work_limit_ends_the_step():
    meshes = random_step(2, 6)
    V0, V1, F, P = meshes[0]
    with pytest.raises(polyccd.LimitError):
        polyccd.check_step(V0, V1, F, points=P, limits=polyccd.Limits(max_work=3))


@pytest.mark.parametrize("gap,touches", [(0.0, True), (2.0 ** -50, False)])
def test_coplanar_min_distance_boundary(gap, touches):
    # B's vertex exactly 1/4 (or just more) from A's edge x = 0, all in z = 0, static:
    # the separating-direction filter must leave the exact boundary to the solver.
    b = [[-0.25 - gap, 0.5, 0], [-2, 0, 0], [-2, 1, 0]]
    meshes = two_triangles(b, b)
    truth, (tc, *_rest) = check_against_brute(meshes, min_distance="1/4")
    assert bool(truth) == touches
    assert (tc is not None and tc.exact == 0) == touches
