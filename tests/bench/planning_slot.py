"""The narrow passage of bench_planning.py: a slot for the Panda's hand, two upright 2 mm
plates with CLEARANCE (8 mm) on either side of the hand's and fingers' exact extent at a
goal pose along one horizontal axis, so the hand goes down into it with 16 mm of play in
all (a passage narrower than 2 cm). The plates span the hand's extent along the other
horizontal axis grown by MARGIN, and from MARGIN below the hand up to the hand's top
(the wrist above stays free); the goal is a variation of examples/ompl_panda.py's GOAL
whose pose is free with the slot (decided exactly by polyccd). A helper module."""
import importlib
import random

import numpy as np

CLEARANCE = 0.008  # m, above and below the hand: 2 x 8 mm < 2 cm
THICK = 0.002
MARGIN = 0.03
HAND = ("panda_hand", "panda_leftfinger", "panda_rightfinger")


def hand_box(robot, q):
    """(lo, hi): the exact extent of the hand and fingers at pose q, as floats."""
    motions = robot.motions(q, q)
    pts = []
    for link, _, k, shape in robot.shapes:
        if link in HAND:
            pts.extend([float(x) for x in motions[k].position(v, 0)] for v in shape.vertices)
    pts = np.array(pts)
    return pts.min(axis=0), pts.max(axis=0)


def slot(robot, plates, rng, make_plate, base_goal, finger, tries=40):
    """(goal, [(name, lo, hi)] of the two plates, their Bodies) for the first variation of
    base_goal (joints moved by up to 0.3 rad, seeded) that is free with the slot."""
    while tries > 0:
        goal = np.append(np.array(base_goal) + [rng.uniform(-0.3, 0.3) for _ in base_goal], finger)
        lo, hi = hand_box(robot, goal)
        a = tries % 2  # the axis across the slot: x or y, alternately
        b = 1 - a
        boxes = []
        for name, side in (("slot_left", -1), ("slot_right", 1)):
            p_lo, p_hi = [0.0] * 3, [0.0] * 3
            inner = lo[a] - CLEARANCE if side < 0 else hi[a] + CLEARANCE
            p_lo[a], p_hi[a] = (inner - THICK, inner) if side < 0 else (inner, inner + THICK)
            p_lo[b], p_hi[b] = lo[b] - MARGIN, hi[b] + MARGIN
            p_lo[2], p_hi[2] = lo[2] - MARGIN, hi[2]
            boxes.append((name, tuple(p_lo), tuple(p_hi)))
        tries -= 1
        bodies = [make_plate(a, b, name) for name, a, b in boxes]
        if not robot.check(goal, goal, plates + bodies, self_collision=False,
                           first_contact=False, joint_limits="ignore").collides:
            return goal, boxes, bodies
    raise SystemExit("planning_slot: no free slot goal found")


def problem(seed, with_slot):
    """The planning benches' problem (bench_planning.py, bench_planning_cpp.py): the
    example's Panda and plates (examples/ompl_panda.py, importable as ompl_panda), its
    wall and shelf as (name, lo, hi) boxes and, with_slot, the slot at a goal seeded by
    seed. Returns (robot, plates, boxes, slot_goal or None, the slot's (name, lo, hi))."""
    import ompl_panda as ex
    robot, plates = ex.scene()
    boxes = [("wall",) + ex.WALL, ("shelf",) + ex.SHELF]
    if not with_slot:
        return robot, plates, boxes, None, []
    goal, more, bodies = slot(robot, plates, random.Random(seed), ex.plate, ex.GOAL, ex.FINGER)
    return robot, plates + bodies, boxes + more, goal, more


def ompl_ready(bench, seed, modules=()):
    """Whether the planning benchmarks' optional modules and OMPL import; OMPL then logs
    errors only and draws from seed. When one is missing: False, after printing
    "<bench>: skipped (<module> is not installed)"."""
    try:
        for name in modules:
            importlib.import_module(name)
        from ompl import util as ou
    except ImportError as e:
        print(f"{bench}: skipped ({e.name} is not installed)")
        return False
    ou.setLogLevel(ou.LogLevel.LOG_ERROR)
    ou.RNG.setSeed(seed)
    return True
