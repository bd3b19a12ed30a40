"""Robot checks in one C call (pccd_robot_check, include/polyccd.h "Robots"): the robot's
chain and link bodies are attached to a pccd_robot once and kept for the Robot (rebuilt
when Robot.shapes changes); the allowed group pairs are handed over in one call when
they change. Only conversion here: the pair matrix, the filter, the lazy exact link
motions and the decide mode are the C library's. SRDF files are read here (XML only).
"""
import os
import weakref
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np

from . import _handles as handles
from . import _limits
from ._errors import InputError, check
from ._path import file_path
from ._pccd import ffi, lib
from ._scene import Body, _options, _read, _scratch
from ._solve import _items


# Robot -> (shapes key, (pccd_robot, bodies, groups, last allowed), shapes): kept beside
# the Robot rather than in it, so that a Robot still pickles (a cffi handle does not).
_HANDLES = weakref.WeakKeyDictionary()


def read_srdf(path, robot):
    """The link pairs of an SRDF file's <disable_collisions link1= link2=/> elements, as
    a set of frozensets of URDF link names. InputError for a missing or unreadable file
    or a link the robot does not have."""
    path = file_path(path, "srdf")
    if not os.path.isfile(path):
        raise InputError(f"srdf: file {path!r} not found")
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise InputError(f"srdf: {path!r} is not readable XML ({e})") from None
    out = set()
    for k, d in enumerate(root.iter("disable_collisions")):
        a, b = d.get("link1"), d.get("link2")
        for name, value in (("link1", a), ("link2", b)):
            if value not in robot.tree:
                raise InputError(f"srdf: disable_collisions[{k}].{name}: {value!r} is not a "
                                 f"link of {robot.name!r}")
        if a != b:
            out.add(frozenset((a, b)))
    return out


def _names(robot):
    count = {}
    for link, _, _, _ in robot.shapes:
        count[link] = count.get(link, 0) + 1
    return [link if count[link] == 1 else f"{link}[{i}]" for link, i, _, _ in robot.shapes]


def _handle(robot):
    """(pccd_robot, robot Bodies for the report's names, group of each URDF link): built
    on the first check and kept while robot.shapes holds the same geometry."""
    key = tuple((link, i, k, id(shape)) for link, i, k, shape in robot.shapes)
    cached = _HANDLES.get(robot)
    if cached is not None and cached[0] == key:
        return cached[1]
    r = handles.new("robot", robot.chain._handle)
    groups = {name: g for g, name in enumerate(robot.tree)}
    for link, _, k, shape in robot.shapes:
        check(lib.pccd_robot_add_body(r, k, groups[link], shape._handle, ffi.NULL))
    bodies = [Body(shape, None, name=name) for (_, _, _, shape), name in zip(robot.shapes, _names(robot))]
    # [the allowed set last handed to C, then (key, default allowed set) once known]
    made = (r, bodies, groups, [None])
    _HANDLES[robot] = (key, made, [s for *_, s in robot.shapes])  # the list keeps the ids valid
    return made


def _set_allowed(robot, made, allowed):
    r, _, groups, last = made
    if allowed is None:  # the default, recomputed only when the tree or SRDF pairs change
        srdf = robot.__dict__.get("srdf_pairs", set())
        key = (tuple(robot.tree.items()), frozenset(srdf))
        if len(last) < 3 or last[1] != key:
            last[1:] = [key, _validated(robot, robot.adjacent_pairs() | srdf)]
        allowed_set = last[2]
    else:
        allowed_set = _validated(robot, allowed)
    if last[0] == allowed_set:
        return
    flat = [groups[x] for pair in allowed_set for x in (sorted(pair) * 2)[:2]]
    arr = np.asarray(flat, dtype=np.uintp)
    check(lib.pccd_robot_set_allowed(r, ffi.from_buffer("size_t[]", arr), len(allowed_set)))
    last[0] = allowed_set


def _validated(robot, allowed):
    """The allowed link pairs as a set of frozensets; InputError naming a bad one."""
    allowed_set = set()
    pairs = list(allowed) if isinstance(allowed, (set, frozenset)) else \
        _items(allowed, "allowed", "an iterable of link-name pairs")  # a set of pairs: as good
    for k, pair in enumerate(pairs):
        pair = tuple(pair) if isinstance(pair, frozenset) else \
            tuple(_items(pair, f"allowed[{k}]", "a pair of link names"))
        if len(pair) != 2 or any(x not in robot.tree for x in pair):
            raise InputError(f"allowed[{k}]: {pair!r} is not a pair of link names")
        allowed_set.add(frozenset(pair))
    return allowed_set


_ROPT = {}


def _robot_options(self_collision, filter):
    for name, v in (("self_collision", self_collision), ("filter", filter)):
        if v not in (True, False):
            raise InputError(f"{name}: expected True or False, got {v!r}")
    key = (bool(self_collision), bool(filter))
    if key not in _ROPT:
        o = ffi.new("pccd_robot_options *")
        check(lib.pccd_robot_options_init(o))
        o.self_collision, o.filter = int(key[0]), int(key[1])
        _ROPT[key] = o
    return _ROPT[key]


_COMMON = {b"0": Fraction(0), b"1": Fraction(1)}  # most answers (Fractions are immutable)


def free_until(rep):
    """The report's certified contact-free prefix (pccd_report_free_until), a Fraction."""
    needed = ffi.new("size_t *")
    buf = ffi.new("char[]", 128)
    rc = lib.pccd_report_free_until(rep, buf, len(buf), needed, ffi.NULL)
    if rc == lib.PCCD_ERANGE:
        buf = ffi.new("char[]", needed[0])
        rc = lib.pccd_report_free_until(rep, buf, len(buf), needed, ffi.NULL)
    check(rc)
    text = ffi.string(buf)
    common = _COMMON.get(text)
    return common if common is not None else Fraction(text.decode("ascii"))


def check_robot(robot, ends, obstacles, *, self_collision, allowed, time_tolerance,
                all_contacts, threads, broad_phase, min_distance, limits, first_contact,
                filter):
    """(SceneResult, free_until) of one segment (Robot.check). ends: the chain values of
    its q0 and q1 (_joint_values.checked_ends)."""
    obstacles = checked_obstacles(obstacles)
    a0, a1 = ends
    made = _handle(robot)
    _set_allowed(robot, made, allowed)
    cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, True, limits,
                               min_distance, first_contact)
    ropt = _robot_options(self_collision, filter)
    obs, mot, n = obstacle_arrays(obstacles)
    rep = _scratch.report
    rc = _limits.run(cfg, lib.pccd_robot_check, made[0], ffi.from_buffer("double[]", a0),
                     ffi.from_buffer("double[]", a1), len(a0), obs, mot, n, cfg, opt, ropt, rep)
    if rc:
        check(rc)  # the chain names the joint: "q1[2] (elbow): ..."
    return _read(rep, report_bodies(made, obstacles)), free_until(rep)


def checked_obstacles(obstacles):
    """The obstacles as a list of polyccd.Body, or InputError naming the bad one."""
    obstacles = _items(obstacles, "obstacles", "an iterable of polyccd.Body")
    for i, o in enumerate(obstacles):
        if not isinstance(o, Body):
            raise InputError(f"obstacles[{i}]: expected a polyccd.Body, got {type(o).__name__}")
    return obstacles


def obstacle_arrays(obstacles):
    """(pccd_body *[], pccd_motion *[], count) of checked obstacles, for the C calls."""
    obs = ffi.new("pccd_body *[]", [o.shape._handle for o in obstacles] or [ffi.NULL])
    mot = ffi.new("pccd_motion *[]", [o.motion._handle if o.motion is not None else ffi.NULL
                                      for o in obstacles] or [ffi.NULL])
    return obs, mot, len(obstacles)


def report_bodies(made, obstacles):
    """The Bodies a robot report's indices refer to: the robot's, then the obstacles (a
    named obstacle itself: Bodies are immutable; an unnamed one renamed "obstacle<i>")."""
    return made[1] + [o if o.name is not None else Body(o.shape, o.motion, name=f"obstacle{i}")
                      for i, o in enumerate(obstacles)]
