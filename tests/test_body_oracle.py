"""Self-checks of the body oracle (tests/oracle/oracle_body.py), which are not allowed to
pass by accident: hand-derived answers (derivations in the comments), invariances that
change every polynomial the oracle sees but not the answer, 1e-30 perturbations on both
sides of a contact, a pointwise cross-check with a second, world-frame formulation at
rational times, and the corpus files on disk equal to what
tests/tools/make_body_corpus.py writes.
No polyccd here: the oracle is checked on its own.
"""
import itertools
import json
import math
from decimal import Decimal
from fractions import Fraction as F
from pathlib import Path

import pytest

import make_body_corpus as MK
import oracle_body as OB
from oracle_hull import in_hull

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "bodies"
E30 = F(1, 10 ** 30)


def T(x):
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else "%d/%d" % (x.numerator, x.denominator)


def scene(*bodies):
    return {"format": "polyccd/1", "bodies": list(bodies)}


def mbody(name, vertices, triangles, translation=None, rotation=None):
    b = {"name": name, "mesh": {"vertices": [[T(c) for c in v] for v in vertices],
                                "triangles": triangles}}
    return _moving(b, translation, rotation)


def sbody(name, centers, radii, translation=None, rotation=None):
    b = {"name": name, "spheres": {"centers": [[T(c) for c in v] for v in centers],
                                   "radii": [T(r) for r in radii]}}
    return _moving(b, translation, rotation)


def _moving(b, translation, rotation):
    mo = {}
    if translation is not None:
        mo["translation"] = [[T(c) for c in comp] for comp in translation]
    if rotation is not None:
        mo["rotation"] = [[T(c) for c in comp] for comp in rotation]
    if mo:
        b["motion"] = mo
    return b


def cube_v(lo=(0, 0, 0), s=1):
    return [[F(lo[0]) + s * (i & 1), F(lo[1]) + s * ((i >> 1) & 1), F(lo[2]) + s * (i >> 2)]
            for i in range(8)]


CUBE_T = MK.CUBE_TRIS
PIN = [[0, 0, -1], [F(-1, 4), F(-1, 4), 0], [F(1, 4), F(-1, 4), 0], [F(-1, 4), F(1, 4), 0]]
TET_T = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]
BIG = [[-3, -3, 0], [3, -3, 0], [0, 3, 0]]


def first(doc):
    return OB.solve_scene(doc).first


# ---------------------------------------------------------------- hand-derived answers

def test_cube_translating_onto_cube_at_one_half():
    # B = [3, 4] x [0, 1] x [0, 1] moving by (-4t, 0, 0): its face x = 3 - 4t reaches A's
    # face x = 1 at t = 1/2; the faces overlap in the unit square there.
    r = OB.solve_scene(scene(mbody("A", cube_v(), CUBE_T),
                             mbody("B", cube_v((3, 0, 0)), CUBE_T, translation=[[0, -4], [0], [0]])))
    assert r.collides and r.first == F(1, 2)
    # ... and with the speed lowered to 2 - 1/10^30 it stops 1e-30 short at t = 1
    r = OB.solve_scene(scene(mbody("A", cube_v(), CUBE_T),
                             mbody("B", cube_v((3, 0, 0)), CUBE_T,
                                   translation=[[0, -2 + E30], [0], [0]])))
    assert not r.collides and r.first is None


def test_rotation_with_irrational_contact_time():
    # The apex (0, 0, -1) of B, turned about the x axis by th with tan(th/2) = tau = t - 1
    # and lifted by 1/2, is at (0, sin th, 1/2 - cos th). It reaches the plane z = 0 when
    # cos th = (1 - tau^2) / (1 + tau^2) = 1/2, i.e. tau^2 = 1/3, tau = -1/sqrt(3) (tau runs
    # from -1 to 0): t* = 1 - sqrt(3)/3 = 0.42264973..., a root of 3t^2 - 6t + 2. There
    # y = sin th = -sqrt(3)/2, inside the big triangle; B's other points stay within 0.36
    # of (0, 0, 1/2), i.e. above the plane.
    doc = scene(mbody("A", BIG, [[0, 1, 2]]),
                mbody("B", PIN, TET_T, translation=[[0], [0], [F(1, 2)]],
                      rotation=[[1], [-1, 1], [0], [0]]))
    r = OB.solve_scene(doc)
    t = r.first
    assert r.collides and not isinstance(t, F)
    assert [int(c) for c in t.f.coeffs()] in ([2, -6, 3], [-2, 6, -3])
    lo, hi = t.enclosure(F(1, 10 ** 40))
    exact = 1 - math.sqrt(3) / 3
    assert float(lo) <= exact + 1e-15 and float(hi) >= exact - 1e-15
    # 3 lo^2 - 6 lo + 2 > 0 > 3 hi^2 - 6 hi + 2 (the root is simple, the polynomial falls)
    assert 3 * lo * lo - 6 * lo + 2 > 0 > 3 * hi * hi - 6 * hi + 2
    assert r.pair_list[0].touching == [(("triangle", 0), ("vertex", 0))]


def test_rotating_dumbbell_irrational():
    # atoms (+-2, 0, 0) (radius 1/2) turning about z, tau = t: atom 0 at (2 cos th, 2 sin th);
    # the ball (0, 5/2, 0) (radius 1/2) is touched when 4 + 25/4 - 10 sin th = 1, i.e.
    # sin th = 2t / (1 + t^2) = 37/40: 37 t^2 - 80 t + 37 = 0, t* = (40 - sqrt(231)) / 37.
    doc = scene(sbody("A", [[2, 0, 0], [-2, 0, 0]], [F(1, 2), F(1, 2)],
                      rotation=[[1], [0], [0], [0, 1]]),
                sbody("B", [[0, F(5, 2), 0]], [F(1, 2)]))
    t = first(doc)
    assert [int(c) for c in t.f.coeffs()] == [37, -80, 37]
    assert abs(t.approx() - (40 - math.sqrt(231)) / 37) < 1e-15


def test_grazing_double_root_and_both_sides():
    # apex height over the plane: h(t) = 1 + c - cos th with tau = t - 1/2 about x:
    # 1 - cos th = 2 tau^2 / (1 + tau^2) >= 0. c = 0: touches only at t = 1/2 (double
    # root); c = 1e-30: never; c = -1e-30: two simple roots around 1/2, the first < 1/2.
    def doc(c):
        return scene(mbody("A", BIG, [[0, 1, 2]]),
                     mbody("B", PIN, TET_T, translation=[[0], [0], [1 + c]],
                           rotation=[[1], [F(-1, 2), 1], [0], [0]]))
    assert first(doc(0)) == F(1, 2)
    assert first(doc(E30)) is None
    t = first(doc(-E30))
    # 2 tau^2 / (1 + tau^2) = 1e-30  ->  tau^2 = 1e-30 / (2 - 1e-30): irrational
    assert not isinstance(t, F)
    assert t.cmp_rational(F(1, 2)) < 0 and t.cmp_rational(F(1, 2) - F(1, 10 ** 15)) > 0
    # tau = -1/sqrt(2e30 - 1) = -7.0710678...e-16
    assert t.cmp_rational(F(1, 2) - F(70, 10 ** 17)) < 0 and t.cmp_rational(F(1, 2) - F(71, 10 ** 17)) > 0


def test_translation_perturbation_1e30():
    # apex (1/3, 1/4) at height 1 + d - t over the plate z = 0 ... the plate is at z = 0 and
    # the apex at body z = 0: contact iff d <= 0, then at t = 1 + d (d = 0: exactly t = 1).
    def doc(d):
        return scene(mbody("A", [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], [[0, 1, 2], [1, 3, 2]]),
                     mbody("B", [[F(1, 3), F(1, 4), 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]], TET_T,
                           translation=[[0], [0], [1 + d, -1]]))
    assert first(doc(E30)) is None
    assert first(doc(0)) == 1
    assert first(doc(-E30)) == 1 - E30
    assert first(doc(-F(1, 3))) == F(2, 3)


def test_transversal_crossing_at_t0_found_only_by_static_test():
    # A in y = 0, B in x = 0, crossing on the segment x = y = 0, -1 <= z <= 1 at t = 0,
    # with no vertex of either in the other and no edges meeting: only the static
    # triangle-triangle test sees it. B then slides along +x by 3t; while it still cuts A
    # the contact persists, so the first contact is 0.
    A = mbody("A", [[-2, 0, -1], [2, 0, -1], [0, 0, 2]], [[0, 1, 2]])
    B = mbody("B", [[0, -2, 1], [0, 2, 1], [0, 0, -2]], [[0, 1, 2]], translation=[[0, 3], [0], [0]])
    r = OB.solve_scene(scene(A, B))
    assert r.first == 0
    assert r.pair_list[0].touching == [(("triangle", 0), ("triangle", 0))]
    # no vertex-triangle or edge-edge contact at t = 0: a method without the static test
    # would report a later time, so check that the feature pairs alone start later
    bodies = OB.parse_scene(scene(A, B))
    G = OB.Pair(bodies[0], bodies[1])
    ev = OB.Ev(F(0), record=False)
    for k in range(3):
        assert not G.point_in_triangle(ev, ("A", k), ("B", 0), ("B", 1), ("B", 2))
        assert not G.point_in_triangle(ev, ("B", k), ("A", 0), ("A", 1), ("A", 2))
    for (a0, a1), (b0, b1) in itertools.product(bodies[0].edges, bodies[1].edges):
        assert not G.segments_meet(ev, ("A", a0), ("A", a1), ("B", b0), ("B", b1))


def test_unused_vertex_is_not_surface():
    # vertex 4 of B is in no triangle: it passes through the plate at t = 1/3, which is
    # no contact; the apex touches at t = 2/3 (apex height 1 - 3t/2).
    plate = mbody("A", [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], [[0, 1, 2], [1, 3, 2]])
    B = mbody("B", [[F(1, 3), F(1, 4), 1], [0, 0, 2], [1, 0, 2], [0, 1, 2], [F(1, 2), F(1, 2), F(1, 2)]],
              TET_T, translation=[[0], [0], [0, F(-3, 2)]])
    assert first(scene(plate, B)) == F(2, 3)
    # the same vertex used by a point triangle [4, 4, 4] is surface: contact at t = 1/3
    B["mesh"]["triangles"] = TET_T + [[4, 4, 4]]
    assert first(scene(plate, B)) == F(1, 3)


def test_degenerate_triangles():
    # segment triangles [0, 1, 1] (x axis) and [0, 0, 1] (along y, height 1 - 2t): t = 1/2
    A = mbody("A", [[-1, 0, 0], [1, 0, 0]], [[0, 1, 1]])
    B = mbody("B", [[0, -1, 1], [0, 1, 1]], [[0, 0, 1]], translation=[[0], [0], [0, -2]])
    assert first(scene(A, B)) == F(1, 2)
    # shifted sideways by 1 + 1e-30 in x the segment B misses A's end (1, 0, 0)
    B2 = mbody("B", [[1 + E30, -1, 1], [1 + E30, 1, 1]], [[0, 0, 1]], translation=[[0], [0], [0, -2]])
    assert first(scene(A, B2)) is None
    B3 = mbody("B", [[1, -1, 1], [1, 1, 1]], [[0, 0, 1]], translation=[[0], [0], [0, -2]])
    assert first(scene(A, B3)) == F(1, 2)
    # a ball onto a collinear triangle (three points on the x axis): centre (5/2, 0, 3 - 4t),
    # radius 1: the triangle is the segment [0, 2], nearest point (2, 0, 0): distance
    # sqrt(1/4 + z^2) = 1 at z = sqrt(3)/2, t = (3 - sqrt(3)/2) / 4, root of 64t^2 - 96t + 33.
    A = mbody("A", [[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]])
    S = sbody("S", [[F(5, 2), 0, 0]], [1], translation=[[0], [0], [3, -4]])
    t = first(scene(A, S))
    assert [int(c) for c in t.f.coeffs()] == [33, -96, 64]
    assert abs(t.approx() - (3 - math.sqrt(3) / 2) / 4) < 1e-15


def test_ball_cutting_face_at_t0_and_ball_edge():
    # ball (0, 0, 1/2 + 2t), radius 1, over a big triangle's interior: contact at 0 with no
    # vertex inside the ball
    A = mbody("A", [[-4, -4, 0], [4, -4, 0], [0, 4, 0]], [[0, 1, 2]])
    assert first(scene(A, sbody("S", [[0, 0, F(1, 2)]], [1], translation=[[0], [0], [0, 2]]))) == 0
    # ball centre (0, -3 + 3t, 3 - 3t) towards the edge y = 0 of a triangle in y >= 0:
    # distance sqrt(2) (3 - 3t) = 1 at t = 1 - sqrt(2)/6, root of 18t^2 - 36t + 17
    A = mbody("A", [[-2, 0, 0], [2, 0, 0], [0, 2, 0]], [[0, 1, 2]])
    t = first(scene(A, sbody("S", [[0, 0, 0]], [1], translation=[[0, 0], [-3, 3], [3, -3]])))
    assert [int(c) for c in t.f.coeffs()] == [17, -36, 18]
    assert abs(t.approx() - (1 - math.sqrt(2) / 6)) < 1e-15


# ---------------------------------------------------------------- invariances

CASES = {c["category"] + "/" + c["name"]: c for c in MK.CASES}
SOME = ["mesh-mesh/vertex-face-irrational-rotation", "mesh-mesh/edge-edge-grazing-rotation",
        "mesh-mesh/coplanar-square-turning-in-plane", "spheres-spheres/rotating-dumbbell-irrational",
        "spheres-mesh/ball-hits-edge-irrational", "motions/screw-tip-hits-wall-irrational",
        "mesh-mesh/octahedron-tumbling-into-cube", "motions/general-quaternion-quartic-translation"]


def _doc(name):
    c = CASES[name]
    return json.loads(MK.render(MK.scene_doc(c)), parse_float=Decimal)


def _times_equal(a, b):
    if isinstance(a, F) or isinstance(b, F) or a is None or b is None:
        return a == b
    return a.f == b.f and OB.cmp_points(a, b) == 0


@pytest.mark.parametrize("name", SOME)
def test_quaternion_scaled_by_positive_polynomial(name):
    # r(t) and (1 + t + t^2) r(t) are the same rotation; every rational function the
    # oracle builds changes, the answer must not.
    doc = _doc(name)
    want = OB.solve_scene(doc).first
    for b in doc["bodies"]:
        mo = b.setdefault("motion", {})
        rot = mo.get("rotation", [[1], [0], [0], [0]])
        mo["rotation"] = [[T(c) for c in MK.pmul([OB.parse_number(x) for x in comp], [1, 1, 1])]
                          for comp in rot]
    assert _times_equal(OB.solve_scene(doc).first, want)


@pytest.mark.parametrize("name", SOME)
def test_body_order_swapped(name):
    # the oracle works in the frame of the first body of a pair: swapping the bodies
    # changes the frame (and every polynomial), not the answer
    doc = _doc(name)
    want = OB.solve_scene(doc).first
    doc["bodies"] = doc["bodies"][::-1]
    assert _times_equal(OB.solve_scene(doc).first, want)


@pytest.mark.parametrize("name", SOME[:4])
def test_common_rigid_motion_of_the_world(name):
    # turning the whole world by the exact rotation q = (2, 1, 0, 1) (|q|^2 = 6) and
    # shifting it by (1/3, -2, 5): world positions R_q x + s. For each body the new motion
    # is rotation q * r(t) (quaternion product) and translation R_q o(t) + s.
    doc = _doc(name)
    want = OB.solve_scene(doc).first
    q = [F(2), F(1), F(0), F(1)]
    cols = [_qrot(q, e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
    R = [[cols[j][i] for j in range(3)] for i in range(3)]
    s = [F(1, 3), F(-2), F(5)]
    for b in doc["bodies"]:
        mo = b.setdefault("motion", {})
        rot = [[OB.parse_number(x) for x in comp] for comp in mo.get("rotation", [[1], [0], [0], [0]])]
        tr = [[OB.parse_number(x) for x in comp] for comp in mo.get("translation", [[0], [0], [0]])]
        w, x, y, z = rot
        a0, a1, a2, a3 = q
        # Hamilton product q * r
        new_rot = [MK.padd(MK.padd([a0 * c for c in w], [-a1 * c for c in x]),
                           MK.padd([-a2 * c for c in y], [-a3 * c for c in z])),
                   MK.padd(MK.padd([a0 * c for c in x], [a1 * c for c in w]),
                           MK.padd([a2 * c for c in z], [-a3 * c for c in y])),
                   MK.padd(MK.padd([a0 * c for c in y], [-a1 * c for c in z]),
                           MK.padd([a2 * c for c in w], [a3 * c for c in x])),
                   MK.padd(MK.padd([a0 * c for c in z], [a1 * c for c in y]),
                           MK.padd([-a2 * c for c in x], [a3 * c for c in w]))]
        n = max(len(c) for c in tr)
        tr = [c + [F(0)] * (n - len(c)) for c in tr]
        new_tr = [[sum(R[i][j] * tr[j][k] for j in range(3)) + (s[i] if k == 0 else 0)
                   for k in range(n)] for i in range(3)]
        mo["rotation"] = [[T(c) for c in comp] for comp in new_rot]
        mo["translation"] = [[T(c) for c in comp] for comp in new_tr]
    assert _times_equal(OB.solve_scene(doc).first, want)


# ---------------------------------------------------------------- a second formulation

def _qrot(q, p):
    """q p q^-1 for the quaternion q (not normalised) and the vector p, exactly."""
    w, x, y, z = q
    n = w * w + x * x + y * y + z * z
    # t = q * (0, p)
    tw = -(x * p[0] + y * p[1] + z * p[2])
    tx = w * p[0] + y * p[2] - z * p[1]
    ty = w * p[1] + z * p[0] - x * p[2]
    tz = w * p[2] + x * p[1] - y * p[0]
    # t * conj(q)
    return ((-tw * x + tx * w - ty * z + tz * y) / n,
            (-tw * y + ty * w - tz * x + tx * z) / n,
            (-tw * z + tz * w - tx * y + ty * x) / n)


def _at(coeffs, t):
    v = F(0)
    for c in reversed(coeffs):
        v = v * t + OB.parse_number(c)
    return v


def world(b, p, t):
    mo = b.get("motion", {})
    q = [_at(c, t) for c in mo.get("rotation", [[1], [0], [0], [0]])]
    o = [_at(c, t) for c in mo.get("translation", [[0], [0], [0]])]
    r = _qrot(q, [OB.parse_number(c) for c in p])
    return tuple(r[i] + o[i] for i in range(3))


def _dist2_to_hull(p, pts):
    """Exact squared distance from p to conv(pts) (<= 3 points): the nearest point is the
    projection of p onto the affine hull of some affinely independent subset, with
    non-negative barycentric coordinates."""
    best = None
    pts = list(dict.fromkeys(pts))
    for k in range(1, len(pts) + 1):
        for S in itertools.combinations(pts, k):
            p0 = S[0]
            D = [[a - b for a, b in zip(s, p0)] for s in S[1:]]
            y = [a - b for a, b in zip(p, p0)]
            G = [[sum(a * b for a, b in zip(u, v)) for v in D] for u in D]
            rhs = [sum(a * b for a, b in zip(u, y)) for u in D]
            if len(D) == 0:
                mu = []
            elif len(D) == 1:
                if G[0][0] == 0:
                    continue
                mu = [rhs[0] / G[0][0]]
            else:
                det = G[0][0] * G[1][1] - G[0][1] * G[1][0]
                if det == 0:
                    continue
                mu = [(rhs[0] * G[1][1] - rhs[1] * G[0][1]) / det,
                      (G[0][0] * rhs[1] - G[1][0] * rhs[0]) / det]
            if any(m < 0 for m in mu) or sum(mu) > 1:
                continue
            proj = [p0[i] + sum(m * d[i] for m, d in zip(mu, D)) for i in range(3)]
            d2 = sum((a - b) ** 2 for a, b in zip(p, proj))
            best = d2 if best is None else min(best, d2)
    return best


def contact_at(doc, t, i, j):
    """Pointwise contact of bodies i and j at the rational time t, in the world frame."""
    A, B = doc["bodies"][i], doc["bodies"][j]

    def tris(b):
        m = b["mesh"]
        P = [world(b, v, t) for v in m["vertices"]]
        return [[P[int(k)] for k in tri] for tri in m["triangles"]]

    def atoms(b):
        s = b["spheres"]
        return [(world(b, c, t), OB.parse_number(r)) for c, r in zip(s["centers"], s["radii"])]

    def apart(pa, pb, grow=0):
        # exact box test: the point sets' boxes (pa's grown by `grow`) are disjoint
        return any(min(p[i] for p in pa) - grow > max(p[i] for p in pb)
                   or max(p[i] for p in pa) + grow < min(p[i] for p in pb) for i in range(3))

    if "mesh" in A and "mesh" in B:
        return any(not apart(ta, tb) and
                   in_hull([tuple(a - b for a, b in zip(u, v)) for u in ta for v in tb], (0, 0, 0))
                   for ta in tris(A) for tb in tris(B))
    if "spheres" in A and "spheres" in B:
        return any(sum((x - y) ** 2 for x, y in zip(ca, cb)) <= (ra + rb) ** 2
                   for ca, ra in atoms(A) for cb, rb in atoms(B))
    S, M = (A, B) if "spheres" in A else (B, A)
    return any(not apart([c], tri, r) and _dist2_to_hull(c, tri) <= r * r
               for c, r in atoms(S) for tri in tris(M))


def _samples(t_star):
    """Rational times strictly before t* (or in [0, 1] when there is no contact)."""
    if t_star is None:
        return [F(k, 4) for k in range(5)]
    if isinstance(t_star, F):
        hi = t_star
    else:   # a short rational just below t*
        lo, _ = t_star.enclosure(F(1, 10 ** 6), denominator=10 ** 7)
        hi = lo
    return [hi * F(k, 3) for k in range(3)] + [hi - F(1, 10 ** 6)] if hi > F(1, 10 ** 6) else [F(0)] * (hi > 0)


FILES = sorted(CORPUS.rglob("*.json"))


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(CORPUS)) for p in FILES])
def test_pointwise_second_method(path):
    """On each pair: no contact at rational times before the oracle's t* (world frame,
    quaternion sandwich product, Minkowski hull / exact nearest-point distance), and
    contact AT a rational t*."""
    with open(path) as fh:
        doc = json.load(fh, parse_float=Decimal)
    res = OB.solve_scene(doc)
    for p in res.pair_list:
        for t in _samples(p.first):
            assert not contact_at(doc, t, p.i, p.j), (p, t)
        if isinstance(p.first, F):
            assert contact_at(doc, p.first, p.i, p.j), p


# ---------------------------------------------------------------- the corpus

_FILES = []


def generated():
    if not _FILES:
        _FILES.append(MK.all_files())
    return _FILES[0]


def test_corpus_files_are_what_the_generator_writes():
    files = generated()
    on_disk = {str(p.relative_to(CORPUS)): p.read_text() for p in CORPUS.rglob("*.json")}
    assert set(on_disk) == set(files), set(on_disk) ^ set(files)
    stale = [rel for rel, text in files.items() if on_disk[rel] != text]
    assert not stale, "run `python tests/tools/make_body_corpus.py`: %s" % stale


def test_corpus_covers_the_categories():
    cats = {}
    for rel in generated():
        cats[rel.split("/")[0]] = cats.get(rel.split("/")[0], 0) + 1
    assert sum(cats.values()) >= 45 and set(cats) == {
        "mesh-mesh", "spheres-spheres", "spheres-mesh", "multi-body", "motions"}, cats
