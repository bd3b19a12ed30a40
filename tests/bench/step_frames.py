"""Frames of a real simulator for bench_step.py: a MuJoCo flex cloth (a square grid of
n x n cells, 2 n^2 triangles, self-collision on) falling onto a sphere above a floor.

MuJoCo (PyPI `mujoco`, tests/bench/requirements.txt) steps the model; the flex vertex
positions at steps k and k + 1 (data.flexvert_xpos) are one step V0 -> V1. The sphere
and the floor are static obstacle meshes: an icosphere inscribed in the sphere geom (its
vertices on the sphere, so the polyhedron lies inside what MuJoCo's contacts keep the
cloth out of) and two triangles of the floor plane. Frames are cached in
build/step_frames/ (npz per resolution), since the 100k-triangle model steps slowly.
"""
import os
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
CACHE = ROOT / "build" / "step_frames"
SPHERE_R, SPHERE_Z, CLOTH_Z = 0.25, 0.3, 0.6
# Steps recorded (2 ms each): free fall, first contact with the sphere (about step 60
# from a drop of 5 cm... the cloth's corners keep falling), and draped over the ball.
PHASES = {"falling": 10, "impact": 90, "draped": 240}


def cloth_xml(n):
    sp = 1.0 / n
    return f"""
<mujoco>
  <option timestep="0.002" integrator="implicitfast"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <geom name="ball" type="sphere" size="{SPHERE_R}" pos="0 0 {SPHERE_Z}"/>
    <flexcomp name="cloth" type="grid" count="{n + 1} {n + 1} 1" spacing="{sp} {sp} {sp}"
              pos="0 0 {CLOTH_Z}" radius="0.002" dim="2" mass="0.2">
      <contact selfcollide="auto" condim="3" solref="0.005 1"/>
      <edge equality="true" damping="0.001"/>
    </flexcomp>
  </worldbody>
</mujoco>"""


def icosphere(radius, center, subdiv=3):
    """Vertices (on the sphere) and triangles of a subdivided icosahedron."""
    t = (1 + 5 ** 0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t],
         [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    v = [list(np.array(p) / np.linalg.norm(p)) for p in v]
    for _ in range(subdiv):
        mid, nf = {}, []
        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                p = (np.array(v[a]) + np.array(v[b])) / 2
                v.append(list(p / np.linalg.norm(p)))
                mid[key] = len(v) - 1
            return mid[key]
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        f = nf
    # Inscribed: every vertex exactly representable is not needed; it stays inside the
    # ball up to rounding (shrunk by 1e-9 relative to be sure).
    return np.array(v) * radius * (1 - 1e-9) + np.array(center), np.array(f, dtype=np.int64)


def obstacles():
    sphere = icosphere(SPHERE_R, [0, 0, SPHERE_Z])
    floor = (np.array([[-2.0, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]),
             np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64))
    return [sphere, floor]


def simulate(n, phases=PHASES):
    """{phase: (V0, V1)} and the cloth's triangles, from MuJoCo."""
    import mujoco
    model = mujoco.MjModel.from_xml_string(cloth_xml(n))
    data = mujoco.MjData(model)
    adr, num = model.flex_elemadr[0], model.flex_elemnum[0]
    faces = model.flex_elem[3 * adr:3 * (adr + num)].reshape(-1, 3).astype(np.int64)
    want = {k: p for p, k in phases.items()}
    frames, prev = {}, None
    start = time.time()
    for k in range(max(want) + 2):
        x = np.array(data.flexvert_xpos, dtype=np.float64)
        if k - 1 in want:
            frames[want[k - 1]] = (prev, x)
        prev = x
        mujoco.mj_step(model, data)
    return frames, faces, time.time() - start


def load(n):
    """The frames of resolution n (cached): {phase: (V0, V1)}, faces, obstacles."""
    CACHE.mkdir(parents=True, exist_ok=True)
    path = CACHE / f"cloth_{n}.npz"
    if not path.exists():
        frames, faces, secs = simulate(n)
        arrays = {"faces": faces, "sim_seconds": np.array(secs)}
        for p, (a, b) in frames.items():
            arrays[f"{p}_V0"], arrays[f"{p}_V1"] = a, b
        tmp = path.with_suffix(".tmp.npz")
        np.savez(tmp, **arrays)
        os.replace(tmp, path)
    z = np.load(path)
    frames = {p: (z[f"{p}_V0"], z[f"{p}_V1"]) for p in PHASES if f"{p}_V0" in z}
    return frames, z["faces"], obstacles()


def grid_faces(n):
    """Triangles of an (n + 1) x (n + 1) vertex grid, vertex i (n + 1) + j, as MuJoCo's
    flexcomp grid numbers them."""
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    a = (i * (n + 1) + j).ravel()
    b, c, d = a + n + 2, a + 1, a + n + 1
    return np.concatenate([np.stack([a, b, c], 1), np.stack([a, d, b], 1)]).astype(np.int64)


def upsampled(frames, n_src, n_dst):
    """The frames of an n_src cloth resampled (bilinear in the grid parameters) onto an
    n_dst grid: a finer mesh on the same simulated surfaces, for sizes MuJoCo steps too
    slowly here (the 100k-triangle model)."""
    u = np.linspace(0, n_src, n_dst + 1)
    i0 = np.minimum(np.floor(u).astype(int), n_src - 1)
    w = (u - i0)[:, None, None]
    out = {}
    for phase, (a, b) in frames.items():
        pair = []
        for X in (a, b):
            G = X.reshape(n_src + 1, n_src + 1, 3)
            rows = G[i0] * (1 - w) + G[i0 + 1] * w                       # along i
            cols = rows[:, i0] * (1 - w.transpose(1, 0, 2)) + rows[:, i0 + 1] * w.transpose(1, 0, 2)
            pair.append(np.ascontiguousarray(cols.reshape(-1, 3)))
        out[phase] = tuple(pair)
    return out, grid_faces(n_dst)
