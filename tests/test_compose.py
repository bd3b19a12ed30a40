"""Composition of polynomial rigid motions (pccd_motion_compose, Motion.compose(inner),
Motion.then(outer)) against an independent oracle, and scenes on composed motions.

The oracle never calls polyccd: each motion is kept as its recipe (translation and
rotation coefficient lists, then constant poses composed on the body or world side),
its pose at a rational time t is an exact 3x4 matrix [R | o] of Fractions built from the
quaternion r(t) with the textbook matrix of a unit quaternion (divided by |r|^2) and the
translation o(t), and compositions are products of those matrices. polyccd's positions
(pccd_motion_position_s) must equal the oracle's exactly at >= 1000 sampled times.
"""
import os
import pickle
import random
from fractions import Fraction as F

import pytest

import polyccd as P
from helpers import cube, summary
from polyccd import InputError, Motion

SEED = int(os.environ.get("POLYCCD_COMPOSE_SEED", "20261124"))


# ---------------------------------------------------------------- the oracle

def peval(coeffs, t):
    return sum((F(c) * t ** k for k, c in enumerate(coeffs)), F(0))


def quat_matrix(q):
    """The rotation of the nonzero quaternion q = (w, x, y, z): the unit-quaternion matrix
    of q / |q| (every entry is quadratic in q, so it is q's entries over |q|^2)."""
    w, x, y, z = q
    n = w * w + x * x + y * y + z * z
    assert n != 0
    return [[(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n],
            [2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n],
            [2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n]]


def mul(A, B):
    """(R_A, o_A) after (R_B, o_B): x -> R_A (R_B x + o_B) + o_A."""
    RA, oa = A
    RB, ob = B
    R = [[sum(RA[i][k] * RB[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    o = [sum(RA[i][k] * ob[k] for k in range(3)) + oa[i] for i in range(3)]
    return R, o


def apply(A, p):
    R, o = A
    return tuple(sum(R[i][k] * F(p[k]) for k in range(3)) + o[i] for i in range(3))


class Recipe:
    """A motion as the oracle sees it: base (translation, rotation), then poses."""

    def __init__(self, translation, rotation, poses=()):
        self.translation, self.rotation, self.poses = translation, rotation, list(poses)

    def pose(self, t):
        r = [peval(c, t) for c in self.rotation]
        M = (quat_matrix(r), [peval(c, t) for c in self.translation])
        for side, q, off in self.poses:
            Q = (quat_matrix([F(c) for c in q]), [F(c) for c in off])
            M = mul(M, Q) if side == "body" else mul(Q, M)
        return M

    def motion(self):
        m = Motion(translation=self.translation, rotation=self.rotation)
        for side, q, off in self.poses:
            m = m.compose(q, off, side=side)
        return m


class Composite:
    def __init__(self, outer, inner):
        self.outer, self.inner = outer, inner

    def pose(self, t):
        return mul(self.outer.pose(t), self.inner.pose(t))


def rnd(rng, k=6, den=4):
    return F(rng.randint(-k, k), rng.randint(1, den))


def random_recipe(rng):
    """Degrees 0..3 for the translation and the rotation (a rotation that vanishes
    somewhere on [0, 1] is drawn again), then 0..2 constant poses on random sides."""
    while True:
        translation = [[rnd(rng) for _ in range(rng.randint(0, 4))] for _ in range(3)]
        deg = rng.randint(0, 3)
        rotation = [[rnd(rng) for _ in range(deg + 1)] for _ in range(4)]
        try:
            Motion(rotation=rotation).validate()
        except InputError:
            continue
        break
    poses = []
    for _ in range(rng.randint(0, 2)):
        q = [rnd(rng) for _ in range(4)]
        if not any(q):
            q = [1, 0, 0, 0]
        poses.append((rng.choice(["body", "world"]), q, [rnd(rng) for _ in range(3)]))
    return Recipe(translation, rotation, poses)


def sample_times(rng, n):
    return [F(0), F(1)] + [F(rng.randint(0, 997), 997) if rng.random() < 0.5
                           else F(rng.randint(0, 10 ** 6), 10 ** 6) for _ in range(n - 2)]


# ---------------------------------------------------------------- the oracle test

def test_composition_matches_the_oracle_at_1000_times():
    rng = random.Random(SEED)
    checked = 0
    for case in range(25):
        a, b = random_recipe(rng), random_recipe(rng)
        ma, mb = a.motion(), b.motion()
        composites = [(ma.compose(mb), Composite(a, b)), (mb.then(ma), Composite(a, b)),
                      (mb.compose(ma), Composite(b, a))]
        if case % 5 == 0:  # three factors, associativity included
            c = random_recipe(rng)
            mc = c.motion()
            composites.append((ma.compose(mb).compose(mc), Composite(Composite(a, b), c)))
            composites.append((ma.compose(mb.compose(mc)), Composite(a, Composite(b, c))))
        for t in sample_times(rng, 16):
            p = [rnd(rng) for _ in range(3)]
            for m, oracle in composites:
                got = m.position(p, t)
                want = apply(oracle.pose(t), p)
                assert got == want, (SEED, case, vars(a), vars(b), p, t, got, want)
                checked += 1
    assert checked >= 1000, checked


def test_composite_pickles_and_validates():
    rng = random.Random(SEED + 1)
    a, b = random_recipe(rng), random_recipe(rng)
    m = a.motion().compose(b.motion())
    back = pickle.loads(pickle.dumps(m))
    for t in sample_times(rng, 5):
        assert back.position([1, 2, 3], t) == m.position([1, 2, 3], t)
    assert m.validate() is m


def test_factor_errors_name_the_factor():
    bad = Motion(rotation=[["-1/2", 1], [0], [0], [0]])  # r(t) = t - 1/2
    good = Motion.linear([0, 0, 0], [1, 0, 0])
    with pytest.raises(InputError, match=r"^outer: the rotation quaternion .* t = 1/2"):
        bad.compose(good)
    with pytest.raises(InputError, match=r"^inner: the rotation quaternion .* t = 1/2"):
        good.compose(bad)
    with pytest.raises(InputError, match=r"^outer: the rotation quaternion"):
        good.then(bad)
    with pytest.raises(InputError, match=r"^outer: expected a Motion"):
        good.then([1, 0, 0, 0])
    with pytest.raises(InputError, match=r"^offset, side:"):
        good.compose(good, [0, 0, 0])
    big = Motion(rotation=[[1] + [0] * 39 + [1], [0], [0], [0]])  # 1 + t^40 > 0
    with pytest.raises(P.LimitError, match=r"^outer, inner: .* degree 80"):
        big.compose(big)


def test_rotation_of_a_turning_composite_cannot_be_set():
    # set_rotation is C-level (Motion never changes); reach it through the handle.
    from polyccd._errors import check
    from polyccd._pccd import ffi, lib
    turning = Motion.axis_rotation([0, 0, 1], [0, 0, 0], 0, 1)
    m = turning.compose(Motion.linear([0, 0, 0], [1, 0, 0]))
    one = ffi.new("double[]", [1.0])
    with pytest.raises(P.InternalError, match="composed"):
        check(lib.pccd_motion_set_rotation_d(m._handle, 0, one, 1))


# ---------------------------------------------------------------- scenes

def qmul(a, b):
    """Quaternion polynomials (coefficient lists) multiplied: the hand-written product."""
    def pm(x, y):
        out = [F(0)] * (len(x) + len(y) - 1)
        for i, u in enumerate(x):
            for j, v in enumerate(y):
                out[i + j] += F(u) * F(v)
        return out

    def padd(*ps):
        out = [F(0)] * max(len(p) for p in ps)
        for p in ps:
            for i, c in enumerate(p):
                out[i] += c
        return out

    def neg(p):
        return [-c for c in p]
    (aw, ax, ay, az), (bw, bx, by, bz) = a, b
    return [padd(pm(aw, bw), neg(pm(ax, bx)), neg(pm(ay, by)), neg(pm(az, bz))),
            padd(pm(aw, bx), pm(ax, bw), pm(ay, bz), neg(pm(az, by))),
            padd(pm(aw, by), pm(ay, bw), pm(az, bx), neg(pm(ax, bz))),
            padd(pm(aw, bz), pm(az, bw), pm(ax, by), neg(pm(ay, bx)))]


def hand_written_cases(rng):
    """(composed motion, the same motion written out by hand) pairs."""
    axis = [rng.randint(-1, 1) for _ in range(3)]
    if axis == [0, 0, 0]:
        axis = [0, 0, 1]
    center = [F(rng.randint(-2, 2), 2) for _ in range(3)]
    tau0, tau1, adv = F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2)
    # A translation along the axis after a fixed-axis rotation is the screw.
    turn = Motion.axis_rotation(axis, center, tau0, tau1)
    slide = Motion.translation([[0, adv * a] for a in axis])
    yield turn.then(slide), Motion.screw(axis, center, tau0, tau1, adv)
    # Two rotations about the origin: r = r_outer r_inner (degree 2), no translation.
    r1 = [[1], [0], [0], [tau0, tau1 - tau0]]         # about z
    r2 = [[1], [tau1, adv - tau1], [0], [0]]          # about x
    yield Motion(rotation=r1).compose(Motion(rotation=r2)), Motion(rotation=qmul(r1, r2))


@pytest.mark.parametrize("k", range(5))
def test_scene_on_composed_motions(k):
    rng = random.Random(SEED + 100 + k)
    for composed, by_hand in hand_written_cases(rng):
        moving = cube([F(rng.randint(-2, 1), 2) for _ in range(3)], F(1, 2))
        # The obstacle near where a corner of the moving box passes at some time
        # (shifted at random: hits and misses both occur).
        hit = rng.random() < 0.7  # the corner is inside the obstacle at that time
        corner = composed.position(moving.exact_vertices()[0], F(rng.randint(1, 3), 4))
        fixed = cube([c + (F(-1, 8) if hit else F(rng.randint(-3, 3), 4)) for c in corner], F(1, 4))
        ours = [P.Body(fixed, None, name="fixed"), P.Body(moving, composed, name="moving")]
        theirs = [P.Body(fixed, None, name="fixed"), P.Body(moving, by_hand, name="moving")]
        brute = summary(P.check(theirs, broad_phase="brute", time_tolerance="1e-9"))
        for broad_phase in ("brute", "boxes", "bvh", "range", "auto"):
            got = summary(P.check(ours, broad_phase=broad_phase, time_tolerance="1e-9"))
            assert got == brute, (SEED, k, broad_phase)


@pytest.mark.parametrize("k", range(4))
def test_general_composites_equal_brute_force(k):
    """Composites with rational body origin paths (turning outer, translating inner) in
    every broad phase against brute force."""
    rng = random.Random(SEED + 200 + k)
    bodies = []
    for i in range(3):
        axis = [rng.randint(-1, 1) for _ in range(3)]
        if axis == [0, 0, 0]:
            axis = [1, 0, 0]
        turn = Motion.axis_rotation(axis, [F(rng.randint(-2, 2), 2) for _ in range(3)],
                                    F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2))
        slide = Motion.linear([F(rng.randint(-2, 2), 2) for _ in range(3)],
                              [F(rng.randint(-2, 2), 2) for _ in range(3)])
        m = turn.compose(slide) if rng.random() < 0.7 else slide.compose(turn)
        shape = cube([F(rng.randint(-2, 2), 2) for _ in range(3)], F(rng.randint(1, 2), 2)) \
            if i != 1 else P.Spheres([[0, 0, 0], [F(1, 2), 0, 0]], [F(1, 4), F(1, 3)])
        bodies.append(P.Body(shape, m, name=f"b{i}"))
    brute = summary(P.check(bodies, broad_phase="brute", time_tolerance="1e-9", all_contacts=True))
    for broad_phase in ("boxes", "bvh", "range"):
        got = summary(P.check(bodies, broad_phase=broad_phase, time_tolerance="1e-9",
                              all_contacts=True))
        assert got == brute, (SEED, k, broad_phase)
