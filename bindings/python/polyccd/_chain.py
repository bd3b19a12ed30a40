"""Chain: a kinematic chain (tree) of links, a thin wrapper of pccd_chain.

No geometry here: the C library turns joint origins (xyz, roll-pitch-yaw) and joint
values into exact rigid motions (include/polyccd.h, "Kinematic chains"). A Chain only
grows (add_link); the motions it gives are ordinary Motions (they pickle as the chain's
links and the segment's joint values, rebuilt by the C library).
"""
from __future__ import annotations

import numpy as np

from typing import TYPE_CHECKING, List, Optional, Sequence

from ._types import Number

if TYPE_CHECKING:
    from ._limits import Limits
    from ._motion import Motion
from . import _handles as handles
from . import _limits
from ._arrays import _float64_array
from ._errors import InputError, check
from ._motion import RECIPE_BUILDERS, Motion, _number
from ._numbers import show
from ._pccd import ffi, lib

JOINTS = {"fixed": lib.PCCD_JOINT_FIXED, "revolute": lib.PCCD_JOINT_REVOLUTE,
          "continuous": lib.PCCD_JOINT_CONTINUOUS, "prismatic": lib.PCCD_JOINT_PRISMATIC}


def _doubles(value, place, size):
    """A float64 array of `size` numbers (floats are taken as their exact value)."""
    a = _float64_array(value, place, f"({size},)", lambda s: True)  # types, bools, exactness
    if a.shape != (size,):
        raise InputError(f"{place}: expected {size} numbers, got shape {a.shape}")
    return a


class Chain:
    """Links joined by fixed / revolute / continuous / prismatic joints (URDF's
    conventions); see docs/robots.md, "Kinematic chains"."""

    __slots__ = ("_handle", "_links")

    def __init__(self) -> None:
        self._handle = handles.new("chain")
        self._links = []

    def add_link(self, parent: int = -1, joint: str = "fixed", axis: Optional[Sequence[float]] = None,
                 xyz: Sequence[float] = (0, 0, 0), rpy: Sequence[float] = (0, 0, 0)) -> int:
        """Appends a link hung from `parent` (an earlier link's index, or -1: the world)
        by a joint of type `joint` with origin (xyz, rpy) and axis; returns its index."""
        if not isinstance(joint, str) or joint not in JOINTS:
            raise InputError(f"joint: {show(joint)} is not one of {', '.join(JOINTS)}")
        if isinstance(parent, bool) or not isinstance(parent, (int, np.integer)):
            raise InputError(f"parent: expected a link index, got {show(parent)}")
        a = ffi.NULL if axis is None else _doubles(axis, "axis", 3)
        p, r = _doubles(xyz, "xyz", 3), _doubles(rpy, "rpy", 3)
        index = ffi.new("size_t *")
        check(lib.pccd_chain_add_link(
            self._handle, int(parent), JOINTS[joint],
            a if a is ffi.NULL else ffi.from_buffer("double[]", a),
            ffi.from_buffer("double[]", p), ffi.from_buffer("double[]", r), index))
        self._links.append((int(parent), joint, None if axis is None else tuple(map(float, a)),
                            tuple(map(float, p)), tuple(map(float, r))))
        return index[0]

    def set_value_place(self, k: int, place: str) -> None:
        """Errors about link k's joint value name it "q0" / "q1" followed by place
        instead of "[k]" (pccd_chain_set_value_place): e.g. a robot says "[2] (elbow)"
        for its joint 2, and a bad value reads "q1[2] (elbow): ..."."""
        if not isinstance(place, str):
            raise InputError(f"place: expected a string, got {show(place)}")
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
            raise InputError(f"k: expected a link index, got {show(k)}")
        check(lib.pccd_chain_set_value_place(self._handle, int(k), place.encode()))
        parent, joint, axis, xyz, rpy = self._links[k][:5]
        self._links[k] = (parent, joint, axis, xyz, rpy, place)

    def __len__(self):
        return len(self._links)

    def _segment(self, q0, q1):
        n = len(self._links)
        return _doubles(q0, "q0", n), _doubles(q1, "q1", n)

    def motions(self, q0: Sequence[float], q1: Sequence[float], *,
                limits: Optional[Limits] = None) -> List[Motion]:
        """The world Motion of every link over the segment q0 -> q1 (q[k]: link k's joint
        value, ignored for fixed joints). limits: a polyccd.Limits over the compositions
        and the links' numbers (None: no limits, Ctrl-C still ends the call)."""
        a0, a1 = self._segment(q0, q1)
        n = len(self._links)
        out = ffi.new("pccd_motion *[]", max(n, 1))
        cfg = _limits.config(limits)
        check(_limits.run(cfg, lib.pccd_chain_segment_motions_cfg, self._handle,
                          ffi.from_buffer("double[]", a0), ffi.from_buffer("double[]", a1), n,
                          cfg, out))
        links, t0, t1 = tuple(self._links), tuple(map(float, a0)), tuple(map(float, a1))
        return [Motion._wrap(ffi.gc(out[k], lib.pccd_motion_free), ("chain", (links, t0, t1, k)))
                for k in range(n)]

    def joint_values(self, q0: Sequence[float], q1: Sequence[float], t: Number) -> np.ndarray:
        """The joint values (float64 array, by link) at time t in [0, 1] of the segment:
        outputs, computed from the exact motion (fixed joints: 0)."""
        a0, a1 = self._segment(q0, q1)
        n = len(self._links)
        values = np.zeros(n, dtype=np.float64)
        check(lib.pccd_chain_joint_values_s(self._handle, ffi.from_buffer("double[]", a0),
                                            ffi.from_buffer("double[]", a1), n, _number(t, "t"),
                                            ffi.from_buffer("double[]", values)))
        return values

    def __reduce__(self):
        return _chain_from_links, (tuple(self._links),)


def _chain_from_links(links):
    c = Chain()
    for k, (parent, joint, axis, xyz, rpy, *place) in enumerate(links):
        c.add_link(parent, joint, axis, xyz, rpy)
        if place:
            c.set_value_place(k, place[0])
    return c


def motion_from_recipe(links, q0, q1, k):
    """The Motion of a "chain" recipe (Motion pickling)."""
    return _chain_from_links(links).motions(q0, q1)[k]


RECIPE_BUILDERS["chain"] = motion_from_recipe
