"""Robots (polyccd.robot): the Franka Panda with its real collision meshes (every link,
the fingers' boxes) among three thin plates: Robot.check equals brute force (all
contacts), and dense sampling (Pinocchio's float FK and a float separating-axis filter
flag candidates, an exact Fraction triangle-plate test at the exact link motions'
positions decides) finds no contact earlier than polyccd's first one (robot vs
obstacles only).
"""
import math
import os
import random
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import summary  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402
from test_robot import SAMPLES, SEED, pinocchio_q  # noqa: E402
from test_robot_fk import ROBOTS, URDFS, needs_robots  # noqa: E402


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
    # The same first contact: equal when exact, else overlapping enclosures (each holds
    # it; a robot check may solve on a shorter window and enclose it more tightly).
    assert got.collides == brute.collides, (SEED, k)
    if got.collides:
        a, b = got.first_contact, brute.first_contact
        assert a.exact == b.exact and a.lo <= b.hi and b.lo <= a.hi, (SEED, k, a, b)
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
