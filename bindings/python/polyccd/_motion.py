"""Motion: an exact rigid motion over t in [0, 1], a thin wrapper of pccd_motion.

No geometry here: every number is converted exactly (see _numbers) and every motion is
built, composed and evaluated by the C library. A Motion never changes after it is
built; compose() returns a new one. The C library names a bad number as the Python
arguments nest it ("translation[1][2]", "ctrl[3][0]", "tau0"); its message is raised
as it is (_errors.check).

A Motion remembers how it was made (its recipe: the constructor and its exact number
texts), so that it pickles: unpickling replays the recipe in the C library (the C handle
itself cannot travel, e.g. to a Dask worker).
"""
from __future__ import annotations

from fractions import Fraction
from time import monotonic as _clock
from typing import TYPE_CHECKING, Optional, Sequence, Tuple, Union

from ._types import Coefficients, Number, Pose, Quaternion, Vector

if TYPE_CHECKING:
    from ._limits import Limits
from . import _handles as handles
from . import _limits
from ._errors import InputError, check
from ._numbers import fraction_from_text, number_text, show
from ._pccd import ffi, lib
from ._solve import _items, _texts

_SIDES = {"body": lib.PCCD_POSE_BODY, "world": lib.PCCD_POSE_WORLD}


def _vector(value, place, size=3):
    """The exact number texts of a vector of `size` numbers, or InputError."""
    items = _items(value, place, f"{size} numbers")
    if len(items) != size:
        raise InputError(f"{place}: expected {size} numbers, got {len(items)}")
    return [number_text(x, f"{place}[{i}]") for i, x in enumerate(items)]


def _polys(value, place, count, names):
    """count coefficient lists (each ascending powers of t) as lists of number texts."""
    lists = _items(value, place, f"{count} coefficient lists [{names}]")
    if len(lists) != count:
        raise InputError(f"{place}: expected {count} coefficient lists [{names}], "
                         f"got {len(lists)}")
    out = []
    for k, coeffs in enumerate(lists):
        items = _items(coeffs, f"{place}[{k}]", "a list of polynomial coefficients")
        out.append([number_text(c, f"{place}[{k}][{i}]") for i, c in enumerate(items)])
    return out


def _text(cstring):
    return ffi.string(cstring).decode("utf-8")


def _number(value, place):
    if isinstance(value, (list, tuple, dict)):
        raise InputError(f"{place}: expected a number, got {show(value)}")
    return ffi.new("char[]", number_text(value, place).encode("utf-8", "replace"))


class Motion:
    """An exact rigid motion: body point p is at R(r(t)) p + o(t) for t in [0, 1]
    (formats.md, MOTION). See docs/python.md, "Motions"."""

    __slots__ = ("_handle", "_recipe")

    def __init__(self, translation: Optional[Sequence[Coefficients]] = None,
                 rotation: Optional[Sequence[Coefficients]] = None) -> None:
        """translation: [xs, ys, zs] and rotation: [ws, xs, ys, zs], coefficient lists in
        ascending powers of t (omitted: zero translation, identity rotation)."""
        handle = handles.new("motion")
        recipe = [None, None]
        if translation is not None:
            recipe[0] = _polys(translation, "translation", 3, "xs, ys, zs")
            for axis, texts in enumerate(recipe[0]):
                array, _keep = _texts(texts)
                check(lib.pccd_motion_set_translation_s(handle, axis, array, len(texts)))
        if rotation is not None:
            recipe[1] = _polys(rotation, "rotation", 4, "ws, xs, ys, zs")
            for c, texts in enumerate(recipe[1]):
                array, _keep = _texts(texts)
                check(lib.pccd_motion_set_rotation_s(handle, c, array, len(texts)))
        object.__setattr__(self, "_handle", handle)
        object.__setattr__(self, "_recipe", ("__init__", tuple(recipe)))

    def __reduce__(self):
        """Pickles as its recipe (exact number texts); unpickling rebuilds it in C."""
        return _from_recipe, (self._recipe,)

    def __setattr__(self, name, value):
        raise AttributeError("a Motion cannot be changed; compose() returns a new one")

    def __copy__(self):
        return self  # immutable

    def __deepcopy__(self, memo):
        return self

    @classmethod
    def _wrap(cls, handle, recipe):
        motion = cls.__new__(cls)
        object.__setattr__(motion, "_handle", handle)
        object.__setattr__(motion, "_recipe", recipe)
        return motion

    @classmethod
    def _built(cls, recipe, setter, *arrays):
        """A new motion from one C setter taking (const char *[]) arrays / strings;
        recipe: (constructor name, its arguments as number texts)."""
        handle = handles.new("motion")
        check(setter(handle, *arrays))
        return cls._wrap(handle, recipe)

    @classmethod
    def translation(cls, coeffs_xyz: Sequence[Coefficients]) -> Motion:
        """A pure translation: [xs, ys, zs], ascending powers of t."""
        if coeffs_xyz is None:  # Motion(translation=None) is the identity; this is not
            raise InputError("coeffs_xyz: expected [xs, ys, zs] (coefficient lists), got None")
        return cls(translation=coeffs_xyz)

    @classmethod
    def linear(cls, p0: Vector, p1: Vector) -> Motion:
        """A translation moving linearly from p0 (t = 0) to p1 (t = 1)."""
        v0, v1 = _vector(p0, "p0"), _vector(p1, "p1")
        a0, k0 = _texts(v0)
        a1, k1 = _texts(v1)
        return cls._built(("linear", (v0, v1)), lib.pccd_motion_set_linear_translation_s, a0, a1)

    @classmethod
    def between(cls, pose0: Pose, pose1: Pose) -> Motion:
        """The motion from pose0 (t = 0) to pose1 (t = 1), each a 4x4 pose matrix (row
        major, last row exactly 0 0 0 1) or a (position, quaternion) pair with the
        quaternion as (w, x, y, z), any nonzero length; both poses of the same form.

        The body origin moves linearly, o(t) = (1 - t) p0 + t p1, and the quaternion is
        interpolated linearly, r(t) = (1 - t) q0 + t q1', where q1' is q1 or -q1 (the same
        rotation) with q0 . q1' >= 0: the body turns the shorter way round, along the
        great arc between the two orientations (not at a constant angular speed), and
        r(t) never vanishes. With (position, quaternion) pairs the end poses are exactly
        the given ones (numbers: floats at their binary values, ints, Fractions, strings).
        With matrices the translation is exact and the rotation is the exact rotation of
        the unit quaternion computed from the 3x3 block in doubles (equal to the block up
        to about 1e-15); a block that is not a rotation (orthonormal to 1e-6, det 1) is
        an InputError, as is a zero quaternion."""
        forms = [_pose_form(p, f"pose{i}") for i, p in enumerate((pose0, pose1))]
        if forms[0][0] != forms[1][0]:
            raise InputError("pose0, pose1: give both as 4x4 matrices or both as "
                             "(position, quaternion) pairs")
        if forms[0][0] == "matrix":
            m0, m1 = forms[0][1], forms[1][1]
            return cls._built(("between", (m0.tolist(), m1.tolist())),
                              lib.pccd_motion_set_between_matrices_d,
                              ffi.from_buffer("double[]", m0), ffi.from_buffer("double[]", m1))
        (p0, q0), (p1, q1) = forms[0][1], forms[1][1]
        texts = [_texts(v) for v in (p0, q0, p1, q1)]   # (array, buffers kept alive)
        return cls._built(("between", ((p0, q0), (p1, q1))), lib.pccd_motion_set_between_s,
                          *[array for array, _keep in texts])

    @classmethod
    def bezier(cls, ctrl: Sequence[Vector]) -> Motion:
        """The cubic Bezier translation of 4 control points [[x, y, z], ...] (through
        ctrl[0] at t = 0 and ctrl[3] at t = 1)."""
        points = _items(ctrl, "ctrl", "4 control points")
        if len(points) != 4:
            raise InputError(f"ctrl: expected 4 control points, got {len(points)}")
        texts = [x for i, point in enumerate(points) for x in _vector(point, f"ctrl[{i}]")]
        array, _keep = _texts(texts)
        recipe = ("bezier", ([texts[3 * i:3 * i + 3] for i in range(4)],))
        return cls._built(recipe, lib.pccd_motion_set_bezier_translation_s, array)

    @classmethod
    def hermite(cls, p0: Vector, v0: Vector, p1: Vector, v1: Vector) -> Motion:
        """The cubic Hermite translation: position p0, velocity v0 at t = 0; p1, v1 at 1."""
        vectors = [_vector(v, name) for v, name in ((p0, "p0"), (v0, "v0"), (p1, "p1"), (v1, "v1"))]
        arrays = [_texts(v) for v in vectors]
        return cls._built(("hermite", tuple(vectors)), lib.pccd_motion_set_hermite_translation_s,
                          *(a for a, _ in arrays))

    @classmethod
    def axis_rotation(cls, axis: Vector, center: Vector, tau0: Number, tau1: Number) -> Motion:
        """Rotation about the fixed axis through center (linear quaternion interpolation
        (1, tau0 axis) -> (1, tau1 axis)); tan(angle(t) / 2) = tau(t) ``|axis|``."""
        va, vc = _vector(axis, "axis"), _vector(center, "center")
        a, ka = _texts(va)
        c, kc = _texts(vc)
        n0, n1 = _number(tau0, "tau0"), _number(tau1, "tau1")
        recipe = ("axis_rotation", (va, vc, _text(n0), _text(n1)))
        return cls._built(recipe, lib.pccd_motion_set_axis_rotation_s, a, c, n0, n1)

    @classmethod
    def screw(cls, axis: Vector, center: Vector, tau0: Number, tau1: Number,
              advance: Number) -> Motion:
        """axis_rotation plus the translation advance * t * axis along the axis."""
        va, vc = _vector(axis, "axis"), _vector(center, "center")
        a, ka = _texts(va)
        c, kc = _texts(vc)
        n0, n1, adv = _number(tau0, "tau0"), _number(tau1, "tau1"), _number(advance, "advance")
        recipe = ("screw", (va, vc, _text(n0), _text(n1), _text(adv)))
        return cls._built(recipe, lib.pccd_motion_set_screw_s, a, c, n0, n1, adv)

    def compose(self, quat: Union[Quaternion, Motion], offset: Optional[Vector] = None,
                side: str = "body") -> Motion:
        """A new motion. compose(inner), inner a Motion: self o inner, the point p at
        self(inner(p, t), t) (pccd_motion_compose; degrees add). compose(quat, offset,
        side): this one composed with the constant pose (R(quat), offset);
        side="body": x'(t) = M(R p + offset); side="world": x'(t) = R M(p) + offset."""
        if isinstance(quat, Motion):
            if offset is not None or side != "body":
                raise InputError("offset, side: composing with a Motion takes no pose "
                                 "arguments")
            return _composed(self, quat)
        if offset is None:
            raise InputError("offset: missing (compose takes a Motion, or a quaternion "
                             "and an offset)")
        if not isinstance(side, str) or side not in _SIDES:
            raise InputError(f'side: {show(side)} is not "body" or "world"')
        vq, vo = _vector(quat, "quat", 4), _vector(offset, "offset")
        q, kq = _texts(vq)
        o, ko = _texts(vo)
        handle = handles.new("motion", self._handle, via="copy")
        check(lib.pccd_motion_compose_pose_s(handle, _SIDES[side], q, o))
        return Motion._wrap(handle, ("compose", (self._recipe, vq, vo, side)))

    def then(self, outer: Motion, *, limits: Optional[Limits] = None) -> Motion:
        """A new motion: outer o self, the point p at outer(self(p, t), t). limits: a
        polyccd.Limits (None: no limits, Ctrl-C still ends the call)."""
        if not isinstance(outer, Motion):
            raise InputError(f"outer: expected a Motion, got {show(outer)}")
        return _composed(outer, self, limits)

    def validate(self, *, limits: Optional[Limits] = None) -> Motion:
        """Returns self when r(t) vanishes nowhere on [0, 1]; else InputError with the
        first vanishing time (exact, or an enclosure when irrational). limits: a
        polyccd.Limits (None: no limits, Ctrl-C still ends the call)."""
        cfg = _limits.config(limits)
        check(_limits.run(cfg, lib.pccd_motion_validate_cfg, self._handle, cfg))
        return self

    def position(self, p: Vector, t: Number, *,
                 limits: Optional[Limits] = None) -> Tuple[Fraction, Fraction, Fraction]:
        """The exact position of body point p at time t in [0, 1]: 3 Fractions. limits: a
        polyccd.Limits (None: no limits, Ctrl-C still ends the call)."""
        point, _keep = _texts(_vector(p, "p"))
        time = _number(t, "t")
        cfg = _limits.config(limits)
        needed = ffi.new("size_t *")
        cap = 4096 + 4 * len(ffi.string(time))  # most answers fit: the work is done once
        buf = ffi.new("char[]", cap)
        start = _clock()
        rc = _limits.run(cfg, lib.pccd_motion_position_cfg_s, self._handle, point, time, cfg,
                         buf, cap, needed)
        if rc == lib.PCCD_ERANGE:
            buf = ffi.new("char[]", needed[0])
            if cfg.max_seconds > 0:  # the second call has what the first one left
                cfg.max_seconds = max(cfg.max_seconds - (_clock() - start), 1e-3)
            rc = _limits.run(cfg, lib.pccd_motion_position_cfg_s, self._handle, point, time, cfg,
                             buf, needed[0], needed)
        check(rc)
        return tuple(fraction_from_text(x) for x in ffi.string(buf).decode().split(" "))


def _pose_form(pose, place):
    """("matrix", a C-contiguous float64 (4, 4) array) or ("pair", (position texts,
    quaternion texts)) of one pose given to Motion.between."""
    import numpy as np
    if isinstance(pose, (tuple, list)) and len(pose) == 2:
        return "pair", (_vector(pose[0], f"{place}[0]"), _vector(pose[1], f"{place}[1]", 4))
    try:
        a = np.asarray(pose, dtype=np.float64)
    except (TypeError, ValueError):
        a = None
    if a is None or a.shape != (4, 4):
        raise InputError(f"{place}: expected a 4x4 pose matrix or a (position, quaternion) "
                         f"pair, got {show(pose)}")
    return "matrix", np.ascontiguousarray(a)


def _composed(outer, inner, limits=None):
    """outer o inner (both Motions), through pccd_motion_compose_cfg."""
    if not isinstance(inner, Motion):
        raise InputError(f"inner: expected a Motion, got {show(inner)}")
    cfg = _limits.config(limits)
    handle = _limits.run(cfg, handles.new, "motion", outer._handle, inner._handle, cfg,
                         via="compose_cfg")
    return Motion._wrap(handle, ("compose_motions", (outer._recipe, inner._recipe)))


# The builders of recipes named by the modules that make such Motions ("chain":
# polyccd._chain registers its own on import), so that this module imports none of them.
RECIPE_BUILDERS = {}


def _from_recipe(recipe):
    """The Motion of a recipe (see Motion.__reduce__): the same constructors, called with
    the exact number texts they recorded."""
    name, args = recipe
    if name == "__init__":
        return Motion(*args)
    if name in RECIPE_BUILDERS:
        return RECIPE_BUILDERS[name](*args)
    if name == "compose_motions":
        return _from_recipe(args[0]).compose(_from_recipe(args[1]))
    if name == "compose":
        parent, quat, offset, side = args
        return _from_recipe(parent).compose(quat, offset, side)
    return getattr(Motion, name)(*args)
