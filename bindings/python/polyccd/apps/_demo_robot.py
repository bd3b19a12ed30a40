"""The robot demo: a Franka Panda (example-robot-data's URDF and collision meshes, read
by polyccd.robot) sweeps its joints over one joint-space segment past a 2 mm plate
standing upright below its gripper. The fingertips clip the plate's top edge between
two of the 10 poses a discrete check samples: every sampled pose is collision-free
(each decided exactly by polyccd, as a stationary robot), while the exact check of the
whole segment finds the first contact, its links and features and the joint values.

Needs yourdfpy and example-robot-data (tests/requirements.txt, pyproject's `demo`
extra); without them robot_demo() returns None and the demo says it skipped this part.
"""
import glob
import os
import sys
import sysconfig
import time
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import numpy as np

PANDA_URDF = "panda_description/urdf/panda.urdf"  # under example-robot-data's robots/

# The segment (panda_joint1..7 in rad, panda_finger_joint1 in m). Joint 1 (the base yaw)
# turns from -0.6 to 0.6 while joints 2, 4 and 6 move a little; joint 7 at -0.785 puts
# both fingers in the arm's vertical plane (one behind the other along the reach), so
# both cross the plate's plane near yaw 0, half-way between the samples t = 4/9 and 5/9
# (the fingertips then sweep about 6 cm of arc between two samples).
Q0 = (-0.6, -0.5, 0.0, -2.2, 0.0, 1.9, -0.785, 0.02)
Q1 = (0.6, -0.3, 0.0, -2.0, 0.0, 2.0, -0.785, 0.02)

# The plate: 2 mm thick (y in [-0.001, 0.001], the plane the gripper crosses at yaw 0),
# 22 cm along the reach (x), from z = 0.30 to its top edge at z = 0.51. Read from the
# float poses of the segment at t = 1/2: the fingertips reach down to z = 0.495, the hand
# above them stays above z = 0.539, so only the fingers meet the top 15 mm of the plate.
PLATE_LO = ("0.38", "-0.001", "0.30")
PLATE_HI = ("0.6", "0.001", "0.51")
SAMPLES = 10  # the discrete check's poses: t = k / 9, k = 0..9 (both ends included)

BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def example_robot_file(relative):
    """The file `relative` under example-robot-data's robots/ folder (the PyPI package
    installs it under <prefix>/.../share/example-robot-data/robots), or None."""
    for root in (sysconfig.get_paths()["purelib"], sys.prefix):
        for hit in glob.glob(os.path.join(root, "**", "share", "example-robot-data", "robots"),
                             recursive=True):
            path = os.path.join(hit, relative)
            if os.path.isfile(path):
                return path
    return None


def missing_packages():
    """The packages the robot demo needs that are not importable / installed."""
    missing = []
    try:
        import yourdfpy  # noqa: F401
    except ImportError:
        missing.append("yourdfpy")
    if example_robot_file(PANDA_URDF) is None:
        missing.append("example-robot-data")
    return missing


def plate_body():
    """The plate as a polyccd Body: the box [PLATE_LO, PLATE_HI] (exact decimals), 12
    triangles, stationary; its vertices also kept in float for drawing."""
    import polyccd
    lo = [Fraction(x) for x in PLATE_LO]
    hi = [Fraction(x) for x in PLATE_HI]
    corners = [[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)]
    mesh = polyccd.Mesh([[str(x) for x in c] for c in corners], BOX_TRIANGLES)
    return polyccd.Body(mesh, name="plate"), np.array(corners, dtype=np.float64)


@dataclass
class SampledPose:
    t: Fraction
    q: tuple          # the joint values at t (doubles: the segment's values, rounded)
    collides: bool    # the exact check of the robot standing still at q


@dataclass
class RobotDemo:
    robot: object
    plate: object
    plate_vertices: object
    result: object    # RobotResult of the segment Q0 -> Q1
    samples: list     # SampledPose, t = k / (SAMPLES - 1)
    seconds: float    # wall time of the exact segment check
    between: SampledPose  # the pose at t = 1/2, between the samples 4/9 and 5/9


def pose_collides(robot, q, obstacles):
    """The exact check of the robot standing still at the joint values q (a segment
    q -> q: every link on a constant pose) against the obstacles."""
    return robot.check(q, q, obstacles, self_collision=False).collides


def sampled_poses(robot, q0, q1, obstacles, n=SAMPLES):
    """The n poses t = k / (n - 1) of the segment q0 -> q1, each checked exactly."""
    out = []
    for k in range(n):
        t = Fraction(k, n - 1)
        values = robot.joint_values(q0, q1, t)
        q = tuple(values[name] for name in robot.joints)
        out.append(SampledPose(t, q, pose_collides(robot, np.array(q), obstacles)))
    return out


def robot_demo():
    """Loads the Panda, checks the segment Q0 -> Q1 against the plate exactly (robot vs
    plate; self-collision is not part of this scene) and the 10 sampled poses; None
    when yourdfpy or example-robot-data is missing."""
    if missing_packages():
        return None
    from ..robot import load_urdf
    robot = load_urdf(example_robot_file(PANDA_URDF))
    plate, plate_vertices = plate_body()
    q0, q1 = np.array(Q0), np.array(Q1)
    start = time.perf_counter()
    result = robot.check(q0, q1, [plate], self_collision=False)
    seconds = time.perf_counter() - start
    samples = sampled_poses(robot, q0, q1, [plate])
    half = robot.joint_values(q0, q1, Fraction(1, 2))
    q = tuple(half[name] for name in robot.joints)
    between = SampledPose(Fraction(1, 2), q, pose_collides(robot, np.array(q), [plate]))
    return RobotDemo(robot, plate, plate_vertices, result, samples, seconds, between)


def _joints_text(values):
    return ", ".join(f"{name.replace('panda_', '')} {v:.6f}" for name, v in values.items())


def run_robot_demo(out_dir="build/demo", *, out=print):
    """Prints the robot demo and writes out_dir/scene_robot.png at the first contact;
    returns (RobotDemo or None when skipped, png path or None, ok)."""
    from ._demo_bodies import time_text
    from ._render import render_scene
    out("== robot")
    missing = missing_packages()
    if missing:
        out(f"robot demo skipped: {', '.join(missing)} not installed "
            f"(pip install {' '.join(missing)})")
        return None, None, True
    demo = robot_demo()
    r = demo.result
    out(f"robot: {demo.robot.name} (example-robot-data), {len(demo.robot.shapes)} collision "
        f"meshes; a 2 mm plate [{', '.join(PLATE_LO)}] - [{', '.join(PLATE_HI)}] below the "
        "gripper's path.")
    out(f"segment q0 -> q1 (joint 1 turns -0.6 -> 0.6 rad; joints 2, 4, 6 move):\n"
        f"  q0 = {list(Q0)}\n  q1 = {list(Q1)}")
    out(f"exact check of the segment ({demo.seconds:.3f} s): collides: {r.collides}")
    free = [s for s in demo.samples if not s.collides]
    if r.collides:
        out(f"first contact: {time_text(r.first_contact)}")
        for c in r.contacts:
            out(f"  touching: {c.a[0]} {c.a[1]} {c.a[2]}  <->  {c.b[0]} {c.b[1]} {c.b[2]}")
        lo, hi = r.joint_values
        out(f"joint values at the first contact (t = lo .. hi of its enclosure):\n"
            f"  lo: {_joints_text(lo)}\n  hi: {_joints_text(hi)}")
    out(f"{SAMPLES}-sample discrete check (poses t = k/{SAMPLES - 1}, each decided exactly "
        "as a stationary robot):")
    for s in demo.samples:
        out(f"  t = {str(s.t):>3}: {'COLLIDES' if s.collides else 'free'}")
    out(f"  -> {len(free)} of {SAMPLES} sampled poses free: the discrete check "
        f"{'MISSES the contact' if len(free) == SAMPLES and r.collides else 'sees a collision'}")
    out(f"  (the pose at t = 1/2, between the samples 4/9 and 5/9, checked the same way: "
        f"{'COLLIDES' if demo.between.collides else 'free'})")
    ok = r.collides and len(free) == SAMPLES
    png = None
    if r.collides:
        bodies, _ = demo.robot.bodies(np.array(Q0), np.array(Q1))
        bodies.append(demo.plate)
        geometry = {len(bodies) - 1: {"vertices": demo.plate_vertices,
                                      "triangles": BOX_TRIANGLES}}
        title = f"Panda vs a 2 mm plate: first contact, {time_text(r.first_contact)}"
        png = render_scene(bodies, r.first_contact, r.scene, Path(out_dir) / "scene_robot.png",
                           title=title, geometry=geometry)
        out(f"picture: {png}")
    out("OK" if ok else "MISMATCH: expected a contact that all 10 sampled poses miss")
    return demo, png, ok
