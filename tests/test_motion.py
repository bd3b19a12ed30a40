"""Rigid motions (polyccd.Motion) against an independent sympy oracle.

The oracle evaluates formats.md's MOTION formula directly: x(t) = R(r(t)) p + o(t) with
R(r) = ((w^2 - |v|^2) I + 2 v v^T + 2 w [v]x) / (w^2 + |v|^2), in exact sympy Rationals.
Every comparison is an exact equality; failures print the seed and the inputs.
"""
import copy
import random
import re
from fractions import Fraction

import pytest
import sympy

import polyccd
from polyccd import InputError, LimitError, Motion

T = sympy.Symbol("t")
SEED = 20240612


def rat(x):
    x = Fraction(x)
    return sympy.Rational(x.numerator, x.denominator)


def frac(x):
    x = sympy.nsimplify(x) if not isinstance(x, sympy.Rational) else x
    return Fraction(int(x.p), int(x.q))


def poly(coeffs):
    return sum((rat(c) * T ** i for i, c in enumerate(coeffs)), sympy.Integer(0))


def rot(q):
    """The oracle's R(q) for a quaternion q = (w, x, y, z) of sympy numbers."""
    w, x, y, z = q
    v = sympy.Matrix([x, y, z])
    skew = sympy.Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    n = w ** 2 + (v.T * v)[0]
    return ((w ** 2 - (v.T * v)[0]) * sympy.eye(3) + 2 * v * v.T + 2 * w * skew) / n


def oracle(translation, rotation):
    """x(p, t) of the MOTION (translation, rotation) as an exact function."""
    o = [poly(c) for c in translation]
    r = [poly(c) for c in rotation]

    def x(p, t):
        tv = rat(t)
        R = rot([c.subs(T, tv) for c in r])
        pos = R * sympy.Matrix([rat(c) for c in p]) + sympy.Matrix([c.subs(T, tv) for c in o])
        return tuple(frac(c) for c in pos)
    return x


def rnd(rng, lo=-9, hi=9, den=8):
    return Fraction(rng.randint(lo, hi), rng.randint(1, den))


def random_motion(rng):
    translation = [[rnd(rng) for _ in range(rng.randint(0, 3))] for _ in range(3)]
    # r may vanish somewhere: the tests only evaluate at times where it does not.
    rotation = [[rnd(rng) for _ in range(rng.randint(1, 3))] for _ in range(4)]
    return translation, rotation


def times(rng, n=5):
    return [Fraction(0), Fraction(1)] + [Fraction(rng.randint(0, 97), 97) for _ in range(n)]


def nonzero_at(rotation, t):
    return any(poly(c).subs(T, rat(t)) != 0 for c in rotation)


def test_identity_and_types():
    m = Motion()
    assert m.position([1, "2/3", 0.5], "1/2") == (1, Fraction(2, 3), Fraction(1, 2))
    assert all(type(c) is Fraction for c in m.position([1, 2, 3], 0))
    assert m.validate() is m
    with pytest.raises(AttributeError):
        m.anything = 1
    assert copy.deepcopy(m) is m


def test_random_motions_match_the_oracle():
    rng = random.Random(SEED)
    for case in range(30):
        translation, rotation = random_motion(rng)
        m, x = Motion(translation=translation, rotation=rotation), oracle(translation, rotation)
        for t in times(rng):
            if not nonzero_at(rotation, t):
                continue
            p = [rnd(rng) for _ in range(3)]
            assert m.position(p, t) == x(p, t), (SEED, case, translation, rotation, p, t)


def test_rotation_is_orthogonal_with_determinant_one():
    # R is read back from polyccd's positions: column i = x(e_i, t) - x(0, t).
    rng = random.Random(SEED + 1)
    for case in range(12):
        translation, rotation = random_motion(rng)
        m = Motion(translation=translation, rotation=rotation)
        for t in times(rng, 2):
            if not nonzero_at(rotation, t):
                continue
            origin = m.position([0, 0, 0], t)
            cols = [[a - b for a, b in zip(m.position(e, t), origin)]
                    for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
            R = sympy.Matrix(cols).T.applyfunc(rat)
            assert R * R.T == sympy.eye(3) and R.det() == 1, (SEED, case, rotation, t)
            assert R == rot([poly(c).subs(T, rat(t)) for c in rotation]), (case, rotation, t)


def test_rotation_scale_does_not_matter():
    # r and 3 r (and -r) are the same rotation.
    rotation = [[1, 2], [0, -1], ["1/2"], [3, 0, 1]]
    scaled = [[3 * Fraction(c) for c in comp] for comp in rotation]
    negated = [[-Fraction(c) for c in comp] for comp in rotation]
    for t in ("0", "1/3", "1"):
        p = [1, -2, "5/7"]
        assert (Motion(rotation=rotation).position(p, t) == Motion(rotation=scaled).position(p, t)
                == Motion(rotation=negated).position(p, t))


def test_linear_translation_hits_both_ends():
    p0, p1 = [1, "-1/3", 0.1], [Fraction(5, 2), 7, -2]
    m = Motion.linear(p0, p1)
    body = [Fraction(1, 7), 2, -1]
    at = lambda t: m.position(body, t)  # noqa: E731
    assert at(0) == tuple(b + Fraction(c) for b, c in zip(body, [1, Fraction(-1, 3), 0.1]))
    assert at(1) == tuple(b + c for b, c in zip(body, p1))
    mid = tuple(b + (Fraction(a) + Fraction(c)) / 2
                for b, a, c in zip(body, [1, Fraction(-1, 3), 0.1], p1))
    assert at("1/2") == mid


def axis_distance2(x, c, a):
    """Squared distance of x to the line c + s a (exact)."""
    d = [xi - ci for xi, ci in zip(x, c)]
    aa = sum(ai * ai for ai in a)
    da = sum(di * ai for di, ai in zip(d, a))
    return sum(di * di for di in d) - da * da / aa


@pytest.mark.parametrize("axis, center, tau0, tau1", [
    ([0, 0, 1], [0, 0, 0], 0, 1), ([1, 2, 2], [1, -1, "1/2"], "-1/3", "3/4"),
    ([1, 1, 0], [0, 5, 0], 2, -1), (["1/3", 0, "-2/5"], [3, 3, 3], 0, "1/7")])
def test_axis_rotation(axis, center, tau0, tau1):
    a, c = [Fraction(v) for v in axis], [Fraction(v) for v in center]
    m = Motion.axis_rotation(axis, center, tau0, tau1)
    rng = random.Random(SEED + 2)
    aa = sum(v * v for v in a)
    for t in times(rng, 4):
        tau = Fraction(tau0) + (Fraction(tau1) - Fraction(tau0)) * t
        for s in (Fraction(0), Fraction(-3, 2), Fraction(5)):  # points of the axis stay
            on_axis = [ci + s * ai for ci, ai in zip(c, a)]
            assert m.position(on_axis, t) == tuple(on_axis)
        p = [rnd(rng) for _ in range(3)]
        x = m.position(p, t)
        assert axis_distance2(x, c, a) == axis_distance2(p, c, a)
        # The angle: tan(theta / 2) = tau |a|, so cos = (1 - tau^2 |a|^2) / (1 + tau^2 |a|^2)
        # and sin |a| = 2 tau |a|^2 / (1 + ...), checked on the parts perpendicular to a.
        def perp(y):
            d = [yi - ci for yi, ci in zip(y, c)]
            k = sum(di * ai for di, ai in zip(d, a)) / aa
            return [di - k * ai for di, ai in zip(d, a)]
        u, v = perp(p), perp(x)
        uu, k2 = sum(ui * ui for ui in u), tau * tau * aa
        assert sum(ui * vi for ui, vi in zip(u, v)) == uu * (1 - k2) / (1 + k2)
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        assert sum(ci * ai for ci, ai in zip(cross, a)) == uu * 2 * tau * aa / (1 + k2)
        # The quaternion of the oracle (1, tau a) gives the same point.
        R = rot([1] + [rat(tau * ai) for ai in a])
        want = R * sympy.Matrix([rat(pi - ci) for pi, ci in zip(p, c)]) + sympy.Matrix(
            [rat(ci) for ci in c])
        assert x == tuple(frac(w) for w in want)


def test_screw_advances_along_the_axis():
    axis, center, advance = [2, -1, "1/2"], [1, 0, -1], "3/5"
    rotation = Motion.axis_rotation(axis, center, "1/4", -2)
    screw = Motion.screw(axis, center, "1/4", -2, advance)
    rng = random.Random(SEED + 3)
    for t in times(rng):
        p = [rnd(rng) for _ in range(3)]
        shift = [Fraction(advance) * t * Fraction(a) for a in axis]
        assert screw.position(p, t) == tuple(x + d for x, d in zip(rotation.position(p, t), shift))
    screw.validate()


def interpolated(m, p):
    """The cubic through polyccd's positions of p at t = 0, 1/3, 2/3, 1, per coordinate."""
    ts = [Fraction(k, 3) for k in range(4)]
    pts = [m.position(p, t) for t in ts]
    return [sympy.interpolate([(rat(t), rat(x[i])) for t, x in zip(ts, pts)], T) for i in range(3)]


def ends_and_tangents(curves):
    d = [sympy.diff(c, T) for c in curves]
    return ([frac(c.subs(T, 0)) for c in curves], [frac(c.subs(T, 1)) for c in curves],
            [frac(c.subs(T, 0)) for c in d], [frac(c.subs(T, 1)) for c in d])


def test_bezier_translation():
    ctrl = [[0, 0, 0], [1, "1/2", -1], [3, 2, "2/3"], [4, -1, 1]]
    c = [[Fraction(v) for v in point] for point in ctrl]
    m = Motion.bezier(ctrl)
    curves = interpolated(m, [0, 0, 0])
    assert ends_and_tangents(curves) == (c[0], c[3], [3 * (b - a) for a, b in zip(c[0], c[1])],
                                         [3 * (b - a) for a, b in zip(c[2], c[3])])
    bern = [sum(rat(c[k][i]) * sympy.binomial(3, k) * T ** k * (1 - T) ** (3 - k)
                for k in range(4)) for i in range(3)]
    assert all(sympy.expand(a - b) == 0 for a, b in zip(curves, bern))
    for t in (Fraction(1, 5), Fraction(7, 9)):  # not among the interpolation nodes
        assert m.position([1, 2, 3], t) == tuple(frac(b.subs(T, rat(t))) + k
                                                 for b, k in zip(bern, (1, 2, 3)))


def test_hermite_translation():
    p0, v0, p1, v1 = [1, 2, 3], ["1/2", 0, -4], [-1, 0, "5/3"], [2, 2, 0.25]
    m = Motion.hermite(p0, v0, p1, v1)
    want = tuple([Fraction(x) for x in vec] for vec in (p0, p1, v0, v1))
    assert ends_and_tangents(interpolated(m, [0, 0, 0])) == want
    still = Motion.hermite([0] * 3, [0] * 3, [0] * 3, [0] * 3)
    assert still.position([1, 1, 1], "1/2") == (1, 1, 1)


def random_pose(rng):
    return [rnd(rng) for _ in range(4)], [rnd(rng) for _ in range(3)]


def test_composition_equals_poses_in_sequence():
    rng = random.Random(SEED + 4)
    for case in range(10):
        translation, rotation = random_motion(rng)
        base = oracle(translation, rotation)
        m = Motion(translation=translation, rotation=rotation)
        steps = [(rng.choice(["body", "world"]),) + tuple(random_pose(rng)) for _ in range(3)]
        funcs = [base]
        for side, q, off in steps:
            if not any(q):
                q = [1, 0, 0, 0]
            m = m.compose(q, off, side=side)
            R = rot([rat(c) for c in q])
            inner = funcs[-1]

            def step(p, t, inner=inner, R=R, off=off, side=side):
                if side == "body":
                    moved = R * sympy.Matrix([rat(c) for c in p]) + sympy.Matrix(
                        [rat(c) for c in off])
                    return inner([frac(c) for c in moved], t)
                x = R * sympy.Matrix([rat(c) for c in inner(p, t)])
                return tuple(frac(a + rat(b)) for a, b in zip(x, off))
            funcs.append(step)
        for t in times(rng, 3):
            if not nonzero_at(rotation, t):
                continue
            p = [rnd(rng) for _ in range(3)]
            assert m.position(p, t) == funcs[-1](p, t), (SEED, case, translation, rotation,
                                                          steps, p, t)


def test_compose_returns_a_new_motion():
    m = Motion.linear([0, 0, 0], [1, 0, 0])
    before = m.position([1, 2, 3], "1/2")
    m2 = m.compose([0, 0, 0, 1], [1, 1, 1], side="world")  # half turn about z, then shift
    assert m.position([1, 2, 3], "1/2") == before
    assert m2.position([1, 2, 3], "1/2") == (-Fraction(1, 2), -1, 4)
    assert m.compose([2, 0, 0, 0], [0, 0, 0]).position([1, 2, 3], "1/2") == before


def vanishing_message(rotation):
    m = Motion(rotation=rotation)
    with pytest.raises(InputError) as info:
        m.validate()
    return str(info.value)


@pytest.mark.parametrize("rotation, when", [
    ([[0, 1], [0, 2], [0], [0, 0, 3]], "t = 0"),           # t divides every component
    ([[-1, 1], [1, -1], [0], [0]], "t = 1"),               # (t - 1) is common
    ([["-1/3", 1], ["2/3", -2], [0], ["-1/9", 0, 1]], "t = 1/3"),  # (t - 1/3) is common
    ([[-1, 0, 1], [-1, 1], [0], [0]], "t = 1"),            # gcd t - 1 (w has also -1)
    ([[0], [0], [0], [0]], "zero polynomial")])
def test_vanishing_rational_times(rotation, when):
    assert when in vanishing_message(rotation)


def test_vanishing_at_an_irrational_time():
    # w = t^2 - 1/2, x = y = z = 0 vanishes at 1/sqrt(2) only.
    message = vanishing_message([["-1/2", 0, 1], [0], [0], [0]])
    lo, hi = (Fraction(s) for s in re.search(r"(\d+/\d+) < t < (\d+/\d+)", message).groups())
    assert lo * lo < Fraction(1, 2) < hi * hi and hi - lo <= Fraction(1, 10 ** 12), message


@pytest.mark.parametrize("rotation", [
    [["-1/2", 1], ["-1/3", 1], [0], [0]],   # roots 1/2 and 1/3, none common
    [["-1/2", 0, 1], [0, 1], [0], [0]],      # w at 1/sqrt(2), x at 0
    [[0, 0, 1], [-1, 1], [1], [0]],          # y = 1 never vanishes
    [[0], [0], [0], [5]],                    # a constant quaternion (a half turn)
    [[-2, 0, 1], [-2, 0, 1], [0], [0]]])     # common root sqrt(2) lies outside [0, 1]
def test_valid_although_components_have_roots(rotation):
    Motion(rotation=rotation).validate()


def test_validation_against_sympy_gcd():
    # Oracle: r vanishes on [0, 1] iff gcd(w, x, y, z) has a real root there.
    rng = random.Random(SEED + 5)
    for case in range(20):
        common = poly([rnd(rng), rnd(rng)] + [1] * rng.randint(0, 1))
        rotation = []
        for _ in range(4):
            c = sympy.Poly(sympy.expand(common * poly([rnd(rng) for _ in range(2)])), T)
            rotation.append([Fraction(str(x)) for x in reversed(c.all_coeffs())])
        g = sympy.gcd_list([poly(c) for c in rotation])
        bad = g == 0 or (sympy.degree(g, T) > 0 and any(
            0 <= r <= 1 for r in sympy.real_roots(sympy.Poly(g, T))))
        m = Motion(rotation=rotation)
        if bad:
            with pytest.raises(InputError):
                m.validate()
        else:
            m.validate()


def test_position_where_r_vanishes_or_outside():
    m = Motion(rotation=[["-1/2", 1], [0], [0], [0]])
    assert m.position([1, 0, 0], 0) == (1, 0, 0)
    with pytest.raises(InputError, match="vanishes at t = 1/2"):
        m.position([1, 0, 0], "1/2")
    for t in ("-1/3", 2, "1.0000001"):
        with pytest.raises(InputError, match="outside"):
            Motion().position([0, 0, 0], t)


def test_floats_are_exact_binary_values():
    m = Motion.linear([0.1, 0, 0], [0.1, 0, 0])
    assert m.position([0, 0, 0], 0.5)[0] == Fraction(0.1) != Fraction(1, 10)
    big = 10 ** 5000  # beyond Python's int <-> str digit limit
    assert Motion.translation([[0, big], [0], [0]]).position([0, 0, 0], 1)[0] == big


def raises_at(exc, place, call, *words):
    with pytest.raises(exc) as info:
        call()
    message = str(info.value)
    assert message.startswith(place + ":"), message
    for w in words:
        assert w in message, message


@pytest.mark.parametrize("value, words", [
    (float("nan"), ["finite"]), (float("inf"), ["finite"]), ("1/0", ["zero denominator"]),
    ("abc", ['"abc"']), (True, ["boolean"]), (None, ["not a number"])])
def test_bad_numbers_name_their_place(value, words):
    raises_at(InputError, "translation[1][2]", lambda: Motion(translation=[[0], [0, 0, value], []]),
              *words)
    raises_at(InputError, "rotation[3][0]", lambda: Motion(rotation=[[1], [0], [0], [value]]),
              *words)
    raises_at(InputError, "p1[2]", lambda: Motion.linear([0, 0, 0], [0, 0, value]), *words)
    raises_at(InputError, "ctrl[2][1]", lambda: Motion.bezier([[0] * 3, [0] * 3, [0, value, 0],
                                                               [0] * 3]), *words)
    raises_at(InputError, "v1[0]", lambda: Motion.hermite([0] * 3, [0] * 3, [0] * 3,
                                                           [value, 0, 0]), *words)
    raises_at(InputError, "tau0", lambda: Motion.axis_rotation([0, 0, 1], [0] * 3, value, 1),
              *words)
    raises_at(InputError, "center[1]", lambda: Motion.screw([0, 0, 1], [0, value, 0], 0, 1, 1),
              *words)
    raises_at(InputError, "advance", lambda: Motion.screw([0, 0, 1], [0] * 3, 0, 1, value), *words)
    raises_at(InputError, "quat[3]", lambda: Motion().compose([1, 0, 0, value], [0] * 3), *words)
    raises_at(InputError, "offset[0]", lambda: Motion().compose([1, 0, 0, 0], [value, 0, 0]),
              *words)
    raises_at(InputError, "p[1]", lambda: Motion().position([0, value, 0], 0), *words)
    raises_at(InputError, "t", lambda: Motion().position([0, 0, 0], value), *words)


def test_bad_shapes_and_values():
    raises_at(InputError, "rotation", lambda: Motion(rotation=[[1], [0], [0], [0], [0]]), "4")
    raises_at(InputError, "rotation", lambda: Motion(rotation=[[1], [0], [0]]), "got 3")
    raises_at(InputError, "translation", lambda: Motion(translation="xyz"), "expected")
    raises_at(InputError, "translation[0]", lambda: Motion(translation=[5, [0], [0]]), "list")
    raises_at(InputError, "p0", lambda: Motion.linear([0, 0], [0, 0, 0]), "3 numbers")
    raises_at(InputError, "ctrl", lambda: Motion.bezier([[0] * 3] * 3), "4 control points")
    raises_at(InputError, "quat", lambda: Motion().compose([1, 0, 0], [0] * 3), "4 numbers")
    raises_at(InputError, "quat", lambda: Motion().compose([0, 0, 0, 0], [0] * 3), "zero")
    raises_at(InputError, "side", lambda: Motion().compose([1, 0, 0, 0], [0] * 3, side="left"))
    raises_at(InputError, "axis", lambda: Motion.axis_rotation([0, 0, 0], [0] * 3, 0, 1), "zero")
    raises_at(InputError, "tau1", lambda: Motion.axis_rotation([1, 0, 0], [0] * 3, 0, [1]))


def test_degree_limit():
    ok = [0] * polyccd._lib.PCCD_MAX_TRAJ_DEGREE + [1]  # degree 64
    Motion(translation=[ok, [0], [0]], rotation=[[1], ok, [0], [0]]).validate()
    raises_at(LimitError, "translation[2]", lambda: Motion(translation=[[0], [0], ok + [1]]), "64")
    raises_at(LimitError, "rotation[0]", lambda: Motion(rotation=[ok + [1], [0], [0], [0]]), "64")
    long_number = "1" * (polyccd._lib.PCCD_MAX_NUMBER_CHARS + 1)
    raises_at(LimitError, "rotation[1][0]", lambda: Motion(rotation=[[1], [long_number], [0], [0]]))
