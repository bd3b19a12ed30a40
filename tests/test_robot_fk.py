"""Forward kinematics of robots read from URDF (polyccd.robot, pccd_chain_*) on two real
robots of example-robot-data (Franka Panda with its prismatic fingers, UR5):

(a) exactly equal, at 1000 sampled rational times per link, to an independent exact FK
    written here: the URDF parsed again with ElementTree, 4x4 homogeneous matrices of
    Fractions (stored without their constant last row), every
    rotation (joint and origin) from its half-angle quaternion (w, v) through the
    homogeneous Cayley / Rodrigues form R = I + 2 (w [v]x + [v]x^2) / (w^2 + |v|^2),
    not through polyccd's quaternion code; the joint quaternion is (c(t), s(t) a) with
    c, s linear between cos(q/2), sin(q/2) / |a| at the segment's ends (the doubles the
    library documents), origins from the rpy quaternion qz qy qx in doubles;
(b) within 1e-9 of Pinocchio's float FK at the joint angles the library reports for
    those times (the same random body point per link and time) (2 atan2 of the half-angle quaternion), a check of the URDF conventions
    (origins, rpy, axes, the mimic finger) against an implementation of its own.

Skipped when yourdfpy / example-robot-data / pin are not installed (tests/requirements.txt).
POLYCCD_FK_TIMES changes the number of sampled times (default 1000).
"""
import glob
import math
import os
import random
import sys
import sysconfig
import xml.etree.ElementTree as ET
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
from polyccd.robot import load_urdf  # noqa: E402

TIMES = int(os.environ.get("POLYCCD_FK_TIMES", "1000"))
SEED = 20261124


def robots_dir():
    roots = [sysconfig.get_paths()["purelib"], sys.prefix]
    for root in roots:
        hits = glob.glob(os.path.join(root, "**", "share", "example-robot-data", "robots"),
                         recursive=True)
        if hits:
            return hits[0]
    return None


ROBOTS = robots_dir()
URDFS = {"panda": "panda_description/urdf/panda.urdf", "ur5": "ur_description/urdf/ur5_robot.urdf"}
needs_robots = pytest.mark.skipif(ROBOTS is None, reason="example-robot-data is not installed")


# ---------------------------------------------------------------- the independent FK

def cayley(w, v):
    """The rotation of the quaternion (w, v) (Fractions, not both zero), homogeneous
    Cayley form: R = I + 2 (w [v]x + [v]x^2) / (w^2 + |v|^2)."""
    x, y, z = v
    n = w * w + x * x + y * y + z * z
    K = [[0, -z, y], [z, 0, -x], [-y, x, 0]]
    K2 = [[sum(K[i][k] * K[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return [[(1 if i == j else 0) + 2 * (w * K[i][j] + K2[i][j]) / n for j in range(3)]
            for i in range(3)]


def frame(R, p):
    """The rigid transform x -> R x + p as its 3x4 matrix [R | p] (the last row of the 4x4
    homogeneous matrix, (0, 0, 0, 1), left out)."""
    return [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]]]


def matmul(A, B):
    """The 4x4 product of [A; 0 0 0 1] and [B; 0 0 0 1], without its last row."""
    return [[A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j] + (A[i][3] if j == 3 else 0)
             for j in range(4)] for i in range(3)]


def rpy_quat(rpy):
    """qz(yaw) qy(pitch) qx(roll) in doubles, as documented (then exact)."""
    cr, sr = math.cos(rpy[0] / 2), math.sin(rpy[0] / 2)
    cp, sp = math.cos(rpy[1] / 2), math.sin(rpy[1] / 2)
    cy, sy = math.cos(rpy[2] / 2), math.sin(rpy[2] / 2)
    return [F(cy * cp * cr + sy * sp * sr), F(cy * cp * sr - sy * sp * cr),
            F(cy * sp * cr + sy * cp * sr), F(sy * cp * cr - cy * sp * sr)]


def origin_of(el):
    o = el.find("origin")
    if o is None:
        return [0.0] * 3, [0.0] * 3
    return ([float(x) for x in o.get("xyz", "0 0 0").split()],
            [float(x) for x in o.get("rpy", "0 0 0").split()])


class Oracle:
    """The URDF's own tree, its joints and their segment ends."""

    def __init__(self, path):
        root = ET.parse(path).getroot()
        self.joints = {}
        for j in root.findall("joint"):
            xyz, rpy = origin_of(j)
            a = j.find("axis")
            axis = [float(x) for x in (a.get("xyz") if a is not None else "1 0 0").split()]
            m = j.find("mimic")
            mimic = None if m is None else (m.get("joint"), float(m.get("multiplier", "1")),
                                            float(m.get("offset", "0")))
            self.joints[j.find("child").get("link")] = dict(
                name=j.get("name"), type=j.get("type"), parent=j.find("parent").get("link"),
                T=frame(cayley(*self._split(rpy_quat(rpy))), [F(x) for x in xyz]),
                axis=[F(x) for x in axis], norm=math.sqrt(sum(x * x for x in axis)), mimic=mimic)
        self.geometry = {}
        for link in root.findall("link"):
            for i, g in enumerate(link.findall("collision")):
                xyz, rpy = origin_of(g)
                if any(xyz) or any(rpy):
                    self.geometry[f"{link.get('name')}#{i}"] = (
                        link.get("name"), frame(cayley(*self._split(rpy_quat(rpy))), [F(x) for x in xyz]))

    @staticmethod
    def _split(q):
        return q[0], q[1:]

    def values(self, q, names):
        """Joint value of every moving joint by name (mimic joints from their leader)."""
        v = dict(zip(names, (float(x) for x in q)))
        for j in self.joints.values():
            if j["mimic"]:
                leader, mult, off = j["mimic"]
                v[j["name"]] = mult * v[leader] + off
        return v

    def poses(self, v0, v1, t):
        """{link name: exact 4x4 world pose} at time t of the segment v0 -> v1."""
        out = {}

        def pose(link):
            if link in out:
                return out[link]
            j = self.joints.get(link)
            if j is None:
                out[link] = frame(cayley(F(1), [F(0)] * 3), [F(0)] * 3)
                return out[link]
            M = matmul(pose(j["parent"]), j["T"])
            a, n = j["axis"], j["norm"]
            if j["type"] in ("revolute", "continuous"):
                q0, q1 = v0[j["name"]], v1[j["name"]]
                c0, c1 = F(math.cos(q0 / 2)), F(math.cos(q1 / 2))
                s0, s1 = F(math.sin(q0 / 2) / n), F(math.sin(q1 / 2) / n)
                c, s = c0 + (c1 - c0) * t, s0 + (s1 - s0) * t
                M = matmul(M, frame(cayley(c, [s * x for x in a]), [F(0)] * 3))
            elif j["type"] == "prismatic":
                e0, e1 = F(v0[j["name"]] / n), F(v1[j["name"]] / n)
                e = e0 + (e1 - e0) * t
                M = matmul(M, frame(cayley(F(1), [F(0)] * 3), [e * x for x in a]))
            out[link] = M
            return M
        for link in list(self.joints):
            pose(link)
        for name, (link, T) in self.geometry.items():
            out[name] = matmul(pose(link), T)
        return out


def apply(M, p):
    return tuple(sum(M[i][k] * F(p[k]) for k in range(3)) + M[i][3] for i in range(3))


def random_segment(robot, rng):
    """Joint values within the limits, each joint moving by less than 3 (radians or
    length units: a revolute segment must turn by less than 2 pi)."""
    q0, q1 = [], []
    for name in robot.joints:
        lo, hi = robot.limits[name] or (-math.pi, math.pi)
        q0.append(rng.uniform(lo, hi))
        q1.append(min(hi, max(lo, q0[-1] + rng.uniform(-3, 3))))
    return np.array(q0), np.array(q1)


def sample_times(rng, n):
    return [F(0), F(1)] + [F(rng.randint(0, 10 ** 6), 10 ** 6) for _ in range(n - 2)]


def pinocchio_fk(path, mimic):
    """A function (joint values by name) -> {frame name: (R, p)} of floats, or None when
    pin is not installed."""
    try:
        import pinocchio as pin
    except ImportError:
        return None
    model = pin.buildModelFromUrdf(path)
    data = model.createData()

    def fk(values):
        q = pin.neutral(model)
        for jid in range(1, model.njoints):
            jname = model.names[jid]
            if jname in mimic:  # Panda's second finger follows the first
                leader, mult, off = mimic[jname]
                value = mult * values[leader] + off
            else:
                value = values[jname]
            q[model.joints[jid].idx_q] = value
        pin.framesForwardKinematics(model, data, q)
        return lambda link: data.oMf[model.getFrameId(link)]
    return fk


@needs_robots
@pytest.mark.parametrize("name", sorted(URDFS))
def test_fk_exact_and_against_pinocchio(name):
    """Per sampled time and link: polyccd's exact position of a random body point equals
    the independent exact FK's (every link, the geometry frames "<link>#i" included), and
    is within 1e-9 of Pinocchio's at the reported joint angles (URDF links)."""
    path = os.path.join(ROBOTS, URDFS[name])
    robot, oracle = load_urdf(path), Oracle(path)
    mimic = {j["name"]: j["mimic"] for j in oracle.joints.values() if j["mimic"]}
    pin_fk = pinocchio_fk(path, mimic)
    rng = random.Random(SEED + len(name))
    q0, q1 = random_segment(robot, rng)
    motions = dict(zip(robot.links, robot.motions(q0, q1)))
    v0, v1 = oracle.values(q0, robot.joints), oracle.values(q1, robot.joints)
    checked, worst = 0, 0.0
    for t in sample_times(rng, TIMES):
        poses = oracle.poses(v0, v1, t)
        pin_pose = pin_fk(robot.joint_values(q0, q1, t)) if pin_fk else None
        for link, m in motions.items():
            p = [F(rng.randint(-100, 100), 64) for _ in range(3)]
            got = m.position(p, t)
            assert got == apply(poses[link], p), (name, link, list(q0), list(q1), t, p)
            checked += 1
            if pin_pose and "#" not in link:
                M = pin_pose(link)
                want = M.rotation @ np.array([float(x) for x in p]) + M.translation
                worst = max(worst, float(np.max(np.abs(np.array([float(x) for x in got]) - want))))
    assert len(motions) >= 10 and checked == TIMES * len(motions)
    if pin_fk is None:
        pytest.skip("pin (Pinocchio) is not installed: the exact FK was checked, not the convention")
    print(f"{name}: {checked} exact positions, Pinocchio max deviation {worst:.3g}")
    assert worst <= 1e-9, (name, worst)
