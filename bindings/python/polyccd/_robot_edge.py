"""One robot segment's yes/no answer at the least Python per call, for planners' validators
(polyccd.ompl.RobotSpace: a state or an edge per OMPL callback). The same C call as
Robot.check (pccd_robot_check, with the same options, so the same answer), with what
does not depend on the joint values converted once: the obstacles' handle arrays, the
joint-to-chain columns and the joint limits as arrays; the per-call part is the
vectorized joint-limit test, two column copies and the C call. A segment the limits
refuse goes through Robot.check for its message; a C error is raised as Robot.check
raises it."""
import numpy as np

from . import _limits
from ._errors import check
from ._pccd import ffi, lib
from ._robot_check import (_handle, _robot_options, _set_allowed, checked_obstacles,
                           obstacle_arrays)
from ._scene import _options, _scratch

# Robot.check's keywords this path takes (first_contact is False: a yes/no answer).
KEYWORDS = {"self_collision", "allowed", "time_tolerance", "threads", "broad_phase",
            "min_distance", "limits", "filter", "joint_limits", "first_contact", "all_contacts"}


class EdgeCheck:
    """collides(q0, q1) == robot.check(q0, q1, obstacles, **options).collides for float64
    joint vectors q0, q1 (robot.joints order), options a subset of KEYWORDS; decide mode
    unless first_contact is True. Options are read again on every call (a caller may
    change them), their conversions cached as Robot.check caches them."""

    def __init__(self, robot, obstacles, options):
        self.robot, self.options = robot, options
        self.obstacles = checked_obstacles(obstacles)
        self._arrays = obstacle_arrays(self.obstacles)
        cols = [robot._joint_link[name] for name in robot.joints]
        self._cols = np.array(cols, dtype=np.intp)
        self._mimic = [(k, robot.joints.index(leader), mult, off)
                       for k, (leader, mult, off) in robot._mimic.items()]
        lims = [robot.limits.get(name) or (None, None) for name in robot.joints]
        self._lo = np.array([-np.inf if a is None else a for a, _ in lims], dtype=np.float64)
        self._hi = np.array([np.inf if b is None else b for _, b in lims], dtype=np.float64)
        n = len(robot.chain)
        self._a0, self._a1 = np.zeros(n), np.zeros(n)
        self._p0, self._p1 = ffi.from_buffer("double[]", self._a0), ffi.from_buffer("double[]", self._a1)
        self._out = ffi.new("int *")

    def _values(self, a, q):
        a[self._cols] = q
        for k, j, mult, off in self._mimic:
            a[k] = mult * q[j] + off

    def collides(self, q0, q1):
        o = self.options
        if o.get("joint_limits", "error") != "ignore" and (
                (q0 < self._lo).any() or (q0 > self._hi).any() or
                (q1 < self._lo).any() or (q1 > self._hi).any()):
            return self.robot.check(q0, q1, self.obstacles, **o).collides  # raises its error
        self._values(self._a0, q0)
        self._values(self._a1, q1)
        robot = self.robot
        made = _handle(robot)
        _set_allowed(robot, made, o.get("allowed"))
        cfg, _keep, opt = _options(o.get("time_tolerance", "1e-12"), o.get("all_contacts", False),
                                   o.get("threads", 1), o.get("broad_phase", "auto"), True,
                                   o.get("limits"), o.get("min_distance"),
                                   o.get("first_contact", False))
        ropt = _robot_options(o.get("self_collision", True), o.get("filter", True))
        obs, mot, n = self._arrays
        rep = _scratch.report
        rc = _limits.run(cfg, lib.pccd_robot_check, made[0], self._p0, self._p1, len(self._a0),
                         obs, mot, n, cfg, opt, ropt, rep)
        if rc:
            check(rc)  # the chain names the joint, as for Robot.check
        check(lib.pccd_report_collides(rep, self._out))
        return bool(self._out[0])
