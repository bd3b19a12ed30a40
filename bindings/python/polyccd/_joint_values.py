"""A robot's actuated joint values: validated once, expanded to the chain's values, and
checked against the joint limits (Robot.chain_values, check_joint_limits, check). A
Robot.check converted and validated q0 and q1 four times and rebuilt the limit arrays
(about 20 us of a 170 us Panda edge check from Python, issue 30); now once each."""
import numpy as np

from ._arrays import _float64_array
from ._errors import InputError


def q_array(robot, q, place):
    """q as a float64 array of one value per actuated joint (each exactly a double), or
    InputError naming place."""
    if not isinstance(place, str):
        raise InputError(f"place: expected a string, got {place!r}"[:120])
    n = len(robot.joints)
    q = _float64_array(q, place, f"({n},)", lambda s: True)
    if q.shape != (n,):
        raise InputError(f"{place}: expected {n} joint values "
                         f"({', '.join(robot.joints)}), got shape {q.shape}")
    return q


def expand(robot, q):
    """The chain's joint values (by chain link) of the validated actuated values q. (Per
    joint on one vector: numpy's fancy indexing costs more on 8 values; check_many's
    _rows does the same over rows.)"""
    out = np.zeros(len(robot.chain), dtype=np.float64)
    for j, name in enumerate(robot.joints):
        out[robot._joint_link[name]] = q[j]
    for k, (leader, mult, off) in robot._mimic.items():
        out[k] = mult * q[robot.joints.index(leader)] + off
    return out


def limit_arrays(robot):
    """(lower, upper) arrays of the joints' limits (-inf / inf where none), or None when a
    limit is not a number (the per-joint loop of check then decides alone). Kept with
    the robot while robot.limits holds the same entries (a public dict: compared per
    call, 8 lookups)."""
    key = tuple(robot.limits.get(name) for name in robot.joints)
    cached = robot.__dict__.get("_limit_cache")
    if cached is not None and cached[0] == key:
        return cached[1]
    try:
        lims = [lim or (None, None) for lim in key]
        arrays = (np.array([-np.inf if a is None else a for a, _ in lims], dtype=np.float64),
                  np.array([np.inf if b is None else b for _, b in lims], dtype=np.float64))
    except (TypeError, ValueError):
        arrays = None
    robot.__dict__["_limit_cache"] = (key, arrays)
    return arrays


def check_limits(robot, q, place, bounds):
    """InputError "place[j] (joint): value is outside the joint limits [lower, upper]" for
    the first joint of q (validated) outside its limits; non-finite values are left to
    the chain's check. bounds: limit_arrays(robot)."""
    if bounds is not None and not (np.isfinite(q) & ~((bounds[0] <= q) & (q <= bounds[1]))).any():
        return  # nothing outside: the loop below (which words the error) finds nothing
    for j, name in enumerate(robot.joints):
        lim = robot.limits.get(name)
        x = float(q[j])
        if lim is None or not np.isfinite(x):
            continue
        lo, hi = (-np.inf if lim[0] is None else lim[0]), (np.inf if lim[1] is None else lim[1])
        if not lo <= x <= hi:
            raise InputError(f"{place}[{j}] ({name}): {x!r} is outside the joint limits "
                             f"[{lo!r}, {hi!r}] of the URDF (joint_limits=\"ignore\" "
                             f"allows it)")


def checked_ends(robot, q0, q1, joint_limits):
    """The chain values of q0 and q1 (C-contiguous), after the joint-limit policy (see
    Robot.check_joint_limits): q0 is validated and checked before q1, as before."""
    if joint_limits not in ("error", "ignore"):
        raise InputError(f'joint_limits: {joint_limits!r} is not "error" or "ignore"')
    bounds = limit_arrays(robot) if joint_limits == "error" else None
    out = []
    for place, q in (("q0", q0), ("q1", q1)):
        x = q_array(robot, q, place)
        if joint_limits == "error":
            check_limits(robot, x, place, bounds)
        out.append(expand(robot, x))
    return out
