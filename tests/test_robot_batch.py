"""Robot batches (Robot.check_many, Robot.check_states; pccd_robot_check_many, _states):
every entry equals the one-segment Robot.check on random segments of the Panda and the
UR5 (self-collision on and off, decide and first-contact mode, one and two threads);
a bad segment (NaN, a row of the wrong length, a value outside the joint limits) gets
its error with its index and the others their answers; the work limits and Cancel end
the whole batch; the C call without a status array fails at the first bad segment.
"""
import math
import os
import random

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd._pccd import ffi, lib  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot import SEED  # noqa: E402
from test_robot_fk import ROBOTS, needs_robots  # noqa: E402

ARMS = {"panda": ("panda_description/urdf/panda.urdf", "panda_description/srdf/panda.srdf"),
        "ur5": ("ur_description/urdf/ur5_robot.urdf", "ur_description/srdf/ur5.srdf")}
# 12 segments per arm and setting: about 1 s each on the Panda (2026-11-28, load 5).
N = int(os.environ.get("POLYCCD_ROBOT_BATCH_SEGMENTS", "12"))


def arm(name):
    urdf, srdf = (os.path.join(ROBOTS, f) for f in ARMS[name])
    return load_urdf(urdf, srdf=srdf)


def boxes(rng):
    """Three boxes and a 2 mm plate around the base, in the arms' reach."""
    out = []
    for k in range(4):
        a, r = rng.uniform(-math.pi, math.pi), rng.uniform(0.3, 0.6)
        c = [r * math.cos(a), r * math.sin(a), rng.uniform(0.1, 0.7)]
        size = [rng.uniform(0.05, 0.2) for _ in range(3)]
        if k == 3:
            size[rng.randrange(3)] = 0.002
        out.append(P.Body(P.Mesh.box(size), P.Motion.linear(c, c), name=f"box{k}"))
    return out


def segments(robot, rng, n, span=0.6):
    lims = [robot.limits[j] or (-math.pi, math.pi) for j in robot.joints]
    q0 = np.array([[rng.uniform(lo, hi) for lo, hi in lims] for _ in range(n)])
    step = np.array([[rng.uniform(-span, span) for _ in lims] for _ in range(n)])
    return q0, np.clip(q0 + step, [lo for lo, _ in lims], [hi for _, hi in lims])


def outward(x, toward):
    """The double nearest the Fraction x, stepped toward -inf or +inf when on the wrong side."""
    d = float(x)
    return math.nextafter(d, toward) if (d > x if toward < 0 else d < x) else d


def bounds(r):
    """(lo, hi) of a RobotResult's contact time rounded outward, as the batch writes it."""
    return outward(r.first_contact.lo, -math.inf), outward(r.first_contact.hi, math.inf)


def assert_entry(batch, k, one):
    assert batch.ok[k] and k not in batch.errors
    assert bool(batch.collides[k]) == one.collides, k
    if one.collides:
        assert (batch.lo[k], batch.hi[k]) == bounds(one), k
    else:
        assert math.isnan(batch.lo[k]) and math.isnan(batch.hi[k])
    assert batch.free_until[k] <= one.free_until, k
    assert one.free_until - batch.free_until[k] < 1e-15 * max(1, one.free_until)


@needs_robots
@pytest.mark.parametrize("name", ["panda", "ur5"])
def test_batch_equals_one_by_one(name):
    robot = arm(name)
    rng = random.Random(SEED + len(name))
    obstacles = boxes(rng)
    q0, q1 = segments(robot, rng, N)
    seen = set()
    for self_collision in (False, True):
        for first_contact in (False, True):
            for threads in (1, 2):
                batch = robot.check_many(q0, q1, obstacles, self_collision=self_collision,
                                         first_contact=first_contact, threads=threads)
                assert len(batch) == N and batch.results is None and not batch.errors
                for k in range(N):
                    one = robot.check(q0[k], q1[k], obstacles, self_collision=self_collision,
                                      first_contact=first_contact)
                    assert_entry(batch, k, one)
                    seen.add(one.collides)
    assert seen == {False, True}  # the segments exercise both answers


@needs_robots
def test_states_equal_zero_length_segments():
    robot = arm("panda")
    rng = random.Random(SEED)
    obstacles = boxes(rng)
    q, _ = segments(robot, rng, N)
    batch = robot.check_states(q, obstacles, results=True)
    for k in range(N):
        one = robot.check(q[k], q[k], obstacles, first_contact=False)
        assert_entry(batch, k, one)
        assert batch.results[k].collides == one.collides


@needs_robots
def test_results_on_request_equal_check():
    robot = arm("ur5")
    rng = random.Random(SEED + 1)
    obstacles = boxes(rng)
    q0, q1 = segments(robot, rng, 6)
    batch = robot.check_many(q0, q1, obstacles, first_contact=True, results=True)
    for k in range(6):
        one = robot.check(q0[k], q1[k], obstacles)
        got = batch.results[k]
        assert (got.collides, got.first_contact, got.contacts, got.free_until) == \
            (one.collides, one.first_contact, one.contacts, one.free_until)


@needs_robots
def test_bad_segments_keep_their_index_and_the_rest():
    robot = arm("panda")
    rng = random.Random(SEED + 2)
    obstacles = boxes(rng)
    q0, q1 = segments(robot, rng, 6)
    rows0, rows1 = [list(r) for r in q0], [list(r) for r in q1]
    rows0[1][2] = float("nan")                      # a NaN: the chain's check, in C
    rows1[3] = rows1[3][:-1]                        # a row of the wrong length
    rows0[4][0] = robot.limits[robot.joints[0]][1] + 0.5  # outside the joint limits
    batch = robot.check_many(rows0, rows1, obstacles)
    assert sorted(batch.errors) == [1, 3, 4] and list(batch.ok) == [True, False, True, False, False, True]
    for k, text in ((1, "segments[1]: q0[2] (panda_joint3): NaN"), (3, "segments[3]: q1: expected 8"),
                    (4, "segments[4]: q0[0] (panda_joint1):")):
        assert isinstance(batch.errors[k], P.InputError) and str(batch.errors[k]).startswith(text), batch.errors[k]
        assert not batch.collides[k] and math.isnan(batch.lo[k]) and math.isnan(batch.free_until[k])
    for k in (0, 2, 5):
        assert_entry(batch, k, robot.check(q0[k], q1[k], obstacles, first_contact=False))
    with pytest.raises(P.InputError, match=r"^segments\[1\]: q0\[2\]"):
        batch.raise_first()
    ignored = robot.check_many(rows0[4:], rows1[4:], obstacles, joint_limits="ignore")
    assert ignored.ok.all()
    states = robot.check_states(rows0, obstacles)
    assert sorted(states.errors) == [1, 4] and str(states.errors[1]).startswith("states[1]: q0[2]")


def test_whole_call_errors_raise():
    robot = arm("panda") if ROBOTS else pytest.skip("example-robot-data is not installed")
    q = np.zeros((2, len(robot.joints)))
    with pytest.raises(P.InputError, match=r"^Q0, Q1: 2 and 1 joint vectors"):
        robot.check_many(q, q[:1])
    with pytest.raises(P.InputError, match=r"^obstacles\[0\]"):
        robot.check_many(q, q, [3])
    with pytest.raises(P.InputError, match=r"^Q0"):
        robot.check_many(np.zeros((2, 2, 2)), q)
    assert len(robot.check_many(np.zeros((0, len(robot.joints))), [])) == 0


@needs_robots
def test_limits_and_cancel_end_the_batch():
    robot = arm("panda")
    rng = random.Random(SEED + 3)
    obstacles = boxes(rng)
    q0, q1 = segments(robot, rng, 8)
    with pytest.raises(P.LimitError, match="config.max_work"):
        robot.check_many(q0, q1, obstacles, self_collision=True, limits=P.Limits(max_work=1))
    with pytest.raises(P.LimitError, match="config.max_work"):
        robot.check_states(q0, obstacles, limits=P.Limits(max_work=1))
    cancel = P.Cancel()
    cancel.set()
    for threads in (1, 2):
        with pytest.raises(P.LimitError, match="config.cancel"):
            robot.check_many(q0, q1, obstacles, threads=threads, limits=P.Limits(cancel=cancel))
    cancel.reset()
    assert len(robot.check_many(q0, q1, obstacles, limits=P.Limits(cancel=cancel))) == 8


@needs_robots
def test_c_call_without_status_fails_at_the_first_bad_segment():
    from polyccd._robot_check import _handle, _set_allowed
    robot = arm("ur5")
    made = _handle(robot)
    _set_allowed(robot, made, None)
    n = len(robot.chain)
    q = np.zeros((4, n))
    j1, j0 = (robot._joint_link[robot.joints[i]] for i in (1, 0))
    q[2, j1] = q[3, j0] = np.inf
    collides = np.full(4, 7, dtype=np.uint8)
    out = ffi.new("pccd_robot_batch_out *")
    out.struct_size = ffi.sizeof("pccd_robot_batch_out")
    out.collides = ffi.from_buffer("unsigned char[]", collides)
    rc = lib.pccd_robot_check_many(made[0], ffi.from_buffer("double[]", q), ffi.from_buffer("double[]", q),
                                   4, n, ffi.NULL, ffi.NULL, 0, ffi.NULL, ffi.NULL, ffi.NULL, out)
    assert rc == lib.PCCD_EINVAL
    assert ffi.string(lib.pccd_last_error()).decode().startswith("pccd_robot_check_many: segments[2]: q0[")
    assert list(collides[:2]) == [0, 0]  # answered (the UR5 at zero touches nothing)
    out.struct_size = 1
    rc = lib.pccd_robot_check_states(made[0], ffi.from_buffer("double[]", q), 4, n, ffi.NULL,
                                     ffi.NULL, 0, ffi.NULL, ffi.NULL, ffi.NULL, out)
    assert rc == lib.PCCD_EINVAL and b"out.struct_size" in ffi.string(lib.pccd_last_error())
