"""The planner side of tests/bench/bench_robot.py: python-fcl's discrete check of a
robot (Pinocchio's float FK, OBBRSS models of the same triangles polyccd gets) at poses
along polyccd's own joint path, with self-collision when asked (the same skipped pairs
as polyccd), and the benchmark's obstacles. A helper module, not a benchmark.
"""
import math
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np

BOX_TRIANGLES = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
FINGER = 0.02


def box_vertices(lo, hi):
    return np.array([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)])


def make_obstacles(rng, boxes, plates):
    """[(name, lo, hi)]: axis-aligned boxes and 2 mm plates near the arm (doubles)."""
    out = []
    for i in range(boxes + plates):
        angle, radius = rng.uniform(-math.pi, math.pi), rng.uniform(0.3, 0.75)
        c = [radius * math.cos(angle), radius * math.sin(angle), rng.uniform(0.1, 0.8)]
        if i < boxes:
            size, name = [rng.uniform(0.05, 0.2) for _ in range(3)], f"box{i}"
        else:
            size, name = [rng.uniform(0.1, 0.3) for _ in range(3)], f"plate{i - boxes}"
            size[rng.randrange(3)] = 0.002
        out.append((name, [c[a] - size[a] / 2 for a in range(3)],
                    [c[a] + size[a] / 2 for a in range(3)]))
    return out


def rpy_matrix(rpy):
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                              math.cos(y), math.sin(y))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


class Discrete:
    """The planner side: float joint interpolation, Pinocchio FK, python-fcl collision
    (robot versus obstacles through two managers, then the robot's own shape pairs)."""

    def __init__(self, robot, urdf, obstacles, allowed=None):
        """allowed: None (robot versus obstacles only) or the link pairs (frozensets of
        URDF link names) the self-collision check skips, as polyccd's Robot.check does
        (and a link's own geometries)."""
        import fcl
        import pinocchio as pin
        self.fcl, self.pin = fcl, pin
        self.model = pin.buildModelFromUrdf(urdf)
        self.data = self.model.createData()
        self.robot = robot
        links = ET.parse(urdf).getroot()
        origins = {}
        for link in links.findall("link"):
            for i, c in enumerate(link.findall("collision")):
                o = c.find("origin")
                get = o.get if o is not None else (lambda key, default: default)
                xyz = [float(x) for x in get("xyz", "0 0 0").split()]
                rpy = [float(x) for x in get("rpy", "0 0 0").split()]
                origins[(link.get("name"), i)] = (rpy_matrix(rpy), np.array(xyz))
        self.shapes = []  # (frame id, offset R, offset p, CollisionObject)
        for link, i, k, shape in robot.shapes:
            R, p = (origins[(link, i)] if k != robot.link_index[link]
                    else (np.eye(3), np.zeros(3)))
            obj = fcl.CollisionObject(self._bvh(shape.vertices, shape.triangles), fcl.Transform())
            self.shapes.append((self.model.getFrameId(link), R, p, obj))
        # Self-collision: every pair of shapes of different links whose link pair is not
        # allowed, each tested by fcl.collide (python-fcl's manager callbacks receive new
        # wrapper objects, so a broad-phase callback could not tell the links apart).
        self.allowed = allowed
        self.request = fcl.CollisionRequest()
        links = [link for link, *_ in robot.shapes]
        self.self_pairs = [] if allowed is None else [
            (self.shapes[i][3], self.shapes[j][3]) for i in range(len(links))
            for j in range(i + 1, len(links))
            if links[i] != links[j] and frozenset((links[i], links[j])) not in allowed]
        self.manager = fcl.DynamicAABBTreeCollisionManager()
        self.manager.registerObjects([s[3] for s in self.shapes])
        self.manager.setup()
        self.obstacles = fcl.DynamicAABBTreeCollisionManager()
        self.obstacles.registerObjects([
            fcl.CollisionObject(self._bvh(box_vertices(lo, hi), BOX_TRIANGLES), fcl.Transform())
            for _, lo, hi in obstacles])
        self.obstacles.setup()
        self.revolute = np.array([robot.joint_types[n] != "prismatic" for n in robot.joints])
        self.q_index = {}
        for jid in range(1, self.model.njoints):
            self.q_index[self.model.names[jid]] = self.model.joints[jid].idx_q

    def _bvh(self, vertices, triangles):
        m = self.fcl.BVHModel()
        m.beginModel(len(vertices), len(triangles))
        m.addSubModel(np.asarray(vertices, dtype=np.float64), np.asarray(triangles, dtype=np.int32))
        m.endModel()
        return m

    def joint_values(self, q0, q1, t):
        """The joint values at t of polyccd's path (see the module comment), floats."""
        h0, h1 = q0 / 2, q1 / 2
        C0, S0 = np.cos(h0), np.sin(h0)
        C = (1 - t) * C0 + t * np.cos(h1)
        S = (1 - t) * S0 + t * np.sin(h1)
        revolute = q0 + 2 * np.arctan2(C0 * S - S0 * C, C0 * C + S0 * S)
        return np.where(self.revolute, revolute, (1 - t) * q0 + t * q1)

    def poses(self, q):
        """[(R, p)] of every robot shape at the joint values q (Pinocchio, floats)."""
        pin = self.pin
        x = pin.neutral(self.model)
        values = dict(zip(self.robot.joints, q))
        for name, idx in self.q_index.items():
            if name in self.robot.mimic_joints:
                leader, mult, off = self.robot.mimic_joints[name]
                x[idx] = mult * values[leader] + off
            else:
                x[idx] = values[name]
        pin.framesForwardKinematics(self.model, self.data, x)
        out = []
        for fid, R, p, _ in self.shapes:
            f = self.data.oMf[fid]
            out.append((f.rotation @ R, f.rotation @ p + f.translation))
        return out

    def pose_collides(self, q):
        fcl = self.fcl
        for (R, p), (_, _, _, obj) in zip(self.poses(q), self.shapes):
            obj.setTransform(fcl.Transform(R, p))
        self.manager.update()
        data = fcl.CollisionData(request=fcl.CollisionRequest())
        self.manager.collide(self.obstacles, data, fcl.defaultCollisionCallback)
        if data.result.is_collision or self.allowed is None:
            return data.result.is_collision
        for o1, o2 in self.self_pairs:  # the shape pairs polyccd checks too
            if fcl.collide(o1, o2, self.request, fcl.CollisionResult()) > 0:
                return True
        return False

    def check(self, q0, q1, resolution):
        """(first colliding sample time or None, poses checked)."""
        m = max(1, math.ceil(float(np.max(np.abs(q1 - q0)[self.revolute])) / resolution))
        for k in range(m + 1):
            t = Fraction(k, m)
            if self.pose_collides(self.joint_values(q0, q1, k / m)):
                return t, k + 1
        return None, m + 1


def agreement(robot, discrete, rng, lims):
    """Largest differences (joint values; link positions in m) between the discrete
    side's floats and polyccd's exact path, at a few random segments and times."""
    from polyccd.apps._render import _float_pose
    dq = dx = 0.0
    for _ in range(3):
        q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
        q1 = np.array([min(hi, max(lo, x + rng.uniform(-1, 1))) for x, (lo, hi) in zip(q0, lims)])
        motions = robot.motions(q0, q1)
        for t in (Fraction(1, 3), Fraction(5, 7)):
            v = robot.joint_values(q0, q1, t)
            q = discrete.joint_values(q0, q1, float(t))
            dq = max(dq, max(abs(v[n] - q[j]) for j, n in enumerate(robot.joints)))
            for (R, p), (_, _, k, shape) in zip(discrete.poses(q), robot.shapes):
                Re, pe = _float_pose(motions[k], t)
                w = shape.vertices[:1]
                dx = max(dx, float(np.abs(w @ R.T + p - (w @ Re.T + pe)).max()))
    return dq, dx
