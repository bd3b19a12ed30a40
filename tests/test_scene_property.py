"""Property tests of scenes: both broad phases (time pieces + CGAL boxes; the range
structure of linearized conditions in CGAL kd-trees) give exactly the answers of brute
force over every feature pair, for any thread count, in first-contact and all-contacts
modes. Bodies and motions are random but built on a coarse rational
grid so that touching, grazing and simultaneous contacts are common.

POLYCCD_SCENE_SEED and POLYCCD_SCENE_COUNT change the seed and the number of scenes.
"""
import os
import random
from fractions import Fraction as F

import pytest

import polyccd as P
from helpers import summary

SEED = int(os.environ.get("POLYCCD_SCENE_SEED", "20261122"))
COUNT = int(os.environ.get("POLYCCD_SCENE_COUNT", "150"))


def grid(rng, k=2):
    return F(rng.randint(-k, k), 2)


def random_mesh(rng):
    """A tetrahedron, an octahedron-ish or a few loose triangles (degenerate allowed)."""
    c = [grid(rng) for _ in range(3)]
    shape = rng.choice(["tet", "tris", "box"])
    if shape == "tet":
        v = [[c[0], c[1], c[2]], [c[0] + 1, c[1], c[2]], [c[0], c[1] + 1, c[2]], [c[0], c[1], c[2] + 1]]
        t = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    elif shape == "box":
        s = F(rng.randint(1, 3), 2)
        v = [[c[0] + s * (i & 1), c[1] + s * ((i >> 1) & 1), c[2] + s * (i >> 2)] for i in range(8)]
        t = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
             [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
    else:
        n = rng.randint(1, 4)
        v = [[grid(rng, 3) for _ in range(3)] for _ in range(n + 2)]
        t = [[rng.randrange(n + 2) for _ in range(3)] for _ in range(n)]
    return P.Mesh(v, t)


def random_spheres(rng):
    n = rng.randint(1, 4)
    return P.Spheres([[grid(rng, 3) for _ in range(3)] for _ in range(n)],
                     [F(rng.randint(1, 4), 4) for _ in range(n)])


def random_motion(rng):
    kind = rng.choice(["none", "linear", "quadratic", "rotation", "screw"])
    if kind == "none":
        return None
    if kind == "linear":
        return P.Motion.linear([grid(rng) for _ in range(3)], [grid(rng) for _ in range(3)])
    if kind == "quadratic":
        return P.Motion.translation([[grid(rng), grid(rng), grid(rng)] for _ in range(3)])
    axis = [rng.randint(-1, 1) for _ in range(3)]
    if axis == [0, 0, 0]:
        axis = [0, 0, 1]
    center = [grid(rng, 2) for _ in range(3)]
    tau0, tau1 = F(rng.randint(-2, 2), 2), F(rng.randint(-2, 2), 2)
    if kind == "rotation":
        m = P.Motion.axis_rotation(axis, center, tau0, tau1)
    else:
        m = P.Motion.screw(axis, center, tau0, tau1, grid(rng, 2))
    return m.compose([1, 0, 0, 0], [grid(rng, 2) for _ in range(3)], side="world")


def random_scene(rng):
    bodies = []
    for i in range(rng.choice([2, 2, 2, 3])):
        shape = random_mesh(rng) if rng.random() < 0.65 else random_spheres(rng)
        bodies.append(P.Body(shape, random_motion(rng), name=f"b{i}"))
    return bodies


def scene_call(bodies, **kw):
    """polyccd.check's answer computed through a pccd_scene (pccd_scene_add,
    pccd_scene_solve), as check() does for three or more bodies; check() of two bodies
    calls pccd_pair_solve instead, which must answer the same."""
    from polyccd import _handles, _scene
    from polyccd._pccd import ffi, lib
    args = dict(time_tolerance="1e-12", all_contacts=False, threads=1, broad_phase="auto",
                want_exact=True)
    args.update(kw)
    cfg, _keep, opt = _scene._options(**args)
    scene = _handles.new("scene")
    for b in bodies:
        _scene.check(lib.pccd_scene_add(scene, b.shape._handle,
                                        ffi.NULL if b.motion is None else b.motion._handle, ffi.NULL))
    rep = _handles.new("report")
    _scene.check(lib.pccd_scene_solve(scene, cfg, opt, rep))
    return _scene._read(rep, bodies)




@pytest.mark.parametrize("k", range(COUNT))
def test_broad_phases_equal_brute_force(k):
    rng = random.Random(SEED * 1000 + k)
    bodies = random_scene(rng)
    for all_contacts in (False, True):
        brute = summary(P.check(bodies, broad_phase="brute", all_contacts=all_contacts,
                                time_tolerance="1e-9"))
        for broad_phase in ("boxes", "range", "bvh"):
            for threads in (1, 2, 3):
                got = summary(P.check(bodies, threads=threads, all_contacts=all_contacts,
                                      broad_phase=broad_phase, time_tolerance="1e-9"))
                assert got == brute, (k, all_contacts, broad_phase, threads)


def test_scenes_collide_often_enough():
    """The generator is useful only if contacts (incl. exact rational ones) are common."""
    hits = exact = 0
    for k in range(COUNT):
        r = P.check(random_scene(random.Random(SEED * 1000 + k)), time_tolerance="1e-9")
        hits += r.collides
        exact += r.collides and r.first_contact.exact is not None
    assert hits >= COUNT // 4 and exact >= COUNT // 10, (hits, exact)
