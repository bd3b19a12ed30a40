"""Robots (polyccd.robot): checks of a real arm among obstacles and against itself, paths,
and the errors for bad URDFs.

- Random segments of the Franka Panda (example-robot-data; its exact chain, each link's
  geometry replaced by its bounding ball so that brute force stays cheap) among a few
  obstacle boxes: answers of Robot.check equal brute force (PCCD_BROAD_BRUTE) exactly,
  self-collision included, and every contact that dense sampling finds (1e4 times: a
  float FK by Pinocchio flags candidate times, then the exact FK, Motion.position, and an
  exact static ball-box / ball-ball test decide) is found by polyccd no later. Kept for
  self-collision, which brute force cannot afford on the real meshes.
- The same Panda with its real collision meshes (every link, the fingers' boxes) among
  three thin plates: Robot.check equals brute force (all contacts), and dense sampling
  (Pinocchio's float FK and a float separating-axis filter flag candidates, an exact
  Fraction triangle-plate test at the exact link motions' positions decides) finds no
  contact earlier than polyccd's first one (robot vs obstacles only).
- A small synthetic arm written here: obstacle and self-collision answers equal brute
  force, the allowed pairs and the first colliding segment of a path.
- Bad URDFs: missing mesh file, floating / planar joints, zero axis, full-turn segment.
"""
import math
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd import InputError  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402
from test_scene_property import summary  # noqa: E402

SEED = 20261124
SAMPLES = int(os.environ.get("POLYCCD_ROBOT_SAMPLES", "10000"))
BOX_T = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
         [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]


def box(lo, hi):
    """The axis-aligned box [lo, hi] as 12 triangles (vertex i: bit a of i picks lo or hi
    on axis a)."""
    return P.Mesh([[(lo[a], hi[a])[(i >> a) & 1] for a in range(3)] for i in range(8)], BOX_T)


# ---------------------------------------------------------------- the real arm

# Four links of the arm (rotation degrees 2 to 5): brute force over the hand (degree 7)
# can take minutes in the exact stage, see SEGMENTS.
BALL_LINKS = ("panda_link2", "panda_link3", "panda_link4", "panda_link5")


def ball_robot(path):
    """The robot with each link's geometry (links whose geometry has no origin offset)
    replaced by a ball: centre the mesh's box centre, radius 0.3 times the box diagonal
    (doubles, taken exactly). A stand-in geometry: brute force over every feature pair of
    the real meshes takes minutes per link pair at these degrees."""
    robot = load_urdf(path)
    shapes, balls = [], {}
    for link, i, k, shape in robot.shapes:
        if link not in BALL_LINKS or k != robot.link_index[link] or link in balls:
            continue
        v = shape.vertices
        lo, hi = v.min(axis=0), v.max(axis=0)
        c = (lo + hi) / 2
        r = float(np.linalg.norm(hi - lo)) * 0.3  # a ball inside the bounding one: fewer
        # links touching their neighbours' neighbours (contacts at t = 0 everywhere)
        balls[link] = (c, r)
        shapes.append((link, i, k, P.Spheres([c], [r])))
    robot.shapes = shapes
    return robot, balls


def exact_ball_box(c, r, lo, hi):
    """The closed ball (c, r) meets the closed box [lo, hi]: exact squared distance."""
    d2 = sum((max(F(lo[a]) - c[a], F(0), c[a] - F(hi[a]))) ** 2 for a in range(3))
    return d2 <= F(r) ** 2


def exact_ball_ball(c1, r1, c2, r2):
    return sum((c1[a] - c2[a]) ** 2 for a in range(3)) <= (F(r1) + F(r2)) ** 2


def pinocchio_q(pin, model, robot, angles, k):
    """Pinocchio's configuration at sample k of the joint angles (name -> array); the
    second finger follows the first (mimic joint)."""
    q = pin.neutral(model)
    for jid in range(1, model.njoints):
        n = model.names[jid]
        if n in robot.mimic_joints:
            leader, mult, off = robot.mimic_joints[n]
            q[model.joints[jid].idx_q] = mult * angles[leader][k] + off
        else:
            q[model.joints[jid].idx_q] = angles[n][k]
    return q


def first_sampled_contact(robot, balls, path, q0, q1, obstacles, pairs):
    """The first sampled time k / SAMPLES at which an exact static test finds a contact
    of one of the pairs, or None: candidate times from Pinocchio's float FK at the joint
    angles of the exact motion (the half-angle interpolation, chain.h) with a margin of
    1e-6, then, in time order, the exact test with the link motions' exact positions
    until one holds."""
    pin = pytest.importorskip("pinocchio")
    model = pin.buildModelFromUrdf(path)
    data = model.createData()
    ts = np.arange(SAMPLES + 1) / SAMPLES
    angles = {}
    for j, name in enumerate(robot.joints):
        a, b = q0[j], q1[j]
        if robot.joint_types[name] == "prismatic":
            angles[name] = a + (b - a) * ts  # linear (unit axes)
            continue
        c = (1 - ts) * math.cos(a / 2) + ts * math.cos(b / 2)
        s = (1 - ts) * math.sin(a / 2) + ts * math.sin(b / 2)
        c0, s0 = math.cos(a / 2), math.sin(a / 2)
        angles[name] = a + 2 * np.arctan2(c0 * s - s0 * c, c0 * c + s0 * s)
    links = sorted(balls)
    centre = {link: np.zeros((len(ts), 3)) for link in links}
    for k in range(len(ts)):
        pin.framesForwardKinematics(model, data, pinocchio_q(pin, model, robot, angles, k))
        for link in links:
            M = data.oMf[model.getFrameId(link)]
            centre[link][k] = M.rotation @ balls[link][0] + M.translation
    candidates = []  # (sample index, pair)
    for a, b in pairs:
        r = balls[a][1]
        if isinstance(b, int):  # link a against obstacle box b
            lo, hi = (np.array(v) for v in obstacles[b])
            d2 = np.sum(np.maximum(0, np.maximum(lo - centre[a], centre[a] - hi)) ** 2, axis=1)
            near = d2 <= (r + 1e-6) ** 2
        else:
            near = np.linalg.norm(centre[a] - centre[b], axis=1) <= r + balls[b][1] + 1e-6
        candidates += [(int(k), (a, b)) for k in np.flatnonzero(near)]
    motions = robot.link_motions(q0, q1)
    for k, (a, b) in sorted(candidates, key=lambda x: x[0]):
        t = F(k, SAMPLES)
        ca = motions[a].position(balls[a][0], t)
        if isinstance(b, int):
            hit = exact_ball_box(ca, balls[a][1], *obstacles[b])
        else:
            hit = exact_ball_ball(ca, balls[a][1], motions[b].position(balls[b][0], t), balls[b][1])
        if hit:
            return t
    return None


# Seeds 0 and 2 are left out by default: their scenes take 14 s and 40 s (the exact stage
# on ball-triangle systems of these degrees; a speed issue, the answers agree); run
# every seed below N with POLYCCD_ROBOT_SEGMENTS=N.
SEGMENTS = (range(int(os.environ["POLYCCD_ROBOT_SEGMENTS"])) if "POLYCCD_ROBOT_SEGMENTS" in os.environ
            else (1, 3, 4, 5))


@needs_robots
@pytest.mark.parametrize("k", SEGMENTS)
def test_panda_segments_equal_brute_force_and_sampling(k):
    path = os.path.join(ROBOTS, URDFS["panda"])
    robot, balls = ball_robot(path)
    rng = random.Random(SEED + k)
    lims = [robot.limits[n] for n in robot.joints]
    q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
    q1 = np.array([min(hi, max(lo, x + rng.uniform(-1.5, 1.5))) for x, (lo, hi) in zip(q0, lims)])
    # Obstacles: small boxes near points the link balls pass at random times (hits and
    # near misses are common).
    motions = robot.link_motions(q0, q1)
    obstacles = []
    while len(obstacles) < 3:
        link = rng.choice(sorted(balls))
        x = [float(v) for v in motions[link].position(balls[link][0], F(rng.randint(3, 9), 10))]
        lo = [x[a] + rng.uniform(-0.15, 0.05) for a in range(3)]
        hi = [lo[a] + rng.uniform(0.02, 0.1) for a in range(3)]
        x0 = [float(v) for v in motions[link].position(balls[link][0], 0)]
        d0 = sum(max(lo[a] - x0[a], 0, x0[a] - hi[a]) ** 2 for a in range(3)) ** 0.5
        if d0 > balls[link][1] + 0.01:  # not in contact at t = 0 already (a float choice)
            obstacles.append((lo, hi))
    bodies = [P.Body(box(lo, hi), name=f"box{i}") for i, (lo, hi) in enumerate(obstacles)]
    got = robot.check(q0, q1, bodies, time_tolerance="1e-9")
    brute = robot.check(q0, q1, bodies, time_tolerance="1e-9", broad_phase="brute")
    assert summary(got.scene) == summary(brute.scene), (SEED, k)
    # Dense sampling over the same pairs (links vs boxes; non-adjacent links).
    adjacent = robot.adjacent_pairs()
    links = sorted(balls)
    pairs = [(a, b) for a in links for b in range(len(obstacles))]
    pairs += [(a, b) for i, a in enumerate(links) for b in links[i + 1:]
              if frozenset((a, b)) not in adjacent]
    found = first_sampled_contact(robot, balls, path, q0, q1, obstacles, pairs)
    if found is not None:
        assert got.collides and got.first_contact.lo <= found, (SEED, k, found, got.first_contact)
    if got.collides:  # the joint values at the enclosure's ends are those of that time
        assert set(got.joint_values[0]) == set(robot.joints)
        assert got.contacts and all(c.a[0] in balls or c.a[0].startswith("box") for c in got.contacts)
    print(k, "collides", got.collides, got.first_contact and got.first_contact.approx,
          "first sampled contact", found)


# ---------------------------------------------------------------- the real arm's meshes

# Brute force over every feature pair takes 14 to 25 s a segment here (seeds 0 to 2, the
# default: two segments that collide and one that is free; measured 2026-11-25); run
# every seed below N with POLYCCD_ROBOT_MESH_SEGMENTS=N.
MESH_SEGMENTS = range(int(os.environ.get("POLYCCD_ROBOT_MESH_SEGMENTS", "3")))
MARGIN = 1e-6  # of the float filter (m): FK and rounding errors are near 1e-15 m here
PLATE_T = [[0, 1, 2], [1, 3, 2]]


def plate(axis, c, lo, hi):
    """The closed rectangle {x[axis] = c, lo <= (x[b], x[d]) <= hi} (b < d the other two
    axes) as two triangles; corner i: bit 0 picks lo or hi on b, bit 1 on d."""
    b, d = (x for x in range(3) if x != axis)
    corners = []
    for i in range(4):
        v = [0.0] * 3
        v[axis], v[b], v[d] = c, (lo[0], hi[0])[i & 1], (lo[1], hi[1])[i >> 1]
        corners.append(v)
    return corners


def exact_triangle_meets_plate(tri, axis, c, lo, hi):
    """The closed triangle tri (3 points of Fractions) meets the closed plate (axis, c,
    lo, hi), exactly: the triangle's intersection with the plane x[axis] = c is the convex
    hull S of its vertices on the plane and of its edges' crossing points (a point or a
    segment, or the whole triangle when it lies in the plane), and two convex polygons of
    a plane are disjoint iff an edge normal of one separates them (in 2D: x, y for the
    rectangle, the normals of S's edges)."""
    c = F(c)
    z = [p[axis] - c for p in tri]
    if all(v > 0 for v in z) or all(v < 0 for v in z):
        return False
    b, d = (x for x in range(3) if x != axis)
    flat = [(p[b], p[d]) for p in tri]
    if all(v == 0 for v in z):
        S = flat
    else:
        S = [flat[i] for i in range(3) if z[i] == 0]
        for i, j in ((0, 1), (1, 2), (2, 0)):
            if z[i] * z[j] < 0:
                s = z[i] / (z[i] - z[j])
                S.append(tuple(flat[i][a] + (flat[j][a] - flat[i][a]) * s for a in range(2)))
    rect = [(F(x), F(y)) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
    axes = [(1, 0), (0, 1)] + [(S[i][1] - S[j][1], S[j][0] - S[i][0])
                               for i in range(len(S)) for j in range(i + 1, len(S))]
    for u in axes:
        ps = [p[0] * u[0] + p[1] * u[1] for p in S]
        rs = [p[0] * u[0] + p[1] * u[1] for p in rect]
        if max(ps) < min(rs) or max(rs) < min(ps):
            return False
    return True


def pinocchio_frames(path, robot, q0, q1, ts):
    """{URDF link: (R, p)} of Pinocchio's float FK at the joint angles of the exact motion
    at the times ts (the half-angle interpolation, chain.h; as first_sampled_contact)."""
    pin = pytest.importorskip("pinocchio")
    model = pin.buildModelFromUrdf(path)
    data = model.createData()
    angles = {}
    for j, name in enumerate(robot.joints):
        a, b = q0[j], q1[j]
        if robot.joint_types[name] == "prismatic":
            angles[name] = a + (b - a) * ts
            continue
        c = (1 - ts) * math.cos(a / 2) + ts * math.cos(b / 2)
        s = (1 - ts) * math.sin(a / 2) + ts * math.sin(b / 2)
        c0, s0 = math.cos(a / 2), math.sin(a / 2)
        angles[name] = a + 2 * np.arctan2(c0 * s - s0 * c, c0 * c + s0 * s)
    links = sorted({link for link, _, _, _ in robot.shapes})
    R = {link: np.zeros((len(ts), 3, 3)) for link in links}
    p = {link: np.zeros((len(ts), 3)) for link in links}
    frame = {link: model.getFrameId(link) for link in links}
    for k in range(len(ts)):
        pin.framesForwardKinematics(model, data, pinocchio_q(pin, model, robot, angles, k))
        for link in links:
            M = data.oMf[frame[link]]
            R[link][k], p[link][k] = M.rotation, M.translation
    return R, p


def float_geometry(path, robot, R, p):
    """[[URDF link, vertices (n, 3), triangles (m, 3)]] of every shape: the Mesh's doubles
    through its collision origin as yourdfpy reads it (a float 4x4), in the link's frame;
    world_triangles puts them at Pinocchio's frames (R, p) of sampled times."""
    import yourdfpy
    urdf = yourdfpy.URDF.load(path, load_meshes=False, build_scene_graph=False,
                              load_collision_meshes=False)
    out = []
    for link, i, _, shape in robot.shapes:
        origin = urdf.link_map[link].collisions[i].origin
        v = np.asarray(shape.vertices, dtype=np.float64)
        if origin is not None:
            v = v @ origin[:3, :3].T + origin[:3, 3]
        out.append([link, v, np.asarray(shape.triangles)])
    return out, R, p


def world_vertices(geometry, s, idx):
    """Shape s's vertices (len(idx), n, 3) at the sampled times idx (float)."""
    shapes, R, p = geometry
    link, v = shapes[s][:2]
    return np.einsum("tij,vj->tvi", R[link][idx], v) + p[link][idx][:, None, :]


def float_candidates(tris, corners, margin):
    """Mask (T, m) of the triangles (T, m, 3, 3) that no separating axis keeps more than
    margin away from the plate (4 corners): the plate's normal and edges, the triangle's
    normal and its edges' cross products with the plate's edges (the separating axis
    test of two convex polygons in space, with a margin; a float filter, never a
    decision)."""
    corners = np.asarray(corners)
    e = [tris[..., (i + 1) % 3, :] - tris[..., i, :] for i in range(3)]
    pe = [corners[1] - corners[0], corners[2] - corners[0]]
    axes = [np.broadcast_to(np.eye(3)[a], tris.shape[:-2] + (3,)) for a in range(3)]
    axes.append(np.cross(e[0], e[1]))
    axes += [np.cross(ei, np.broadcast_to(f, ei.shape)) for ei in e for f in pe]
    keep = np.ones(tris.shape[:-2], dtype=bool)
    for u in axes:
        t = np.einsum("...vi,...i->...v", tris, u)
        c = np.einsum("vi,...i->...v", corners, u)
        gap = margin * np.linalg.norm(u, axis=-1)
        keep &= ~((t.min(-1) - c.max(-1) > gap) | (c.min(-1) - t.max(-1) > gap))
    return keep


def first_sampled_mesh_contact(robot, geometry, q0, q1, plates):
    """The first sampled time k / SAMPLES at which an exact static test finds a robot
    triangle meeting a plate, or None, and the number of float candidates looked at: in
    time order (chunks of 100 samples), the (shape, plate) pairs whose boxes come within
    MARGIN, their triangles that float_candidates keeps, then the exact test
    (exact_triangle_meets_plate) on the triangle's vertices at the exact link motions'
    positions (Motion.position at the Fraction time) until one holds."""
    shapes = geometry[0]
    near = {}  # (shape, plate) -> sample indices where their boxes are within MARGIN
    for s in range(len(shapes)):
        if len(shapes[s]) == 3:  # the shape's box at every sampled time, once
            w = world_vertices(geometry, s, slice(None))
            shapes[s] += (w.min(axis=1), w.max(axis=1))
        lo, hi = shapes[s][3:]
        for j, p in enumerate(plates):
            c = np.asarray(plate(*p))
            idx = np.flatnonzero(np.all((lo <= c.max(0) + MARGIN) & (hi >= c.min(0) - MARGIN), axis=1))
            if len(idx):
                near[s, j] = idx
    motions = robot.motions(q0, q1)
    flagged = 0
    for start in range(0, SAMPLES + 1, 100):
        candidates = {}  # sample index -> [(shape, triangle, plate)]
        for (s, j), idx in near.items():
            idx = idx[(idx >= start) & (idx < start + 100)]
            if len(idx) == 0:
                continue
            tris = world_vertices(geometry, s, idx)[:, shapes[s][2]]
            c = np.asarray(plate(*plates[j]))
            k, m = np.nonzero(np.all((tris.min(axis=2) <= c.max(0) + MARGIN)
                                     & (tris.max(axis=2) >= c.min(0) - MARGIN), axis=2))
            keep = float_candidates(tris[k, m], c, MARGIN)  # the boxes that meet, only
            for k, m in zip(k[keep], m[keep]):
                candidates.setdefault(int(idx[k]), []).append((s, int(m), j))
        for k in sorted(candidates):
            t = F(k, SAMPLES)
            for s, m, j in candidates[k]:
                flagged += 1
                _, _, ck, shape = robot.shapes[s]
                tri = [motions[ck].position([float(x) for x in shape.vertices[v]], t)
                       for v in shape.triangles[m]]
                if exact_triangle_meets_plate(tri, *plates[j]):
                    return t, flagged
    return None, flagged


def test_exact_triangle_meets_plate():
    """The sampler's exact test and float filter on triangles built to touch the plate
    [0, 1]^2 at z = 0 in one point (a vertex on its edge, an edge through its corner,
    a plane section or a coplanar edge through its corner, a coplanar overlap), each
    also moved off by 2^-60 (exactly disjoint; boxes still overlapping for the last
    three, so the section's own normal must separate), and a pierce. The float filter
    keeps every touching one."""
    e = F(1, 2 ** 60)
    touching = [
        [(F(1, 2), 1, 0), (F(1, 2), 2, 1), (0, 2, 1)],           # vertex on the edge y = 1
        [(2, 0, -1), (0, 2, 1), (2, 2, 1)],                      # edge through (1, 1, 0)
        [(2, 0, -1), (0, 2, -1), (2, 0, 1)],                     # section x + y = 2
        [(F(3, 2), F(1, 2), 0), (F(1, 2), F(3, 2), 0), (2, 2, 0)],  # coplanar, x + y = 2
        [(F(9, 10), F(9, 10), 0), (2, F(9, 10), 0), (F(9, 10), 2, 0)],  # coplanar overlap
    ]
    away = [  # each moved off by e: +y, +x (+ y), +x, +x, and the overlap one out of the plane
        [(p[0], p[1] + e, p[2]) for p in touching[0]],
        [(p[0] + e, p[1] + e, p[2]) for p in touching[1]],
        [(p[0] + e, p[1], p[2]) for p in touching[2]],
        [(p[0] + e, p[1], p[2]) for p in touching[3]],
        [(p[0], p[1], p[2] + e) for p in touching[4]],
    ]
    pierce = [(F(1, 2), F(1, 2), -1), (F(3, 5), F(1, 2), 1), (F(1, 2), F(3, 5), 1)]
    square = (2, 0, (0, 0), (1, 1))
    for tri in touching + [pierce]:
        tri = [tuple(F(x) for x in p) for p in tri]
        assert exact_triangle_meets_plate(tri, *square), tri
        assert float_candidates(np.array([[[[float(x) for x in p] for p in tri]]]), plate(*square), MARGIN).all()
        # the same triangle about the other two axes (the coordinates rotated)
        for axis in (0, 1):
            rot = [tuple(p[(a - axis - 1) % 3] for a in range(3)) for p in tri]
            assert exact_triangle_meets_plate(rot, axis, 0, (0, 0), (1, 1)), (axis, rot)
    for tri in away:
        assert not exact_triangle_meets_plate([tuple(F(x) for x in p) for p in tri], *square), tri


@needs_robots
@pytest.mark.parametrize("k", MESH_SEGMENTS)
def test_panda_meshes_equal_brute_force_and_sampling(k):
    """The real Panda's collision meshes (every link, the fingers' boxes) among three
    plates (two triangles each: brute force over every feature pair costs 20 to 60 s a
    segment with three plates, 68 s with three boxes), placed near a random vertex of
    a random shape at a random time in [3/10, 9/10] (some hit, some are missed), none
    within 5 mm of the robot at t = 0 by the float test: Robot.check equals brute force
    (first contact and all contacts), and dense sampling, of all plates and of each plate
    alone, finds no contact earlier than polyccd's first one, none when it says free.
    Self-collision is left out: brute force over the links' feature pairs did not end
    within 9 minutes for one segment."""
    path = os.path.join(ROBOTS, URDFS["panda"])
    robot = load_urdf(path)
    rng = random.Random(SEED * 7 + k)
    lims = [robot.limits[n] for n in robot.joints]
    q0 = np.array([rng.uniform(lo, hi) for lo, hi in lims])
    q1 = np.array([min(hi, max(lo, x + rng.uniform(-1.5, 1.5))) for x, (lo, hi) in zip(q0, lims)])
    ts = np.arange(SAMPLES + 1) / SAMPLES
    geometry = float_geometry(path, robot, *pinocchio_frames(path, robot, q0, q1, ts))
    motions = robot.motions(q0, q1)
    plates = []
    while len(plates) < 3:
        _, _, ck, shape = rng.choice(robot.shapes)
        v = [float(x) for x in shape.vertices[rng.randrange(len(shape.vertices))]]
        x = [float(c) for c in motions[ck].position(v, F(rng.randint(3, 9), 10))]
        axis = rng.randrange(3)
        b, d = (a for a in range(3) if a != axis)
        lo = [x[b] - rng.uniform(-0.03, 0.08), x[d] - rng.uniform(-0.03, 0.08)]
        hi = [lo[0] + rng.uniform(0.01, 0.06), lo[1] + rng.uniform(0.01, 0.06)]
        p = (axis, x[axis] + rng.uniform(-0.06, 0.06), lo, hi)
        if not any(float_candidates(world_vertices(geometry, s, [0])[:, t], plate(*p), 0.005).any()
                   for s, (_, _, t) in enumerate(g[:3] for g in geometry[0])):
            plates.append(p)
    bodies = [P.Body(P.Mesh(plate(*p), PLATE_T), name=f"plate{i}") for i, p in enumerate(plates)]
    options = dict(self_collision=False, time_tolerance="1e-9")
    got = robot.check(q0, q1, bodies, **options)
    every = robot.check(q0, q1, bodies, all_contacts=True, **options)
    brute = robot.check(q0, q1, bodies, all_contacts=True, broad_phase="brute", **options)
    assert summary(every.scene) == summary(brute.scene), (SEED, k)
    assert (got.collides, got.first_contact) == (brute.collides, brute.first_contact), (SEED, k)
    if got.collides:
        assert got.contacts and all(c.b[0].startswith("plate") for c in got.contacts)
    # Sampling: all plates, then each plate alone (the plates the arm misses or grazes).
    for j in [None] + list(range(len(plates))):
        one = got if j is None else robot.check(q0, q1, [bodies[j]], **options)
        found, flagged = first_sampled_mesh_contact(robot, geometry, q0, q1,
                                                    plates if j is None else [plates[j]])
        if found is not None:
            assert one.collides and one.first_contact.lo <= found, (SEED, k, j, found, one.first_contact)
        print(k, "plate", "all" if j is None else j, "collides", one.collides,
              one.first_contact and one.first_contact.approx, "first sampled contact", found,
              "float candidates", flagged)


# ---------------------------------------------------------------- a synthetic arm

ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"><collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.2 0.2"/></geometry></collision></link>
  <link name="lower"><collision><origin xyz="0.4 0 0"/><geometry><box size="0.8 0.1 0.1"/></geometry></collision>
                     <collision><origin xyz="0.8 0 0" rpy="0 0 0.5"/><geometry><sphere radius="0.08"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="%s"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0" rpy="0 0 0"/><axis xyz="%s"/><limit lower="-6" upper="6" effort="1" velocity="1"/></joint>
</robot>
"""


def write(tmp_path, text, name="arm.urdf"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def test_synthetic_arm_equals_brute_force(tmp_path):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    assert robot.joints == ["shoulder", "elbow"]
    assert robot.adjacent_pairs() == {frozenset(("base", "upper")), frozenset(("upper", "lower"))}
    rng = random.Random(SEED)
    collided = 0
    for case in range(6):
        q0 = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        q1 = [x + rng.uniform(-2.5, 2.5) for x in q0]
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), F(1, 5)]
        obstacle = P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name="post")
        for allowed in (None, []):
            got = robot.check(q0, q1, [obstacle], allowed=allowed, time_tolerance="1e-9")
            brute = robot.check(q0, q1, [obstacle], allowed=allowed, time_tolerance="1e-9",
                                broad_phase="brute")
            assert summary(got.scene) == summary(brute.scene), (case, q0, q1, c, allowed)
            collided += got.collides
        # With the adjacent pairs checked, upper and lower always touch (they share a face).
        assert robot.check(q0, q1, [], allowed=[]).collides
        assert not robot.check(q0, q1, [], self_collision=True).scene.pairs or \
            all(set(p.names) != {"upper", "lower[0]"} for p in robot.check(q0, q1, []).scene.pairs)
    assert collided > 0


def test_synthetic_arm_path(tmp_path):
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    post = P.Body(box([1.5, -0.05, 0], [1.6, 0.05, 0.5]), name="post")  # on the +x axis
    # The arm points along -y, swings to -x (free: the post is at +x), then to +y through +x? no:
    # from -x back through -y to +x, where it meets the post.
    waypoints = [[-math.pi / 2, 0], [-math.pi + 0.1, 0], [-math.pi / 2, 0], [0.3, 0]]
    r = robot.check_path(waypoints, [post])
    assert r.segment == 2, r.segment
    assert r.result.collides and {c.b[0] for c in r.result.contacts} == {"post"}
    # The shoulder's angle at the first contact: between the segment's ends, and the
    # arm's far end (x = 1.88 at most) first reaches the post's corner.
    lo = r.result.joint_values[0]["shoulder"]
    assert -math.pi / 2 < lo < 0.3
    assert robot.check_path(waypoints[:3], [post]).segment is None


def test_synthetic_arm_min_distance(tmp_path):
    """Robot.check and check_path pass min_distance through: every broad phase equals
    brute force at delta > 0 (the box phases grow one body's boxes by delta), and a post
    the arm's tip passes 0.12 away from (tip at x = 1.88 when the arm points along +x,
    post from x = 2) is met within 1/5, not within 1/10."""
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    rng = random.Random(SEED + 1)
    decided = 0
    for case in range(4):
        q0 = [rng.uniform(-3, 3), rng.uniform(-3, 3)]
        q1 = [x + rng.uniform(-2.5, 2.5) for x in q0]
        c = [rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)]
        obstacle = P.Body(box([c[0], c[1], 0], [c[0] + 0.1, c[1] + 0.1, 0.5]), name="post")
        delta = F(1, 10)  # (1/4 puts base and lower within delta at t = 0: slow brute force)
        brute = robot.check(q0, q1, [obstacle], min_distance=delta, time_tolerance="1e-9",
                            broad_phase="brute")
        for phase in ("auto", "bvh", "boxes"):
            got = robot.check(q0, q1, [obstacle], min_distance=delta, time_tolerance="1e-9",
                              broad_phase=phase)
            assert summary(got.scene) == summary(brute.scene), (case, q0, q1, c, phase)
        plain = robot.check(q0, q1, [obstacle], time_tolerance="1e-9")
        decided += brute.collides and (not plain.collides or
                                       plain.first_contact.lo > brute.first_contact.hi)
    assert decided > 0
    post = P.Body(box([2, -0.05, 0], [2.1, 0.05, 0.5]), name="post")
    waypoints = [[-math.pi / 2, 0], [-math.pi + 0.1, 0], [-math.pi / 2, 0], [0.3, 0]]
    path = dict(self_collision=False, time_tolerance="1e-9")
    assert robot.check_path(waypoints, [post], **path).segment is None
    assert robot.check_path(waypoints, [post], min_distance="1/10", **path).segment is None
    r = robot.check_path(waypoints, [post], min_distance="1/5", **path)
    assert r.segment == 2 and {c.b[0] for c in r.result.contacts} == {"post"}
    brute = robot.check(waypoints[2], waypoints[3], [post], min_distance="1/5",
                        broad_phase="brute", **path)
    assert summary(r.result.scene) == summary(brute.scene)


# ---------------------------------------------------------------- errors

def test_bad_urdfs(tmp_path):
    with pytest.raises(InputError, match="joints.elbow: type 'floating' is not supported"):
        load_urdf(write(tmp_path, ARM % ("floating", "0 0 1")))
    with pytest.raises(InputError, match="joints.elbow: type 'planar' is not supported"):
        load_urdf(write(tmp_path, ARM % ("planar", "0 0 1")))
    with pytest.raises(InputError, match=r"^joints.elbow.axis: the direction is the zero vector"):
        load_urdf(write(tmp_path, ARM % ("revolute", "0 0 0")))
    with pytest.raises(InputError, match=r"^path: .* is not a readable URDF \(could not broadcast"):  # yourdfpy's check
        load_urdf(write(tmp_path, (ARM % ("revolute", "0 0 1")).replace('xyz="1 0 0"', 'xyz="1 0"')))
    text = (ARM % ("revolute", "0 0 1")).replace('<sphere radius="0.08"/>', '<mesh filename="missing/part.stl"/>')
    with pytest.raises(InputError, match=r"^links.lower.collision\[1\].geometry.mesh: mesh file '.*part.stl' not found"):
        load_urdf(write(tmp_path, text))
    with pytest.raises(InputError, match=r"^path: URDF file .* not found"):
        load_urdf(str(tmp_path / "nothing.urdf"))
    robot = load_urdf(write(tmp_path, ARM % ("continuous", "0 0 1")))
    assert robot.limits["elbow"] is None
    with pytest.raises(InputError, match=r"^q1\[1\] \(elbow\): the revolute segment from 0 to 7 turns by 2 pi"):
        robot.motions([0, 0], [0, 7])
    with pytest.raises(InputError, match=r"^waypoints\[1\] -> waypoints\[2\]: q1\[1\] \(elbow\)"):
        robot.check_path([[0, 0], [0, 1], [0, 8]], [P.Body(P.Spheres([[9, 9, 9]], [1]))])
    with pytest.raises(InputError, match=r"^q: expected 2 joint values"):
        robot.motions([0], [0])
    with pytest.raises(InputError, match=r"^allowed\[0\]:"):
        robot.check([0, 0], [0, 1], allowed=[("base", "nope")])


def test_robot_check_takes_limits(tmp_path):
    """Robot.check and check_path pass limits= to the scene (polyccd.Limits): a work limit
    below what the segment needs stops it with LimitError, a generous one changes nothing."""
    robot = load_urdf(write(tmp_path, ARM % ("revolute", "0 0 1")))
    post = P.Body(box([1.5, -0.05, 0], [1.6, 0.05, 0.5]), name="post")
    q0, q1 = [-math.pi / 2, 0], [0.3, 0]
    free = robot.check(q0, q1, [post])
    assert free.collides
    with pytest.raises(P.LimitError, match=r"^config\.max_work: the limit of 3 work steps was reached"):
        robot.check(q0, q1, [post], limits=P.Limits(max_work=3))
    with pytest.raises(P.LimitError, match=r"^waypoints\[0\] -> waypoints\[1\]: config\.max_work"):
        robot.check_path([q0, q1], [post], limits=P.Limits(max_work=3))
    same = robot.check(q0, q1, [post], limits=P.Limits(max_work=10 ** 9))
    assert same.first_contact == free.first_contact
