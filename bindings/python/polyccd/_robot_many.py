"""Batches of robot checks in one C call (pccd_robot_check_many, pccd_robot_check_states):
Robot.check_many and Robot.check_states. Only conversion here, done on whole arrays so
that a segment costs no Python: the joint vectors become chain values by column, the
joint-limit policy of Robot.check is applied by comparison of arrays, and the answers
are numpy arrays filled by C. A segment whose rows cannot be converted, or that breaks
the joint limits, gets its error at its index (the message Robot.check would raise, with
"segments[k]: " before it) and the others their answers."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from . import _handles as handles
from . import _limits
from ._arrays import _float64_array
from ._errors import InputError, check, error_for, last_error
from ._pccd import ffi, lib
from ._robot_check import (_handle, _robot_options, _set_allowed, checked_obstacles,
                           free_until, obstacle_arrays, report_bodies)
from ._scene import _options, _read



@dataclass(frozen=True)
class RobotBatch:
    """The answers of Robot.check_many (or check_states), entry k for segment (pose) k,
    each as Robot.check would answer it: collides (bool array; False where not ok),
    lo, hi (float arrays: the contact time's enclosure rounded outward, the first
    contact's in first-contact mode, the witness's in decide mode; NaN without contact
    or answer), free_until (float array: a double <= the certified contact-free prefix;
    NaN without answer), ok (bool array: the segment was answered), errors ({k:
    InputError or LimitError} of the segments not answered, each message naming
    "segments[k]" or "states[k]"), results (a tuple of RobotResult, None where not ok,
    only when asked for with results=True; else None)."""
    collides: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    free_until: np.ndarray
    ok: np.ndarray
    errors: dict
    results: Optional[tuple] = None

    def __len__(self):
        return len(self.collides)

    def raise_first(self) -> None:
        """Raises the error of the first segment not answered, if any."""
        if self.errors:
            raise self.errors[min(self.errors)]


def _rows(robot, q, place, noun, errors):
    """The chain values of the joint vectors q (an (n, dof) array, or a list of rows) as
    an (n, chain links) float64 array; a row that is not a joint vector of the robot gets
    NaN values and its error in errors[k] (its message as Robot.check's, place[k])."""
    dof = len(robot.joints)
    if isinstance(q, (str, bytes, dict, set, frozenset)):
        raise InputError(f"{place}: expected an (n, {dof}) array of joint vectors, got "
                         f"{type(q).__name__}")
    try:
        a = _float64_array(q, place, f"(n, {dof})", lambda s: len(s) == 2 and s[1] == dof)
        rows = None
    except InputError:  # ragged or mistyped rows: each converted alone, for its message
        if isinstance(q, np.ndarray) and q.ndim != 2:
            raise
        try:
            rows = list(q)
        except TypeError:
            raise InputError(f"{place}: expected an (n, {dof}) array of joint vectors, got "
                             f"{type(q).__name__}") from None
        a = np.full((len(rows), dof), np.nan)
        for k, row in enumerate(rows):
            try:
                a[k] = _float64_array(row, place, f"({dof},)", lambda s: s == (dof,))
            except InputError:
                try:
                    robot.chain_values(row, _SINGLE[place])
                except InputError as e:
                    errors.setdefault(k, InputError(f"{noun}[{k}]: {e}"))
    out = np.zeros((a.shape[0], len(robot.chain)), dtype=np.float64)
    for j, name in enumerate(robot.joints):
        out[:, robot._joint_link[name]] = a[:, j]
    for k, (leader, mult, off) in robot._mimic.items():
        out[:, k] = mult * a[:, robot.joints.index(leader)] + off
    return a, out


# The place Robot.check names a segment's ends by.
_SINGLE = {"Q0": "q0", "Q1": "q1", "Q": "q0"}


def _joint_limit_errors(robot, ends, noun, errors, joint_limits):
    """errors[k] for every segment k with a finite joint value outside the URDF limits
    (the first end, then the first joint, as Robot.check_joint_limits), unless "ignore"."""
    if joint_limits == "ignore":
        return
    if joint_limits != "error":
        raise InputError(f'joint_limits: {joint_limits!r} is not "error" or "ignore"')
    lims = [robot.limits.get(name) or (None, None) for name in robot.joints]
    lo = np.array([-np.inf if a is None else a for a, _ in lims], dtype=np.float64)
    hi = np.array([np.inf if b is None else b for _, b in lims], dtype=np.float64)
    for place, a in ends:
        with np.errstate(invalid="ignore"):
            bad = np.isfinite(a) & ((a < lo) | (a > hi))
        for k in np.flatnonzero(bad.any(axis=1)):
            if k in errors:
                continue
            j = int(np.argmax(bad[k]))
            errors[int(k)] = InputError(
                f"{noun}[{k}]: {place}[{j}] ({robot.joints[j]}): {float(a[k, j])!r} is outside "
                f"the joint limits [{float(lo[j])!r}, {float(hi[j])!r}] of the URDF "
                f"(joint_limits=\"ignore\" allows it)")


def _segment_error(r, a0, a1, k, noun, n_obs, obs, mot, cfg, opt, ropt, status):
    """The error of failed segment k, "<noun>[k]: <pccd_robot_check's message>": the
    segment checked alone again (it fails before any exact work, or at the link motion
    the batch stopped at), so the batch keeps no message buffer of n entries."""
    rep = handles.new("report")
    rc = lib.pccd_robot_check(r, ffi.from_buffer("double[]", a0[k]), ffi.from_buffer("double[]", a1[k]),
                              a0.shape[1], obs, mot, n_obs, cfg, opt, ropt, rep)
    text = last_error() if rc else f"status {status}"
    function, sep, rest = text.partition(": ")
    return error_for(rc or status, f"pccd_robot_check: {noun}[{k}]: {rest if sep else text}")


def check_many(robot, q0, q1, obstacles, *, states, self_collision, allowed, time_tolerance,
               threads, min_distance, limits, first_contact, filter, joint_limits, results):
    """The RobotBatch of the segments q0[k] -> q1[k] (states: the poses q0[k], q1 None)."""
    noun = "states" if states else "segments"
    errors = {}
    if states:
        j0, a0 = _rows(robot, q0, "Q", noun, errors)
        ends = (("q0", j0),)
    else:
        j0, a0 = _rows(robot, q0, "Q0", noun, errors)
        j1, a1 = _rows(robot, q1, "Q1", noun, errors)
        if a0.shape[0] != a1.shape[0]:
            raise InputError(f"Q0, Q1: {a0.shape[0]} and {a1.shape[0]} joint vectors (segment k "
                             f"is Q0[k] -> Q1[k])")
        ends = (("q0", j0), ("q1", j1))
    _joint_limit_errors(robot, ends, noun, errors, joint_limits)
    if results not in (True, False):
        raise InputError(f"results: expected True or False, got {results!r}")
    obstacles = checked_obstacles(obstacles)
    made = _handle(robot)
    _set_allowed(robot, made, allowed)
    cfg, _keep, opt = _options(time_tolerance, False, threads, "auto", True, limits,
                               min_distance, first_contact)
    ropt = _robot_options(self_collision, filter)
    obs, mot, n_obs = obstacle_arrays(obstacles)
    n = a0.shape[0]
    status = np.zeros(n, dtype=np.intc)
    collides = np.zeros(n, dtype=bool)
    lo, hi, free = (np.empty(n, dtype=np.float64) for _ in range(3))
    out = ffi.new("pccd_robot_batch_out *")
    out.struct_size = ffi.sizeof("pccd_robot_batch_out")
    out.status = ffi.from_buffer("int[]", status)
    out.collides = ffi.from_buffer("unsigned char[]", collides)
    out.lo, out.hi = ffi.from_buffer("double[]", lo), ffi.from_buffer("double[]", hi)
    out.free_until = ffi.from_buffer("double[]", free)
    reports = [handles.new("report") for _ in range(n)] if results else []
    if results:
        rep_array = ffi.new("pccd_report *[]", reports or [ffi.NULL])
        out.reports = rep_array
    p0 = ffi.from_buffer("double[]", a0) if n else ffi.NULL
    if states:
        rc = _limits.run(cfg, lib.pccd_robot_check_states, made[0], p0, n, a0.shape[1], obs,
                         mot, n_obs, cfg, opt, ropt, out)
    else:
        p1 = ffi.from_buffer("double[]", a1) if n else ffi.NULL
        rc = _limits.run(cfg, lib.pccd_robot_check_many, made[0], p0, p1, n, a0.shape[1], obs,
                         mot, n_obs, cfg, opt, ropt, out)
    check(rc)  # the whole call: bad options or obstacles, a work limit, Cancel
    for k in np.flatnonzero(status != lib.PCCD_OK):
        k = int(k)
        if k not in errors:
            errors[k] = _segment_error(made[0], a0, a1 if not states else a0, k, noun, n_obs,
                                       obs, mot, cfg, opt, ropt, int(status[k]))
    ok = np.ones(n, dtype=bool)
    if errors:
        bad = np.fromiter(errors, dtype=np.intp, count=len(errors))
        ok[bad] = False
        collides[bad] = False
        lo[bad] = hi[bad] = free[bad] = np.nan
    out_results = None
    if results:
        from .robot import RobotResult
        bodies = report_bodies(made, obstacles)
        b0, b1 = (j0, j0) if states else (j0, j1)
        out_results = tuple(
            RobotResult.of(_read(reports[k], bodies), robot, b0[k], b1[k], free_until(reports[k]))
            if ok[k] else None for k in range(n))
    return RobotBatch(collides, lo, hi, free, ok, errors, out_results)
