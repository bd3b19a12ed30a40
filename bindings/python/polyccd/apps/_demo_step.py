"""The simulator part of `polyccd demo`: one time step of a cloth falling onto a ball,
checked exactly as a whole (polyccd.check_step), with the first contact drawn.

The cloth is a 40 x 40 grid of 3,042 triangles, 1/20 apart, with a gentle ripple; in one
step every vertex falls by 0.9 and the middle sags 0.3 further (so the cloth reaches the
ball at its centre first). The ball is a sphere of radius 1/2 centred at the origin,
refined from an octahedron (a static obstacle mesh). Every vertex-face and edge-edge
pair of the cloth with itself and with the ball is decided exactly; the step size is the
largest double not above the exact first contact time.
"""
import time

import numpy as np

from .. import Body, Mesh, Motion, check_step

N = 40            # grid vertices per side
SPACING = 1 / 20  # grid spacing (the cloth spans 1.95 x 1.95)


def cloth():
    """(V0, V1, faces) of the falling cloth step."""
    u = (np.arange(N) - (N - 1) / 2) * SPACING
    x, y = np.meshgrid(u, u, indexing="ij")
    z0 = 0.56 + 0.01 * np.sin(3 * x) * np.cos(2 * y)
    sag = 0.9 + 0.3 * np.exp(-(x ** 2 + y ** 2) / 0.3)
    v0 = np.stack([x, y, z0], axis=-1).reshape(-1, 3)
    v1 = v0 - np.stack([0 * x, 0 * y, sag], axis=-1).reshape(-1, 3)
    idx = np.arange(N * N).reshape(N, N)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                            np.stack([a, c, d], -1).reshape(-1, 3)])
    return v0, v1, faces


def ball(radius=0.5, levels=3):
    """(vertices, faces) of an octahedron refined `levels` times, projected on the sphere."""
    v = [np.array(p, float) for p in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1))]
    f = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(levels):
        mid, out = {}, []

        def middle(i, j):
            key = (min(i, j), max(i, j))
            if key not in mid:
                mid[key] = len(v)
                m = v[i] + v[j]
                v.append(m / np.linalg.norm(m))
            return mid[key]
        for i, j, k in f:
            a, b, c = middle(i, j), middle(j, k), middle(k, i)
            out += [(i, a, c), (a, j, b), (c, b, k), (a, b, c)]
        f = out
    return np.array(v) * radius, np.array(f)


def run_step_demo(out_dir="build/demo", *, threads=2, out=print):
    """Checks the step and draws it; returns (StepResult, seconds, png path or None)."""
    v0, v1, faces = cloth()
    bv, bf = ball()
    start = time.perf_counter()
    r = check_step(v0, v1, faces, obstacles=[(bv, bf)], threads=threads)
    seconds = time.perf_counter() - start
    out(f"simulator step: a cloth of {len(faces)} triangles falling onto a ball of "
        f"{len(bf)} triangles, every primitive pair of the step checked exactly")
    if not r.collides:
        out(f"  no contact during the step ({seconds * 1000:.1f} ms)")
        return r, seconds, None
    t = r.first_contact
    when = f"exactly t = {t.exact}" if t.exact is not None else f"t in [{float(t.lo):.12f}, {float(t.hi):.12f}]"
    out(f"  first contact at {when} ({seconds * 1000:.1f} ms, {r.stats['candidates']} "
        f"candidate pairs solved); largest safe step {r.stepsize!r}")
    for k in range(min(len(r.contacts), 4)):
        out(f"  {r.contacts.kind[k]}: {tuple(int(i) for i in r.contacts.indices[k])}")
    path = None
    try:
        path = _draw(v0, v1, faces, bv, bf, r, out_dir)
        out(f"  picture: {path}")
    except ModuleNotFoundError as e:
        out(f"  (no picture: {e})")
    return r, seconds, path


def _draw(v0, v1, faces, bv, bf, r, out_dir):
    """The cloth at the first contact (float positions: drawing only) over the ball, the
    first contact's vertices and faces in red (an edge by its two end vertices)."""
    from pathlib import Path
    from ._render import render_scene
    t = float(r.first_contact.lo)
    bodies = [Body(Mesh(v0 + t * (v1 - v0), faces), Motion(), name="cloth"),
              Body(Mesh(bv, bf), Motion(), name="ball")]
    marks = []
    for kind, (ma, a, mb, b) in zip(r.contacts.kind, r.contacts.indices):
        for mesh, feature, k in ((ma, kind.split("-")[0], a), (mb, kind.split("-")[1], b)):
            if feature == "face":
                marks.append((int(mesh), ("triangle", int(k))))
            elif feature == "vertex":
                marks.append((int(mesh), ("vertex", int(k))))
            else:
                marks += [(int(mesh), ("vertex", int(e))) for e in r.edges[mesh][k]]
    path = Path(out_dir) / "scene_cloth_step.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    return render_scene(bodies, t, marks, path, title=f"cloth step: first contact at t = {t:.6f}",
                        trajectories=False)
