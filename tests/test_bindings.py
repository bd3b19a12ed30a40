"""The Python bindings: exact conversion, results, and every error path (the message
names the place of the bad input)."""
import dataclasses
import random
import threading
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
import sympy

import polyccd
from polyccd import InputError, LimitError

Z = [[0], [0], [0]]
# Static triangle (0,0,0) (3,0,0) (0,3,0): its centroid is (1,1,0).
TRIANGLE = [[[0], [0], [0]], [[3], [0], [0]], [[0], [3], [0]]]
T0 = np.array([[1, 1, 1], [0, 0, 0], [3, 0, 0], [0, 3, 0]], dtype=np.float64)
T1 = np.array([[1, 1, -1], [0, 0, 0], [3, 0, 0], [0, 3, 0]], dtype=np.float64)


def falling(z0, dz):
    """A vertex above the centroid moving along z(t) = z0 + dz t, and the triangle."""
    return [[[1], [1], [z0, dz]]] + TRIANGLE


def test_version_matches_the_library():
    assert polyccd.__version__ == "0.1.0"
    assert polyccd._ffi.string(polyccd._lib.pccd_version()).decode() == polyccd.__version__


def test_kinds():
    assert polyccd.KINDS == ("vertex-face", "edge-edge", "vertex-edge", "vertex-vertex",
                             "sphere-sphere")


def test_vertex_through_the_centroid_at_one_half():
    # z(t) = 1 - 2t is 0 exactly at t = 1/2, where the vertex is at the centroid.
    r = polyccd.solve("vertex-face", falling(1, -2))
    assert r.collides
    c = r.first_contact
    assert c.exact == c.lo == c.hi == Fraction(1, 2) and c.approx == 0.5
    assert r.features == (polyccd.Feature("vertex-face", (0, 1, 2, 3)),)
    assert r.stage in ("bounds", "bernstein", "interval", "exact")


def test_result_types_and_frozen():
    r = polyccd.solve("vertex-face", falling(1, -2))
    assert isinstance(r, polyccd.Result) and isinstance(r.collides, bool)
    c = r.first_contact
    assert isinstance(c, polyccd.ContactTime)
    assert all(type(x) is Fraction for x in (c.lo, c.hi, c.exact))
    assert type(c.approx) is float
    assert isinstance(r.features, tuple) and all(type(p) is int for p in r.features[0].points)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.collides = False


def test_no_contact_result():
    r = polyccd.solve("vertex-face", falling(1, 1))  # moves away
    assert (r.collides, r.first_contact, r.features) == (False, None, ())


def test_linear_entry_points_agree():
    r = polyccd.solve_linear("vertex-face", T0, T1)
    assert r.first_contact.exact == Fraction(1, 2)
    assert polyccd.collides_linear("vertex-face", T0, T1) is True
    assert polyccd.collides_linear("vertex-face", T1, T1) is False
    assert polyccd.collides_linear("vertex-face", T0.tolist(), T1.tolist()) is True
    assert polyccd.solve_linear("vertex-face", T0, T1, want_time=False).collides


@pytest.mark.parametrize("z0, t", [
    (1, Fraction(1)), ("1/3", Fraction(1, 3)), (Fraction(2, 7), Fraction(2, 7)),
    ("0.1", Fraction(1, 10)), ("2.5e-7", Fraction(1, 4000000)), (0.1, Fraction(0.1)),
    (np.float32(0.1), Fraction(float(np.float32(0.1)))), (np.int64(1), Fraction(1)),
    (Decimal("0.3"), Fraction(3, 10)), (0.5, Fraction(1, 2))])
def test_numbers_are_exact(z0, t):
    # z(t) = z0 - t reaches the face exactly at t = z0: a float is its binary value.
    assert polyccd.solve("vertex-face", falling(z0, -1)).first_contact.exact == t


def test_float_is_its_binary_value_not_its_decimal():
    assert polyccd.solve("vertex-face", falling(0.1, -1)).first_contact.exact != Fraction(1, 10)


def test_huge_integers_beyond_python_str_limit():
    n = 10 ** 5000  # more digits than sys.get_int_max_str_digits() allows by default
    # 16,611 bits: beyond the default input limit (PCCD_DEFAULT_MAX_NUMBER_BITS), which
    # says so and is raised for the call.
    with pytest.raises(polyccd.LimitError, match="config.max_number_bits = 16384"):
        polyccd.solve("vertex-face", falling(n, -n))
    r = polyccd.solve("vertex-face", falling(n, -n), limits=polyccd.Limits(max_number_bits=None))
    assert r.first_contact.exact == 1


def place_error(exc, place, *words, kind="vertex-face", points=None, **kw):
    with pytest.raises(exc) as info:
        polyccd.solve(kind, points, **kw)
    message = str(info.value)
    assert message.startswith(place + ":"), message
    for w in words:
        assert w in message, message
    return message


def with_coeff(value, point=1, axis=2, index=0):
    points = [[[0], [0], [0]] for _ in range(4)]
    points[point][axis] = [0] * index + [value]
    return points


@pytest.mark.parametrize("value, words", [
    (float("nan"), ["finite"]), (float("inf"), ["finite"]), (-float("inf"), ["finite"]),
    (np.float64("nan"), ["finite"]), (Decimal("NaN"), ["finite"]), (True, ["boolean"]),
    (np.bool_(False), ["boolean"]), (None, ["not a number"]), (1j, ["not a number"]),
    (b"1", ["not a number"]), ("1/0", ["zero denominator"]), ("abc", ['"abc"']),
    ("", ["not a number"]), (" 1", ["not a number"]), ("1\x002", ["NUL"]),
    ([1], ["not a number"])])
def test_bad_number_names_its_place(value, words):
    place_error(InputError, "points[1][2][3]", *words, points=with_coeff(value, 1, 2, 3))


@pytest.mark.parametrize("points, place, words", [
    ([Z] * 3, "points", ["4 points", "got 3"]),
    ([Z] * 5, "points", ["4 points"]),
    ("abcd", "points", ["expected"]),
    (None, "points", ["expected"]),
    ([Z, [[0], [0]], Z, Z], "points[1]", ["3 coefficient lists"]),
    ([Z, Z, "xyz", Z], "points[2]", ["expected"]),
    ([Z, Z, Z, [[0], 5, [0]]], "points[3][1]", ["coefficients"])])
def test_bad_shapes_name_their_place(points, place, words):
    place_error(InputError, place, *words, points=points)


def test_degree_above_64_is_a_limit_error():
    place_error(LimitError, "points[0][1]", "64", points=with_coeff(1, 0, 1, 65))
    assert polyccd.solve("vertex-face", with_coeff(1, 0, 1, 64)) is not None  # degree 64


def test_number_too_long_is_a_limit_error():
    place_error(LimitError, "points[0][0][0]", points=with_coeff("1" * 100001, 0, 0))
    place_error(LimitError, "points[0][0][0]", points=with_coeff("1e-100001", 0, 0))


def test_error_hierarchy():
    assert issubclass(InputError, polyccd.Error) and issubclass(InputError, ValueError)
    assert issubclass(LimitError, InputError)
    assert issubclass(polyccd.InternalError, polyccd.Error)


@pytest.mark.parametrize("kind", ["vertex_face", "", None, 0, "VERTEX-FACE"])
def test_bad_kind(kind):
    place_error(InputError, "kind", "vertex-face", kind=kind, points=[Z] * 4)


def test_radii():
    ball = [[[0], [0], [0]], [[3, -4], [0], [0]]]  # distance 3 - 4t reaches 1 at t = 1/2
    assert polyccd.solve("sphere-sphere", ball, ("1/2", 0.5)).first_contact.exact == Fraction(1, 2)
    place_error(InputError, "radii[0]", "greater than 0", kind="sphere-sphere", points=ball)  # unset
    place_error(InputError, "radii", "2 radii", kind="sphere-sphere", points=ball, radii=[1])
    place_error(InputError, "radii[1]", "greater than 0", kind="sphere-sphere", points=ball,
                radii=[1, 0])
    place_error(InputError, "radii[0]", "greater than 0", kind="sphere-sphere", points=ball,
                radii=["-1/2", 1])
    place_error(InputError, "radii[0]", "finite", kind="sphere-sphere", points=ball,
                radii=[float("nan"), 1])
    place_error(InputError, "radii", "only sphere-sphere", kind="vertex-vertex",
                points=[Z, Z], radii=[1, 1])


@pytest.mark.parametrize("tol, words", [("0", ["greater than 0"]), (-1, ["greater than 0"]),
                                        ("abc", ["not a number"]), (float("nan"), ["finite"])])
def test_bad_time_tolerance(tol, words):
    place_error(InputError, "config.time_tolerance", *words, points=falling(1, -2),
                time_tolerance=tol)


def test_time_tolerance_bounds_the_enclosure():
    # Edge (0,-1,z)-(0,1,z) falling along z = 1 - 2t^2 crosses the static edge on the x
    # axis at t = 1/sqrt(2), an irrational time: only an enclosure is reported.
    edges = [[[-1], [0], [0]], [[1], [0], [0]], [[0], [-1], [1, 0, -2]], [[0], [1], [1, 0, -2]]]
    for tol in ("1e-3", Fraction(1, 2 ** 40), "1e-30"):
        c = polyccd.solve("edge-edge", edges, time_tolerance=tol).first_contact
        assert c.exact is None and c.hi - c.lo <= Fraction(tol)
        assert c.lo ** 2 <= Fraction(1, 2) <= c.hi ** 2 and c.lo <= c.hi


@pytest.mark.parametrize("kind, a, place, words", [
    ("vertex-face", np.zeros((3, 3)), "p_t0", ["shape (4, 3)"]),
    ("vertex-face", np.zeros(12), "p_t0", ["shape (4, 3)"]),
    ("vertex-face", [[0, 0], [0]], "p_t0", ["shape"]),
    ("vertex-face", np.zeros((4, 3), dtype=bool), "p_t0", ["float64"]),
    ("vertex-vertex", [[0, 0, 0], [0, 0, np.nan]], "p_t0[1][2]", ["finite"]),
    ("sphere-sphere", np.zeros((2, 3)), "kind", ["radii"]),
    ("edge", np.zeros((4, 3)), "kind", ["not one of"])])
def test_linear_errors(kind, a, place, words):
    for call in (polyccd.solve_linear, polyccd.collides_linear):
        with pytest.raises(InputError) as info:
            call(kind, a, np.zeros((2 if kind in ("vertex-vertex", "sphere-sphere") else 4, 3)))
        assert str(info.value).startswith(place + ":"), str(info.value)
        assert all(w in str(info.value) for w in words), str(info.value)


@pytest.mark.parametrize("a", [[[Fraction(1, 3), 0, 0]] * 4,
                               np.array([[2 ** 60 + 1, 0, 0]] * 4)])
def test_linear_takes_values_that_are_not_doubles_exactly(a):
    """Not doubles (1/3, 2^60 + 1): solve_linear and collides_linear take the exact
    path, answering as solve() of x(t) = x0 + (x1 - x0) t; the batch entry point, on
    doubles only, names the value."""
    b = np.zeros((4, 3))
    trajs = [[[Fraction(a[i][k]), -Fraction(a[i][k])] for k in range(3)] for i in range(4)]
    want = polyccd.solve("vertex-face", trajs)
    assert polyccd.solve_linear("vertex-face", a, b) == want
    assert polyccd.collides_linear("vertex-face", a, b) == want.collides
    with pytest.raises(InputError, match=r"^t0\[0\]\[0\]\[0\]: .* is not exactly a float64"):
        polyccd.solve_linear_many("vertex-face", [a], [b])


def test_linear_accepts_non_contiguous_and_other_exact_dtypes():
    assert polyccd.collides_linear("vertex-face", np.asfortranarray(T0), T1.astype(np.float32))
    assert polyccd.collides_linear("vertex-face", T0.astype(np.int32), T1)
    assert polyccd.collides_linear("vertex-face", T0.astype(">f8"), T1)  # big-endian
    frozen = T0.copy()
    frozen.flags.writeable = False
    assert polyccd.collides_linear("vertex-face", frozen, T1)


def test_collides_linear_per_thread():
    answers = []

    def work():
        answers.append([polyccd.collides_linear("vertex-face", T0, b) for b in (T1, T0)] * 50)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert answers == [[True, False] * 50] * 4


def test_oracle_vertex_vertex_against_sympy():
    # Oracle: a point at (p(t), 0, 0) meets the origin at the least root of p in [0, 1].
    rng = random.Random(20240611)
    t = sympy.Symbol("t")
    for _ in range(25):
        roots = [Fraction(rng.randint(-4, 12), rng.randint(1, 8)) for _ in range(2)]
        p = sympy.expand(sympy.prod(t - sympy.Rational(r.numerator, r.denominator)
                                    for r in roots) - sympy.Rational(rng.randint(0, 3), 16))
        coeffs = [str(c) for c in reversed(sympy.Poly(p, t).all_coeffs())]
        r = polyccd.solve("vertex-vertex", [[coeffs, [0], [0]], Z])
        real = [x for x in sympy.real_roots(sympy.Poly(p, t)) if 0 <= x <= 1]
        assert r.collides == bool(real), (coeffs, r)
        if real:
            t_star, c = min(real), r.first_contact
            assert c.lo <= t_star <= c.hi, (coeffs, r)
            if t_star.is_rational:
                assert c.exact == Fraction(str(t_star)), (coeffs, r)
