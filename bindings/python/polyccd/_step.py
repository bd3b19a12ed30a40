"""Whole simulator steps of deforming meshes (pccd_step_*): check_step and
collision_free_stepsize. Vertices move on straight paths from V0 (t = 0) to V1 (t = 1),
or on polynomial paths (paths=: power-basis coefficients), float64 arrays taken at their
exact values; every answer comes from the C library."""
import threading
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Optional, Sequence

import numpy as np

from . import _handles as handles
from . import _limits
from ._arrays import _float64_array, _no_bools
from ._body import _indices
from ._errors import InputError, check
from ._flags import flag
from ._pccd import ffi, lib
from ._results import ContactTime
from ._solve import _config, _items
from ._types import Indices, Number, Points

KIND_NAMES = {0: "vertex-face", 1: "edge-edge", 2: "vertex-edge", 3: "vertex-vertex"}


@dataclass(frozen=True)
class StepContacts:
    """Touching primitive pairs, one entry each: kind (str array: vertex-face,
    edge-edge, vertex-edge, vertex-vertex), indices (int64 (n, 4): mesh of a, a, mesh of
    b, b; mesh 0 is the step's mesh, obstacles[k] is mesh k + 1; a is a vertex, or an
    edge for edge-edge; b a face, edge or vertex as the kind says; edges numbered as
    StepResult.edges gives them), and the pair's own first time, lo <= t <= hi (doubles
    rounded outward; NaN in decide mode) with exact (bool)."""
    kind: np.ndarray
    indices: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    exact: np.ndarray

    def __len__(self):
        return len(self.kind)


@dataclass(frozen=True)
class StepResult:
    """collides: does anything touch during [0, 1]; first_contact: the exact first
    contact time (None without contact or in decide mode); stepsize: the largest double
    <= that time, 1.0 when nothing touches (None in decide mode); contacts: the pairs
    touching first (every touching pair with all_contacts; some touching pairs in decide
    mode); stats: broad-phase queries, candidate pairs solved, re-solves, and solved
    pairs by deciding stage; edges: the edge list of each mesh ((m, 2) int64)."""
    collides: bool
    first_contact: Optional[ContactTime]
    stepsize: Optional[float]
    contacts: StepContacts
    stats: dict = field(repr=False)
    edges: tuple = field(repr=False)


def _positions(where, v0, v1):
    """float64 (n, 3) arrays of V0, V1; messages name them as the C library does: v_t0, v_t1."""
    a0 = _float64_array(v0, f"{where}v_t0", "(n, 3)", lambda s: len(s) == 2 and s[1] == 3)
    a1 = _float64_array(v1, f"{where}v_t1", "(n, 3)", lambda s: len(s) == 2 and s[1] == 3)
    if a0.shape != a1.shape:
        raise InputError(f"{where}v_t1: expected shape {a0.shape} like v_t0, got {a1.shape}")
    return a0, a1


def _checked(where, rc):
    """check(rc), with `where` (an obstacle's place) before the C message's place."""
    if rc != 0 and where:
        try:
            check(rc)
        except InputError as err:
            raise type(err)(f"{where}{err}") from None
    check(rc)


def _mesh(step, where, v0, v1, faces, edges, points, cfg):
    """Adds one mesh to the step handle; InputError names its place with `where`."""
    a0, a1 = _positions(where, v0, v1)
    nf, f = _indices(np.zeros((0, 3), np.uint32) if faces is None else faces, f"{where}faces", 3)
    ne, e = (0, None) if edges is None else _indices(edges, f"{where}edges", 2)
    n_p, p = (0, None) if points is None else _points(points, f"{where}points")
    out = ffi.new("size_t *")
    rc = _limits.run(cfg, lib.pccd_step_add_mesh_cfg_d, step, ffi.from_buffer("double[]", a0),
                     ffi.from_buffer("double[]", a1), len(a0), ffi.from_buffer("unsigned int[]", f),
                     nf, ffi.NULL if e is None else ffi.from_buffer("unsigned int[]", e), ne,
                     ffi.NULL if p is None else ffi.from_buffer("unsigned int[]", p), n_p, out, cfg)
    _checked(where, rc)
    return out[0]


def _points(points, where):
    """(n, uint32 array) of a 1-D sequence of vertex indices, or InputError naming the entry."""
    if isinstance(points, (str, bytes, dict, set, frozenset)):
        raise InputError(f"{where}: expected a 1-D sequence of integer vertex indices")
    try:
        a = np.asarray(points)
    except (ValueError, TypeError):  # ragged
        raise InputError(f"{where}: expected a 1-D sequence of integer vertex indices") from None
    if a.ndim == 1 and a.dtype.kind in "iub" and not isinstance(points, np.ndarray):
        _no_bools(points, a.shape, where)
    if a.ndim != 1 or (a.size and a.dtype.kind not in "iu"):
        raise InputError(f"{where}: expected a 1-D sequence of integer vertex indices")
    bad = np.flatnonzero((a < 0) | (a > 2 ** 32 - 1)) if a.size else []
    if len(bad):
        raise InputError(f"{where}[{bad[0]}]: index {int(a[bad[0]])} is not a valid 0-based index")
    return len(a), np.ascontiguousarray(a, dtype=np.uint32)


def _obstacle(k, ob):
    """(V0, V1, faces) of obstacles[k]: (V, faces) static, or (V0, V1, faces) moving."""
    if not isinstance(ob, (tuple, list)) or len(ob) not in (2, 3):
        raise InputError(f"obstacles[{k}]: expected (V, faces) or (V0, V1, faces), got "
                         f"{type(ob).__name__}")
    return (ob[0], ob[0], ob[1]) if len(ob) == 2 else tuple(ob)


def _topology(faces, edges, points, sizes, obs_faces):
    """A key of the connectivity (or None when it cannot be hashed cheaply)."""
    parts = [faces, edges, points] + list(obs_faces)
    if not all(x is None or isinstance(x, np.ndarray) for x in parts):
        return None
    return (tuple(sizes),) + tuple(None if x is None else (x.dtype.str, x.shape, x.tobytes()) for x in parts)


_cache = threading.local()  # the last step handle of this thread, by topology


def _build(V0, V1, faces, edges, points, obstacles, cfg):
    """A step handle of the mesh and obstacles. A simulator calls with the same
    connectivity every step: then the last handle of this thread is reused, only its
    positions replaced (pccd_step_set_positions_d checks them as adding would)."""
    obstacles = _items(obstacles, "obstacles", "a sequence of (V, faces) or (V0, V1, faces)")
    obs = [_obstacle(k, ob) for k, ob in enumerate(obstacles)]
    try:
        sizes = [len(V0)] + [len(o[0]) for o in obs]
    except TypeError:
        sizes = None
    key = None if sizes is None else _topology(faces, edges, points, sizes, [o[2] for o in obs])
    hit = getattr(_cache, "last", None)
    if key is not None and hit is not None and hit[0] == key:
        step = hit[1]
        for m, (where, p0, p1) in enumerate([("", V0, V1)] + [(f"obstacles[{k}].", o[0], o[1])
                                                             for k, o in enumerate(obs)]):
            a0, a1 = _positions(where, p0, p1)
            _checked(where, lib.pccd_step_set_positions_d(step, m, ffi.from_buffer("double[]", a0),
                                                          ffi.from_buffer("double[]", a1), len(a0)))
        return step, len(obs) + 1
    step = handles.new("step")
    _mesh(step, "", V0, V1, faces, edges, points, cfg)  # under the call's limits
    for k, (o0, o1, of) in enumerate(obs):
        _mesh(step, f"obstacles[{k}].", o0, o1, of, None, None, cfg)
    for i in range(1, len(obs) + 1):  # obstacles: against the mesh only
        for j in range(i, len(obs) + 1):
            check(lib.pccd_step_set_pair_check(step, i, j, 0))
    if key is not None:
        _cache.last = (key, step)
    return step, len(obs) + 1


def _time(rep):
    def text(which):
        needed = ffi.new("size_t *")
        lib.pccd_step_report_time(rep, which, ffi.NULL, 0, needed)
        buf = ffi.new("char[]", needed[0])
        check(lib.pccd_step_report_time(rep, which, buf, needed[0], needed))
        return Fraction(ffi.string(buf).decode())
    exact = ffi.new("int *")
    lo_d, hi_d = ffi.new("double *"), ffi.new("double *")
    check(lib.pccd_step_report_time_info(rep, exact, lo_d, hi_d))
    lo, hi = text(0), text(1)
    return ContactTime(lo, hi, lo if exact[0] else None, float((lo + hi) / 2))


def _contacts(rep):
    n = ffi.new("size_t *")
    check(lib.pccd_step_report_contact_count(rep, n))
    n = n[0]
    kind = np.zeros(n, dtype=np.intc)
    index = np.zeros((n, 4), dtype=np.uintp)
    lo, hi = np.empty(n), np.empty(n)
    exact = np.zeros(n, dtype=np.uint8)
    if n:
        check(lib.pccd_step_report_contacts(
            rep, 0, n, ffi.from_buffer("int[]", kind), ffi.from_buffer("size_t[]", index),
            ffi.from_buffer("double[]", lo), ffi.from_buffer("double[]", hi),
            ffi.from_buffer("unsigned char[]", exact)))
    names = np.array([KIND_NAMES[k] for k in kind.tolist()], dtype=object)
    return StepContacts(names, index.astype(np.int64), lo, hi, exact.astype(bool))


def _edges(step, nmeshes):
    out = []
    for m in range(nmeshes):
        ne = ffi.new("size_t *")
        check(lib.pccd_step_mesh_counts(step, m, ffi.NULL, ffi.NULL, ne, ffi.NULL))
        rows = np.zeros((ne[0], 2), dtype=np.uintp)
        if ne[0]:
            check(lib.pccd_step_edges(step, m, 0, ne[0], ffi.from_buffer("size_t[]", rows)))
        out.append(rows.astype(np.int64))
    return tuple(out)


def _paths(paths, V0, V1):
    """float64 (k, n, 3) coefficients of paths= (C: coeffs), with V0 and V1 None."""
    if V0 is not None or V1 is not None:
        raise InputError("paths: give V0 and V1 as None with paths (the paths replace them)")
    return _float64_array(paths, "coeffs", "(k, n, 3)", lambda s: len(s) == 3 and s[2] == 3 and s[0] >= 1)


def _solve(V0, V1, faces, edges, points, obstacles, min_distance, mode, threads, limits,
           time_tolerance="1e-12", paths=None):
    threads = _limits.thread_count(1 if threads is None else threads)  # C checks the range
    _limits.warn_threads(threads)
    c = None if paths is None else _paths(paths, V0, V1)
    if c is not None:
        V0 = V1 = c[0]  # the topology's mesh; its paths are set below
    cfg, _keep = _config(time_tolerance, True, True, limits,
                         None if min_distance is None or (type(min_distance) in (int, float)
                                                          and min_distance == 0) else min_distance)
    step, nmeshes = _build(V0, V1, faces, edges, points, obstacles, cfg)
    if c is not None:
        check(lib.pccd_step_set_paths_d(step, 0, ffi.from_buffer("double[]", c), c.shape[0], c.shape[1]))
    opt = ffi.new("pccd_step_options *")
    check(lib.pccd_step_options_init(opt))
    opt.threads, opt.mode = threads, mode
    rep = handles.new("step_report")
    check(_limits.run(cfg, lib.pccd_step_solve, step, cfg, opt, rep))
    return step, nmeshes, rep


def check_step(V0: Points, V1: Points, faces: Indices, edges: Optional[Indices] = None, *,
               points: Optional[Sequence[int]] = None, obstacles: Sequence[tuple] = (),
               min_distance: Number = 0, first_contact: bool = True,
               threads: Optional[int] = None, limits: Optional[_limits.Limits] = None,
               all_contacts: bool = False, paths: Optional[np.ndarray] = None) -> StepResult:
    """Checks one simulator step exactly: vertex i moves on a straight path from V0[i]
    (t = 0) to V1[i] (t = 1), float64 (n, 3) arrays at their exact values; faces (m, 3)
    and edges (k, 2) are vertex indices (edges=None: the sides of the faces), points
    the isolated vertices (particles). Every vertex-face pair (vertex not in the face),
    edge-edge pair (no shared vertex) and point pair of the mesh itself and against each
    obstacle ((V, faces) static, or (V0, V1, faces) moving; obstacles are not checked
    against each other) is decided exactly over [0, 1]; min_distance > 0 counts a pair
    within that distance as touching. first_contact=False only decides whether
    anything touches (cheaper: it stops at the first contacts found); all_contacts=True
    reports every touching pair with its own first time. threads (default 1) never
    changes an answer. paths (with V0 = V1 = None): polynomial paths instead, float64
    coefficients of shape (k, n, 3), vertex i at sum_j paths[j, i] t^j (1 <= k <= 8),
    solved by the general exact solver. Errors name V0, V1, paths as v_t0, v_t1, coeffs
    (the C arguments), e.g. "obstacles[0].v_t1[4][2]: NaN is not a finite number".
    Returns a StepResult."""
    mode = 2 if flag(all_contacts, "all_contacts") else (0 if flag(first_contact, "first_contact") else 1)
    step, nmeshes, rep = _solve(V0, V1, faces, edges, points, obstacles, min_distance, mode,
                                threads, limits, paths=paths)
    hit = ffi.new("int *")
    check(lib.pccd_step_report_collides(rep, hit))
    stats = ffi.new("pccd_step_stats *")
    check(lib.pccd_step_report_stats(rep, stats))
    stat = {"queries": stats.queries, "candidates": stats.candidates, "refined": stats.refined,
            "by_stage": tuple(stats.by_stage)}
    stepsize = None
    if mode != 1:
        s = ffi.new("double *")
        check(lib.pccd_step_report_stepsize(rep, s))
        stepsize = s[0]
    time = _time(rep) if hit[0] and mode != 1 else None
    return StepResult(bool(hit[0]), time, stepsize, _contacts(rep), stat, _edges(step, nmeshes))


def collision_free_stepsize(V0: Points, V1: Points, faces: Indices, edges: Optional[Indices] = None,
                            *, points: Optional[Sequence[int]] = None, obstacles: Sequence[tuple] = (),
                            min_distance: Number = 0, threads: Optional[int] = None,
                            limits: Optional[_limits.Limits] = None,
                            paths: Optional[np.ndarray] = None) -> float:
    """The largest double s <= t*, the exact first contact time of the step V0 -> V1
    (check_step), 1.0 when nothing touches: moving every vertex to V0 + s (V1 - V0) is
    free of contact at every time before s. Unlike ipctk's compute_collision_free_stepsize,
    whose value is a conservative fraction of Tight Inclusion's time (with its
    tolerance, it may stop well short of the contact, or report a contact that is a near
    miss), this is the exact time rounded down to a double; a caller that wants a gap
    scales it (e.g. 0.8 s), or asks for a min_distance. paths: as check_step."""
    _, _, rep = _solve(V0, V1, faces, edges, points, obstacles, min_distance, 0, threads, limits,
                       paths=paths)
    s = ffi.new("double *")
    check(lib.pccd_step_report_stepsize(rep, s))
    return s[0]
