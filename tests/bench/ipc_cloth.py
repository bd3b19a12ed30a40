"""A small IPC-style implicit time stepper (Li et al. 2020, "Incremental Potential Contact",
Algorithm 1) for bench_ipc_loop.py: a mass-spring cloth falling onto a static cube.

Each time step minimises the incremental potential
    E(x) = 1/2 (x - x_hat)^T M (x - x_hat) + h^2 (Psi(x) + kappa B(x)),
x_hat = x_t + h v_t + h^2 g (implicit Euler), Psi the cloth's springs, B ipctk's barrier
potential (activation distance dhat) on the cloth and the cube, kappa from ipctk's
initial_barrier_stiffness / update_barrier_stiffness as the paper adapts it. Newton's
method: the Hessian made positive semi-definite (springs in closed form, the barrier by
ipctk's projection), the direction p = -H^-1 grad E, then the paper's line search: the
step starts at the largest collision-free step size along p (the CCD step: `stepsize`
below, the only thing the two runs of the bench change) and halves until the energy
decreases. It stops when ||p||_inf / h < tol_velocity.

Every accepted update x -> x + alpha p is checked exactly by polyccd.check_step (the
straight path the line search took): a contact on it is a penetration (counted, and the
run goes on so that the count is complete).
"""
import time
from dataclasses import dataclass, field
from typing import Callable, List

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import ipctk
import polyccd


@dataclass
class Scene:
    """The cloth (grid n x n, side `side`, rotated `angle` about z, at height `height`)
    and the cube (side `cube`, centred at the origin): vertices, faces and the cloth's
    springs; the cloth's vertices come first (the unknowns), the cube's after them."""
    rest: np.ndarray
    faces: np.ndarray
    edges: np.ndarray
    springs: np.ndarray
    lengths: np.ndarray
    ncloth: int
    cloth_faces: np.ndarray
    cube_v: np.ndarray
    cube_f: np.ndarray


def cloth_on_cube(n=10, side=1.0, height=0.3, cube=0.5, angle=0.35):
    """The scene: the grid is turned by `angle` so that no cloth vertex lies over a cube
    edge (a generic drop, not a degenerate one)."""
    u = np.linspace(-side / 2, side / 2, n)
    gx, gy = np.meshgrid(u, u, indexing="ij")
    c, s = np.cos(angle), np.sin(angle)
    cloth = np.stack([c * gx - s * gy + 0.013, s * gx + c * gy - 0.021,
                      np.full_like(gx, height)], axis=-1).reshape(-1, 3)
    tri = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, d, e = i * n + j, (i + 1) * n + j, i * n + j + 1, (i + 1) * n + j + 1
            tri += [[a, b, e], [a, e, d]]
    cloth_f = np.array(tri, dtype=np.int32)
    h = cube / 2
    cube_v = np.array([[x, y, z] for x in (-h, h) for y in (-h, h) for z in (-h, h)], float)
    # Faces of the cube's corners (index 4x + 2y + z), outward normals.
    cube_f = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                       [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]],
                      dtype=np.int32)
    rest = np.vstack([cloth, cube_v])
    faces = np.vstack([cloth_f, cube_f + len(cloth)])
    edges = np.asarray(ipctk.edges(faces), dtype=np.int32)
    springs = np.asarray(ipctk.edges(cloth_f), dtype=np.int64)
    lengths = np.linalg.norm(cloth[springs[:, 0]] - cloth[springs[:, 1]], axis=1)
    return Scene(rest, faces, edges, springs, lengths, len(cloth), cloth_f, cube_v, cube_f)


@dataclass
class Params:
    h: float = 0.01           # time step (s)
    steps: int = 50           # time steps
    mass: float = 1.0         # the cloth's mass (kg), lumped equally on its vertices
    k: float = 2000.0         # spring stiffness (N/m)
    gravity: float = 9.81
    dhat: float = 1e-3        # barrier activation distance (m)
    tol_velocity: float = 1e-3  # Newton stops at ||p||_inf / h below this (m/s)
    max_newton: int = 200


@dataclass
class Stats:
    steps: int = 0
    newton: int = 0
    ccd_calls: int = 0
    ccd_cpu: float = 0.0      # CPU seconds inside `stepsize`
    total_cpu: float = 0.0
    total_wall: float = 0.0
    ccd_steps: List[float] = field(default_factory=list)    # the CCD step of each iteration
    accepted: List[float] = field(default_factory=list)     # the line search's alpha
    penetrations: int = 0     # accepted updates on which polyccd found a contact
    min_distance: float = np.inf  # smallest distance at the end of a Newton update


def _springs(x, sc, k):
    """Energy, gradient (n*3) and PSD-projected Hessian (sparse) of the springs
    1/2 k (|xi - xj| - L)^2: per spring K = k (u u^T + max(0, 1 - L/l) (I - u u^T)),
    the exact Hessian with its negative eigenvalue (compression) clamped to 0."""
    i, j = sc.springs[:, 0], sc.springs[:, 1]
    d = x[i] - x[j]
    ln = np.linalg.norm(d, axis=1)
    u = d / ln[:, None]
    stretch = ln - sc.lengths
    energy = 0.5 * k * np.sum(stretch ** 2)
    f = (k * stretch)[:, None] * u
    grad = np.zeros_like(x)
    np.add.at(grad, i, f)
    np.add.at(grad, j, -f)
    uu = u[:, :, None] * u[:, None, :]
    w = np.maximum(0.0, 1.0 - sc.lengths / ln)[:, None, None]
    K = k * (uu + w * (np.eye(3)[None] - uu))
    rows, cols, vals = [], [], []
    for a, b, sign in ((i, i, 1), (j, j, 1), (i, j, -1), (j, i, -1)):
        r = (3 * a)[:, None, None] + np.arange(3)[None, :, None] + np.zeros((1, 1, 3), int)
        c = (3 * b)[:, None, None] + np.zeros((1, 3, 1), int) + np.arange(3)[None, None, :]
        rows.append(r.ravel())
        cols.append(c.ravel())
        vals.append((sign * K).ravel())
    n3 = 3 * len(x)
    H = sp.csc_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(n3, n3))
    return energy, grad.ravel(), H


class Stepper:
    """Runs the scene with one CCD step-size source: stepsize(V0, V1) -> alpha in [0, 1]
    for the whole collision mesh (cloth then cube) moving linearly from V0 to V1."""

    def __init__(self, sc: Scene, prm: Params, stepsize: Callable):
        self.sc, self.prm, self.stepsize = sc, prm, stepsize
        self.mesh = ipctk.CollisionMesh(sc.rest, sc.edges, sc.faces)
        self.barrier = ipctk.BarrierPotential(prm.dhat, 1.0)  # times kappa here
        self.diag = ipctk.world_bbox_diagonal_length(sc.rest)
        self.m = prm.mass / sc.ncloth
        self.nc = sc.ncloth
        self.kappa = None
        self.kappa_max = None
        self.stats = Stats()

    def _full(self, xc):
        return np.vstack([xc, self.sc.cube_v])

    def _collisions(self, V):
        c = ipctk.NormalCollisions()
        c.build(self.mesh, V, self.prm.dhat)
        return c

    def energy(self, xc, xhat):
        V = self._full(xc)
        e_s, _, _ = _springs(xc, self.sc, self.prm.k)
        c = self._collisions(V)
        b = self.barrier(c, self.mesh, V) if len(c) else 0.0
        dx = (xc - xhat).ravel()
        return 0.5 * self.m * dx @ dx + self.prm.h ** 2 * (e_s + self.kappa * b)

    def _barrier_terms(self, V):
        c = self._collisions(V)
        n3 = 3 * self.nc
        if not len(c):
            return c, np.zeros(n3), sp.csc_matrix((n3, n3))
        g = np.asarray(self.barrier.gradient(c, self.mesh, V))[:n3]
        H = self.barrier.hessian(c, self.mesh, V, ipctk.PSDProjectionMethod.CLAMP)[:n3, :n3]
        return c, g, H

    def _init_kappa(self, xc, xhat):
        """kappa as IPC sets it: ipctk.initial_barrier_stiffness from the energy's and the
        barrier's gradients at the start (kept >= its minimum when nothing is close)."""
        V = self._full(xc)
        _, g_s, _ = _springs(xc, self.sc, self.prm.k)
        g_e = self.m * (xc - xhat).ravel() / self.prm.h ** 2 + g_s
        _, g_b, _ = self._barrier_terms(V)
        full = np.zeros(3 * len(V))
        full_b = np.zeros(3 * len(V))
        full[:3 * self.nc], full_b[:3 * self.nc] = g_e, g_b
        self.kappa, self.kappa_max = ipctk.initial_barrier_stiffness(
            self.diag, self.barrier.barrier, self.prm.dhat, self.m, full, full_b)

    def _checked_move(self, x0, x1):
        """Counts a contact on the straight path x0 -> x1, decided exactly by polyccd."""
        r = polyccd.check_step(x0, x1, self.sc.cloth_faces,
                               obstacles=[(self.sc.cube_v, self.sc.cube_f)], first_contact=False)
        if r.collides:
            self.stats.penetrations += 1

    def time_step(self, x, v):
        prm, st = self.prm, self.stats
        xhat = x + prm.h * v + prm.h ** 2 * np.array([0.0, 0.0, -prm.gravity])
        xc = x.copy()
        if self.kappa is None:
            self._init_kappa(xc, xhat)
        n3 = 3 * self.nc
        M = sp.identity(n3, format="csc") * self.m
        prev_d = None
        for _ in range(prm.max_newton):
            V = self._full(xc)
            e_s, g_s, H_s = _springs(xc, self.sc, prm.k)
            c, g_b, H_b = self._barrier_terms(V)
            grad = self.m * (xc - xhat).ravel() + prm.h ** 2 * (g_s + self.kappa * g_b)
            H = M + prm.h ** 2 * (H_s + self.kappa * H_b)
            p = -spla.spsolve(H.tocsc(), grad).reshape(-1, 3)
            st.newton += 1
            if np.max(np.abs(p)) / prm.h < prm.tol_velocity:
                break
            V1 = self._full(xc + p)
            t = time.process_time()
            alpha = min(1.0, float(self.stepsize(V, V1)))
            st.ccd_cpu += time.process_time() - t
            st.ccd_calls += 1
            st.ccd_steps.append(alpha)
            e0 = self.energy(xc, xhat)
            while alpha > 1e-12 and not self.energy(xc + alpha * p, xhat) <= e0:
                alpha /= 2  # the paper's backtracking: halve until the energy decreases
            if alpha <= 1e-12:
                break  # no decrease along p (converged to round-off)
            st.accepted.append(alpha)
            x_new = xc + alpha * p
            self._checked_move(xc, x_new)
            xc = x_new
            c = self._collisions(self._full(xc))
            d = c.compute_minimum_distance(self.mesh, self._full(xc)) if len(c) else np.inf
            st.min_distance = min(st.min_distance, d)
            if prev_d is not None and np.isfinite(d):
                self.kappa = ipctk.update_barrier_stiffness(prev_d, d, self.kappa_max, self.kappa,
                                                           self.diag)
            prev_d = d if np.isfinite(d) else None
        st.steps += 1
        return xc, (xc - x) / prm.h

    def run(self):
        x = self.sc.rest[:self.nc].copy()
        v = np.zeros_like(x)
        wall, cpu = time.perf_counter(), time.process_time()
        for _ in range(self.prm.steps):
            x, v = self.time_step(x, v)
        self.stats.total_wall = time.perf_counter() - wall
        self.stats.total_cpu = time.process_time() - cpu
        return x, self.stats


def ipctk_stepsize(mesh):
    """ipctk.compute_collision_free_stepsize with its defaults (Tight Inclusion,
    tolerance 1e-6, conservative rescaling 0.8)."""
    return lambda V0, V1: ipctk.compute_collision_free_stepsize(mesh, V0, V1)


def polyccd_stepsize(sc, scale=0.8):
    """scale * polyccd.collision_free_stepsize (the largest double <= the exact first
    contact time; the cube as a static obstacle), 1.0 without contact: scale 0.8 keeps the same gap that
    ipctk's conservative rescaling keeps, so the two runs differ only in the time they
    scale (Tight Inclusion's enclosure vs the exact one)."""
    nc, cf, obst = sc.ncloth, sc.cloth_faces, [(sc.cube_v, sc.cube_f)]

    def stepsize(V0, V1):
        s = polyccd.collision_free_stepsize(np.ascontiguousarray(V0[:nc]),
                                            np.ascontiguousarray(V1[:nc]), cf, obstacles=obst)
        return 1.0 if s == 1.0 else scale * s  # 1.0: no contact (a contact at t = 1 is
        # left to the line search, whose energy is infinite there)
    return stepsize
