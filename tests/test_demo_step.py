"""The simulator part of `polyccd demo` (polyccd.apps._demo_step): the cloth step finds
its first contact, the picture is written, and each first vertex-face contact is
confirmed with Fractions: at the exact time the vertex lies in its face's closed
triangle (an exact barycentric test written here). check_step itself is checked
against brute force in tests/test_step.py."""
from fractions import Fraction as F

import numpy as np
import pytest

pytest.importorskip("matplotlib")
from polyccd.apps._demo_step import ball, cloth, run_step_demo  # noqa: E402


def at(v0, v1, i, t):
    return [F(a) + t * (F(b) - F(a)) for a, b in zip(v0[i], v1[i])]


def inside(p, a, b, c):
    """p in the closed triangle abc (exact): coplanar and on the inner side of each edge."""
    sub = lambda u, v: [x - y for x, y in zip(u, v)]
    cross = lambda u, v: [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    dot = lambda u, v: sum(x * y for x, y in zip(u, v))
    n = cross(sub(b, a), sub(c, a))
    if dot(n, sub(p, a)) != 0:
        return False
    return all(dot(n, cross(sub(q, o), sub(p, o))) >= 0 for o, q in ((a, b), (b, c), (c, a)))


def test_cloth_step_demo(tmp_path):
    lines = []
    r, seconds, png = run_step_demo(tmp_path, threads=2, out=lines.append)
    assert r.collides and r.first_contact.exact is not None and png.is_file()
    assert float(r.first_contact.exact) == pytest.approx(0.05, abs=0.01)
    v0, v1, faces = cloth()
    bv, bf = ball()
    meshes = {0: (v0, v1, faces), 1: (bv, bv, bf)}
    t = r.first_contact.exact
    checked = 0
    for kind, (ma, a, mb, b) in zip(r.contacts.kind, r.contacts.indices):
        if kind != "vertex-face":
            continue
        va, wa, _ = meshes[ma]
        vb, wb, fb = meshes[mb]
        p = at(va, wa, a, t)
        tri = [at(vb, wb, k, t) for k in fb[b]]
        assert inside(p, *tri), (kind, ma, a, mb, b)
        checked += 1
    assert checked >= 1
    assert any("first contact at exactly t =" in line for line in lines)
