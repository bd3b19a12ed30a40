"""polyccd.ompl: OMPL's planners with polyccd's exact checks for a Robot among obstacles.

An optional extra: `pip install "polyccd[ompl]"` adds it to an installed polyccd (PyPI
ompl >= 2.0.1, OMPL's nanobind bindings; from a checkout: `pip install
"./bindings/python[ompl]"`). `import polyccd` never imports this module, and this module
imports ompl only when an OMPL object is made (RobotSpace, MotionValidator,
StateValidityChecker): without it they raise ImportError naming the extra. In short::

    from polyccd.ompl import RobotSpace
    space = RobotSpace(robot, obstacles, fixed={"panda_finger_joint1": 0.02},
                       self_collision=False)        # further keywords go to Robot.check
    ss = space.simple_setup()                      # an ompl.geometric.SimpleSetup
    ss.setStartAndGoalStates(space.state(q_start), space.state(q_goal))
    ss.setPlanner(ompl.geometric.RRTConnect(space.si)); ss.solve(10.0)
    waypoints = space.waypoints(ss.getSolutionPath())   # joint vectors (robot.joints order)
    poses = space.interpolate_path(waypoints, 0.01)     # dense, along polyccd's joint path

The state space is an ompl.base.RealVectorStateSpace over the planned joints (bounds:
the URDF limits; continuous joints [-pi, pi]; `bounds=` overrides), the other actuated
joints held at `fixed` values. Its SpaceInformation gets

  - StateValidityChecker: ``Robot.check(q, q, obstacles, **check_options)``, the exact check
    of the robot standing still at q (a zero-length segment: constant link motions);
  - MotionValidator: ``Robot.check(q1, q2, obstacles, **check_options)``, the exact check of
    the segment's joint path. checkMotion(s1, s2) -> bool; checkMotion(s1, s2, last_valid)
    with last_valid a list [state or None, fraction] (OMPL's std::pair<State*, double>&):
    when the motion is invalid, last_valid[1] = f strictly before the certified first
    contact (f < ContactTime.lo) and last_valid[0] the state at f on the joint path, such
    that the path s1 -> that state is contact-free by one more exact check (its joint
    path is not exactly the prefix of s1 -> s2: each joint's half-angle interpolation
    is reparametrized differently); f = 0 and s1 itself when the contact is at t = 0.
    checkMotionWithLastValid(s1, s2, state) -> (valid, f) is the same for OMPL bindings
    whose trampoline forwards the C++ three-argument form (ompl 2.0.1's does not: C++
    planners calling it, such as KPIECE1, get the two-argument answer and an untouched
    last valid state there).

Any exception inside a check (a LimitError from `limits=`, say) makes the state or
motion invalid (never accepted unchecked) and is kept in `space.errors`.

The joint path. polyccd's chain moves a revolute joint from a to b by interpolating the
half-angle quaternion (c, s) linearly between (cos(a/2), sin(a/2)) and (cos(b/2),
sin(b/2)) (lib/motion/chain.h), so the angle at time t is a + 2 atan2(C0 S - S0 C, C0 C +
S0 S), not a + t (b - a); prismatic joints move linearly. RobotSpace.interpolate and
interpolate_path follow that path: the path executed is the path validated. OMPL's own
interpolation (C++ RealVectorStateSpace::interpolate, linear in the angles) cannot be
replaced from Python with ompl 2.0.1 (its state spaces have no trampoline), so: leave
RRTConnect's intermediate states off (its default), densify a solution with
interpolate_path rather than PathGeometric.interpolate, and simplify with simplify()
(OMPL's reduceVertices and collapseCloseVertices, which check every new edge with the
motion validator), not with shortcutting, which keeps sub-edges of linear
interpolations unchecked; check_path() re-checks any path exactly.
"""
import math
import time
import weakref
from fractions import Fraction

import numpy as np

from . import _ompl_args as _a
from ._errors import InputError
from ._flags import real
from ._robot_edge import KEYWORDS, EdgeCheck
from ._solve import _items

# The public names (the generated reference lists each: tests/test_docs.py; the typed
# argument tests call each); MotionValidator and StateValidityChecker are made when first
# used (__getattr__).
__all__ = ["RobotSpace", "MotionValidator", "StateValidityChecker", "joint_path", "joint_space",
           "simplify", "BACKOFF"]

#: last_valid's candidate fractions: ContactTime.lo times these, each tried until the
#: path from s1 to its state is contact-free (exactly); then s1 itself.
BACKOFF = (Fraction(15, 16), Fraction(3, 4), Fraction(1, 2), Fraction(1, 8))


def _ompl():
    """(ompl.base, ompl.geometric); ModuleNotFoundError naming the "ompl" extra."""
    from ._extras import need
    return (need("polyccd.ompl", "ompl", "ompl.base"),
            need("polyccd.ompl", "ompl", "ompl.geometric"))


def joint_path(revolute, q0, q1, t):
    """The joint values at times t (a scalar or an array, in [0, 1]) of polyccd's joint path
    from q0 to q1 (float arrays; revolute: a bool mask, True for revolute / continuous
    joints): 2 atan2 of the linearly interpolated half-angle (cos, sin), chain.h. Floats:
    within a few ulps of Robot.joint_values, which evaluates the exact path. Shape
    (len(t), n) for an array t, (n,) for a scalar."""
    revolute = _a.mask(revolute, "revolute")
    q0, q1 = _a.vector(q0, "q0"), _a.vector(q1, "q1")
    if not len(revolute) == len(q0) == len(q1):
        raise InputError(f"revolute, q0, q1: lengths {len(revolute)}, {len(q0)}, {len(q1)} differ")
    t = _a.times(t)
    tt = t[..., None] if t.ndim else t
    c0, s0, c1, s1 = np.cos(q0 / 2), np.sin(q0 / 2), np.cos(q1 / 2), np.sin(q1 / 2)
    c, s = (1 - tt) * c0 + tt * c1, (1 - tt) * s0 + tt * s1
    turned = q0 + 2 * np.arctan2(c0 * s - s0 * c, c0 * c + s0 * s)
    return np.where(revolute, turned, (1 - tt) * q0 + tt * q1)


def joint_space(names, bounds):
    """An ompl.base.RealVectorStateSpace with one dimension per joint name, bounds
    [(lo, hi)] (OMPL interpolates it linearly: see the module comment)."""
    ob, _ = _ompl()
    names = _a.names(names, "names")
    bounds = [_a.interval(b, f"bounds[{i}]") for i, b in enumerate(_items(bounds, "bounds", "(lo, hi) pairs"))]
    if len(bounds) != len(names):
        raise InputError(f"names, bounds: {len(names)} names but {len(bounds)} (lo, hi) pairs")
    space = ob.RealVectorStateSpace(len(names))
    b = ob.RealVectorBounds(len(names))
    for i, (lo, hi) in enumerate(bounds):
        b.setLow(i, lo)
        b.setHigh(i, hi)
    space.setBounds(b)
    for i, name in enumerate(names):
        space.setDimensionName(i, name)
    return space


def simplify(si, path, rounds=3):
    """Shortens an OMPL PathGeometric in place with the simplifications that check every
    new edge with si's motion validator and create no state by interpolation
    (reduceVertices, then collapseCloseVertices, up to `rounds` times); returns it."""
    ob, og = _ompl()
    _a.instance(si, "si", ob.SpaceInformation, "an ompl.base.SpaceInformation")
    _a.instance(path, "path", og.PathGeometric, "an ompl.geometric.PathGeometric")
    rounds = _a.count(rounds, "rounds")
    simplifier = og.PathSimplifier(si)
    for _ in range(rounds):
        changed = simplifier.reduceVertices(path)
        changed = simplifier.collapseCloseVertices(path) or changed
        if not changed:
            break
    return path


class RobotSpace:
    """OMPL's state space, SpaceInformation and validators for a polyccd Robot among
    obstacles (see the module comment). joints: the planned joints (names; default every
    actuated joint not fixed); fixed: {joint: value} of the other actuated joints (each required);
    bounds: {joint: (lo, hi)} replacing the URDF limits (beyond them, pass
    joint_limits="ignore" too: Robot.check rejects values outside the limits); check_options: keywords of
    Robot.check (self_collision, allowed, time_tolerance, limits, ...; first_contact=False
    once Robot.check takes it: the last-valid form drops it, it needs the time)."""

    def __init__(self, robot, obstacles=(), *, joints=None, fixed=None, bounds=None,
                 **check_options):
        ob, _ = _ompl()
        from .robot import Robot
        from ._scene import Body
        _a.instance(robot, "robot", Robot, "a polyccd.robot.Robot")
        self.robot, self.obstacles = robot, _items(obstacles, "obstacles", "a list of polyccd.Body")
        for k, o in enumerate(self.obstacles):
            _a.instance(o, f"obstacles[{k}]", Body, "a polyccd.Body")
        self.check_options = dict(check_options)
        fixed, bounds = _a.joint_map(fixed, "fixed", real), _a.joint_map(bounds, "bounds", _a.interval)
        self.joints = ([n for n in robot.joints if n not in fixed] if joints is None
                       else _a.names(joints, "joints"))
        for place, names in (("joints", self.joints), ("fixed", fixed), ("bounds", bounds)):
            for name in names:
                if name not in robot.joints:
                    raise InputError(f"{place}: {name!r} is not an actuated joint of "
                                     f"{robot.name} ({', '.join(robot.joints)})")
        for name in self.joints:
            if name in fixed:
                raise InputError(f"fixed: joint {name!r} is also planned (joints)")
        self._index = [robot.joints.index(n) for n in self.joints]
        self._q = np.zeros(len(robot.joints))  # the fixed joints' values
        self._planned = np.isin(np.arange(len(robot.joints)), self._index)
        for j, name in enumerate(robot.joints):
            if name in self.joints:
                continue
            if name not in fixed:
                raise InputError(f"fixed: joint {name!r} is neither planned nor fixed")
            self._q[j] = float(fixed[name])
        kinds = [robot.joint_types[n] for n in robot.joints]
        self._revolute = np.array([k in ("revolute", "continuous") for k in kinds])
        self.bounds = []
        for name in self.joints:
            lim = bounds.get(name, robot.limits.get(name))
            if lim is None:
                lim = (-math.pi, math.pi)
            self.bounds.append((float(lim[0]), float(lim[1])))
        self.space = joint_space(self.joints, self.bounds)
        self.si = ob.SpaceInformation(self.space)
        self.errors = []
        self._edge = None  # the lean check (_valid), made on first use
        self._lean = True  # False: Robot.check per callback (bench_planning.py compares)
        self.counts = {"state": [0, 0, 0.0], "motion": [0, 0, 0.0]}
        cls = _classes()
        self.validity_checker = cls["StateValidityChecker"](self)
        self.motion_validator = cls["MotionValidator"](self)
        self.si.setStateValidityChecker(self.validity_checker)
        self.si.setMotionValidator(self.motion_validator)
        self.si.setup()

    # ---- states and joint vectors

    def q(self, state, place="state"):
        """The robot's actuated joint values (robot.joints order) of an OMPL state."""
        _a.state(state, place, _ompl()[0])
        q = self._q.copy()
        for i, j in enumerate(self._index):
            q[j] = state[i]
        return q

    def state(self, q, out=None):
        """An OMPL state (allocated by si unless out is given) of joint values: the planned
        joints' values (len(joints)) or every actuated joint's (len(robot.joints))."""
        q = _a.vector(q, "q")
        out = _a.optional_state(out, "out", _ompl()[0])
        if q.shape == (len(self.robot.joints),) and len(self.joints) != len(self.robot.joints):
            q = q[self._index]
        if q.shape != (len(self.joints),):
            raise InputError(f"q: expected {len(self.joints)} values ({', '.join(self.joints)}), "
                             f"got shape {q.shape}")
        s = self.si.allocState() if out is None else out
        for i, x in enumerate(q):
            s[i] = float(x)
        return s

    def joint_path(self, q0, q1, t):
        """polyccd's joint path between two full joint vectors at times t (joint_path())."""
        return joint_path(self._revolute, q0, q1, t)

    def interpolate(self, s1, s2, t, out=None):
        """The state at time t of polyccd's joint path from s1 to s2 (OMPL's interpolate
        signature; out: a state to fill, else a new one)."""
        return self.state(self.joint_path(self.q(s1, "s1"), self.q(s2, "s2"), _a.time(t)), out)

    # ---- paths

    def waypoints(self, path):
        """The joint vectors (robot.joints order) of an OMPL PathGeometric, or of a list
        of states or joint vectors."""
        ob, og = _ompl()
        states = ([path.getState(i) for i in range(path.getStateCount())]
                  if isinstance(path, og.PathGeometric) else _items(path, "path", "a path or joint vectors"))
        return [self.q(s, f"path[{k}]") if isinstance(s, ob.State) else
                _a.vector(s, f"path[{k}]", len(self.robot.joints)) for k, s in enumerate(states)]

    def interpolate_path(self, path, step=0.01):
        """Joint vectors along polyccd's joint path through the waypoints of path (a
        PathGeometric or joint vectors), each segment cut into ceil(largest joint change /
        step) pieces (both ends included once): the poses a controller executes."""
        step = _a.positive(step, "step")
        w = self.waypoints(path)
        if not w:
            raise InputError("path: expected at least one waypoint")
        out = [w[0]]
        for a, b in zip(w, w[1:]):
            n = max(1, math.ceil(float(np.max(np.abs(b - a))) / step))
            out.extend(self.joint_path(a, b, np.arange(1, n + 1) / n))
        return out

    def check_path(self, path, **options):
        """Robot.check_path over the waypoints of path (a PathGeometric or joint vectors)
        with this space's obstacles and check options (options override them)."""
        return self.robot.check_path(self.waypoints(path), self.obstacles,
                                     **{**self.check_options, **options})

    def simple_setup(self):
        """An ompl.geometric.SimpleSetup on this space's SpaceInformation."""
        _, og = _ompl()
        return og.SimpleSetup(self.si)

    def simplify(self, path, rounds=3):
        """simplify(self.si, path, rounds)."""
        return simplify(self.si, path, rounds)

    # ---- the checks behind the validators

    def _checked(self, q0, q1, options=None):
        """Robot.check of the segment with this space's options; None after an exception
        (kept in self.errors). Counted in self.counts: [checks, colliding, seconds] by kind
        ("state": q0 == q1, else "motion")."""
        count = self.counts["state" if q0 is q1 else "motion"]
        start = time.perf_counter()
        try:
            r = self.robot.check(q0, q1, self.obstacles,
                                 **(self.check_options if options is None else options))
        except Exception as e:  # a check that does not finish never accepts the motion
            self.errors.append(e)
            r = None
        count[0] += 1
        count[1] += r is None or r.collides
        count[2] += time.perf_counter() - start
        return r

    def _valid(self, q0, q1):
        """No contact on q0 -> q1 (an exception: not valid, kept in self.errors), by the
        lean one-call path (_robot_edge.py: Robot.check's C call and answer, without its
        result objects) when every check option is one it takes; counted as _checked."""
        if not self._lean or not KEYWORDS.issuperset(self.check_options):
            r = self._checked(q0, q1)
            return r is not None and not r.collides
        count = self.counts["state" if q0 is q1 else "motion"]
        start = time.perf_counter()
        key = (self.check_options, tuple(map(id, self.obstacles)))  # either may be replaced
        if self._edge is None or self._edge[0][0] is not key[0] or self._edge[0][1] != key[1]:
            self._edge = (key, EdgeCheck(self.robot, self.obstacles, self.check_options))
        try:
            hit = self._edge[1].collides(q0, q1)
        except Exception as e:  # a check that does not finish never accepts the motion
            self.errors.append(e)
            hit = True
        count[0] += 1
        count[1] += hit
        count[2] += time.perf_counter() - start
        return not hit

    def is_valid(self, q):
        return self._valid(q, q)

    def motion_valid(self, q1, q2):
        return self._valid(q1, q2)

    def last_valid(self, q1, q2):
        """(valid, fraction, joint vector or None) of the motion q1 -> q2: fraction and
        joint vector of a last valid state when the motion is invalid (module comment)."""
        options = {k: v for k, v in self.check_options.items() if k != "first_contact"}
        r = self._checked(q1, q2, options)
        if r is None:
            return False, 0.0, q1
        if not r.collides:
            return True, 1.0, None
        lo = Fraction(r.first_contact.lo)
        for k in BACKOFF if lo > 0 else ():
            f = lo * k
            values = self.robot.joint_values(q1, q2, f)
            q = np.where(self._planned, [values[n] for n in self.robot.joints], self._q)
            sub = self._checked(q1, q, options)
            if sub is not None and not sub.collides:
                return False, float(f), q
        return False, 0.0, q1


_CLASSES = None


def _classes():
    """The OMPL subclasses, made once ompl is importable."""
    global _CLASSES
    if _CLASSES is not None:
        return _CLASSES
    ob, _ = _ompl()

    class StateValidityChecker(ob.StateValidityChecker):
        """Valid: the robot standing still at the state touches nothing (exact)."""

        def __init__(self, space):
            super().__init__(_a.space(space, "space", RobotSpace).si)
            self.space = weakref.proxy(space)  # the space owns si, which owns this

        def isValid(self, state):
            return self.space.is_valid(self.space.q(state, "state"))

    class MotionValidator(ob.MotionValidator):
        """Valid: polyccd's exact check of the joint path s1 -> s2 finds no contact."""

        def __init__(self, space):
            super().__init__(_a.space(space, "space", RobotSpace).si)
            self.space = weakref.proxy(space)  # the space owns si, which owns this

        def checkMotion(self, s1, s2, last_valid=None):
            sp = self.space
            q1, q2 = sp.q(s1, "s1"), sp.q(s2, "s2")
            if _a.last_valid(last_valid, "last_valid", ob) is None:
                return sp.motion_valid(q1, q2)
            valid, fraction, q = sp.last_valid(q1, q2)
            if not valid:
                if last_valid[0] is not None:
                    sp.state(q, last_valid[0])
                last_valid[1] = fraction
            return valid

        def checkMotionWithLastValid(self, s1, s2, state):
            last = [_a.optional_state(state, "state", ob), 0.0]
            valid = self.checkMotion(s1, s2, last)
            return valid, last[1]

    _CLASSES = {"StateValidityChecker": StateValidityChecker, "MotionValidator": MotionValidator}
    return _CLASSES


def __getattr__(name):
    """polyccd.ompl.MotionValidator / StateValidityChecker: made (and ompl imported) on
    first use."""
    if name in ("MotionValidator", "StateValidityChecker"):
        return _classes()[name]
    raise AttributeError(f"module 'polyccd.ompl' has no attribute {name!r}")
