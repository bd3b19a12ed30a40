"""Limits inside the motions of kinematic chains (issue 23, item 1): Chain.motions
(pccd_chain_segment_motions_cfg) and the link motions a robot check builds on demand
(pccd_robot_check) run their compositions under the call's work limits and hold every
link's numbers to max_number_bits as soon as the link is built.

A serial chain of n revolute links on random axes and origins has link motions of
degree k whose numbers grow by about 650 bits per link (every origin and joint
quaternion is a double): 60 links take about 10 s of exact products without limits,
and the default input limit (16,384 bits) is passed at about link 25. The bounds are
the issue's: a limit of 1 s ends the call within 2 s, a cancellation within 0.5 s.
"""
import random
import threading
import time
from fractions import Fraction as F

import pytest

import polyccd as P


def long_chain(n, seed=7):
    rng = random.Random(seed)
    c = P.Chain()
    for k in range(n):
        c.add_link(k - 1, "revolute", axis=[rng.uniform(-1, 1) for _ in range(3)],
                   xyz=[rng.uniform(-1, 1) for _ in range(3)],
                   rpy=[rng.uniform(-3, 3) for _ in range(3)])
    q0 = [rng.uniform(-1, 1) for _ in range(n)]
    q1 = [rng.uniform(-1, 1) for _ in range(n)]
    return c, q0, q1


def ends_within(call, seconds, limits):
    start = time.perf_counter()
    with pytest.raises(P.LimitError) as e:
        call(limits)
    took = time.perf_counter() - start
    assert took < seconds, (took, str(e.value))
    return str(e.value)


def test_chain_motions_take_the_work_limits():
    c, q0, q1 = long_chain(60)
    e = ends_within(lambda lim: c.motions(q0, q1, limits=lim), 2.0,
                    P.Limits(max_seconds=1, max_number_bits=None))
    assert e.startswith("config.max_seconds: the time limit of 1 s")
    # A work limit ends it after the same count every time (the count is the input's).
    messages = {ends_within(lambda lim: c.motions(q0, q1, limits=lim), 30,
                            P.Limits(max_work=500, max_number_bits=None)).split(" and ")[0]
                for _ in range(2)}
    assert messages == {"config.max_work: the limit of 500 "
                        "work steps was reached (after 500 work steps"}
    cancel = P.Cancel()
    timer = threading.Timer(0.5, cancel.set)
    timer.start()
    try:
        ends_within(lambda lim: c.motions(q0, q1, limits=lim), 1.0,
                    P.Limits(cancel=cancel, max_number_bits=None))
    finally:
        timer.cancel()


def test_chain_motions_hold_the_links_numbers():
    c, q0, q1 = long_chain(60)
    # The default input limit stops at the first link beyond it, named with its number,
    # long before the 60 links are composed.
    e = ends_within(lambda lim: c.motions(q0, q1, limits=lim), 5.0, P.Limits())
    assert e.startswith("motions[")
    k = int(e.split("motions[")[1].split("]")[0])
    assert 10 < k < 40, e
    bits = int(e.split("a number of ")[1].split(" bits")[0])
    assert 16384 < bits < 16384 + 4096, e
    # The link before it is within the limit: the first k links alone pass, and their
    # motions are those of the call without limits, exactly (positions at random times).
    short, p0, p1 = long_chain(60)
    first = P.Chain()
    for link in short._links[:k]:
        first.add_link(link[0], link[1], axis=link[2], xyz=link[3], rpy=link[4])
    held = first.motions(p0[:k], p1[:k], limits=P.Limits())
    free = first.motions(p0[:k], p1[:k])
    rng = random.Random(3)
    for j in (0, k // 2, k - 1):
        t = F(rng.randrange(1, 1000), 1000)
        assert held[j].position([1, 2, 3], t) == free[j].position([1, 2, 3], t)
    # A limit above the largest number lets the whole chain through (a smaller one first).
    small, s0, s1 = long_chain(8)
    assert len(small.motions(s0, s1, limits=P.Limits(max_number_bits=100000))) == 8
    with pytest.raises(P.LimitError, match=r"^motions\[0\]\."
                       r"\w+\[\d\]\[\d\]: a number of \d+ bits .* exceeds config.max_number_bits = 64"):
        small.motions(s0, s1, limits=P.Limits(max_number_bits=64))


URDF_LINK = """  <link name="l{k}"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
"""
URDF_JOINT = """  <joint name="j{k}" type="revolute"><parent link="l{p}"/><child link="l{k}"/>
    <origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="{axis}"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
"""


def long_robot(tmp_path, n, seed=11):
    """A serial arm of n revolute joints with random origins and axes, a ball per link."""
    pytest.importorskip("yourdfpy")
    from polyccd.robot import load_urdf
    rng = random.Random(seed)
    vec = lambda a: " ".join(repr(rng.uniform(-a, a)) for _ in range(3))  # noqa: E731
    parts = ['<?xml version="1.0"?>\n<robot name="long">\n', URDF_LINK.format(k=0)]
    for k in range(1, n + 1):
        parts.append(URDF_LINK.format(k=k))
        parts.append(URDF_JOINT.format(k=k, p=k - 1, xyz=vec(0.3), rpy=vec(3), axis=vec(1)))
    parts.append("</robot>\n")
    path = tmp_path / "long.urdf"
    path.write_text("".join(parts))
    return load_urdf(str(path))


def test_robot_link_motions_take_the_limits(tmp_path):
    robot = long_robot(tmp_path, 60)
    q0, q1 = [0.1] * 60, [0.3] * 60
    # An obstacle ball around the last link's ball at t = 0: the filter cannot clear
    # that pair, so the check builds the exact motions of every link down to it.
    end = robot.motions(q0, q1)[robot.link_index["l60"]].position([0, 0, 0], 0)
    ball = P.Body(P.Spheres([[float(x) for x in end]], [0.2]), name="ball")
    check = lambda lim: robot.check(q0, q1, [ball], self_collision=False, limits=lim)  # noqa: E731
    e = ends_within(check, 5.0, P.Limits())
    assert e.startswith("links["), e
    assert ".motion." in e and "exceeds config.max_number_bits = 16384" in e
    e = ends_within(check, 2.0, P.Limits(max_seconds=1, max_number_bits=None))
    assert "config.max_seconds: the time limit of 1 s" in e
    # With the limit of the numbers raised past them, a shorter arm answers as without
    # the filter (every pair exactly): its last ball reaches the obstacle's centre at
    # t = 1/2, so the first contact is at or before 1/2.
    short = long_robot(tmp_path, 8)
    q0, q1 = [0.1] * 8, [0.3] * 8
    mid = short.motions(q0, q1)[short.link_index["l8"]].position([0, 0, 0], F(1, 2))
    ball = P.Body(P.Spheres([[float(x) for x in mid]], [0.01]), name="ball")
    got = short.check(q0, q1, [ball], self_collision=False, limits=P.Limits(max_number_bits=None))
    ref = short.check(q0, q1, [ball], self_collision=False, filter=False)
    assert got.collides and got.first_contact.hi <= F(1, 2)
    assert got.first_contact == ref.first_contact


def test_robot_checks_that_clear_at_once_still_end(tmp_path):
    """A robot state or segment whose body pairs all clear at once (their boxes far
    apart, or a state's one instant) does no traversal: it must still end on a Cancel
    set before the call, on a spent work budget, and on an expired deadline, as every
    call does (regression: a state check with a set Cancel answered instead)."""
    robot = long_robot(tmp_path, 3)
    far = P.Body(P.Spheres([[100.0, 100.0, 100.0]], [0.5]), name="far")
    cancel = P.Cancel()
    cancel.set()
    for q0, q1 in (([0.1] * 3, [0.1] * 3), ([0.1] * 3, [0.3] * 3)):
        for first in (False, True):
            ok = robot.check(q0, q1, [far], first_contact=first)
            assert not ok.collides
            for lim in (P.Limits(cancel=cancel), P.Limits(max_work=1)):
                with pytest.raises(P.LimitError):
                    robot.check(q0, q1, [far], first_contact=first, limits=lim)
            with pytest.raises(P.LimitError):
                robot.check_states([q0, q1], [far], limits=P.Limits(cancel=cancel))
