"""A fast thin object tunnels through a plate in MuJoCo; polyccd reports the contact
(issue 22, item 4; the scene: tests/bench/tunnel_scene.py).

MuJoCo (a simulator not written here) steps a spinning box bullet through a fixed
1 cm plate and records no contact in any step (its contacts are discrete: geoms
overlapping at a step). Each step, as exact polyccd motions between MuJoCo's poses,
is checked by polyccd.check. Checked independently of polyccd's answer:
  - the bullet's origin passes from one side of the plate to the other in exactly one
    step, with the bullet's whole extent (its half diagonal) clear of the plate at both
    ends, while in every other step the origin stays farther from the plate than the
    half diagonal (so no contact is possible in those: the origin moves linearly);
  - in the crossing step the reported pair is a bullet vertex and a triangle of the
    plate's face x = -0.005 and, at exact Fraction positions (Motion.position), no bullet
    vertex has reached that face before the reported time (sampled) while the vertex
    named is on or past it at the enclosure's upper end, inside the face.
Skipped only when MuJoCo is missing.
"""
import os
import sys
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("mujoco")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench"))
import tunnel_scene as ts  # noqa: E402

import polyccd  # noqa: E402


def test_mujoco_misses_the_plate_and_polyccd_reports_the_contact():
    poses, contacts = ts.simulate()
    assert contacts == [0] * ts.STEPS  # MuJoCo: no contact in any step
    reach = float(np.linalg.norm(ts.BULLET)) + ts.PLATE[0]  # origin-to-plate distance for a contact
    crossing = [k for k in range(ts.STEPS) if poses[k][0][0] < 0 < poses[k + 1][0][0]]
    assert len(crossing) == 1
    k = crossing[0]
    assert poses[k][0][0] < -reach and poses[k + 1][0][0] > reach  # clear at both ends: tunnels
    assert all(abs(poses[k][0][a]) + ts.BULLET[1] * 2 < ts.PLATE[a] for a in (1, 2))

    results = dict(ts.polyccd_steps(poses))
    for j, r in results.items():
        if j == k:
            continue
        # the origin moves linearly; it stays beyond reach of the plate the whole step
        assert min(poses[j][0][0], poses[j + 1][0][0]) > reach or \
            max(poses[j][0][0], poses[j + 1][0][0]) < -reach
        assert not r.collides, j
    r = results[k]
    assert r.collides
    fc = r.first_contact
    assert 0 < fc.lo <= fc.hi < 1
    (pair,) = r.pairs
    contact = pair.contacts[0]
    assert contact.a[0] == "vertex" and contact.b[0] == "triangle"
    bv, bf = ts.box_mesh(ts.BULLET)
    pv, pf = ts.box_mesh(ts.PLATE)
    assert all(pv[i][0] == -ts.PLATE[0] for i in pf[contact.b[1]])  # the face x = -0.005

    (p0, q0), (p1, q1) = poses[k], poses[k + 1]
    motion = polyccd.Motion.between((p0.tolist(), q0.tolist()), (p1.tolist(), q1.tolist()))
    face = -F(ts.PLATE[0])
    for s in range(16):  # before the first time no vertex has reached the face
        t = fc.lo * F(s, 16)
        assert all(motion.position(v.tolist(), t)[0] < face for v in bv), t
    x, y, z = motion.position(bv[contact.a[1]].tolist(), fc.hi)
    assert x >= face and abs(y) < F(ts.PLATE[1]) and abs(z) < F(ts.PLATE[2])
