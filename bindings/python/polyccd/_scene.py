"""Scenes: bodies on motions, checked exactly (bindings/python/API.md, "Scenes").

Only conversion here: the scene is built in C (pccd_scene), solved there
(pccd_scene_solve) and read back from the pccd_report. Scene files are read by
polyccd.apps._scene_file.
"""
from dataclasses import dataclass, field
from typing import Optional, Tuple

import numpy as np

from . import _handles as handles
from ._body import Mesh, Spheres
from ._errors import InputError, check
from ._motion import Motion
from ._numbers import fraction_from_text, show
from ._pccd import ffi, lib
from ._results import ContactTime
from ._solve import _config, _items

FEATURES = ("vertex", "edge", "triangle", "sphere")
BROAD_PHASES = {"auto": lib.PCCD_BROAD_AUTO, "boxes": lib.PCCD_BROAD_BOXES,
                "brute": lib.PCCD_BROAD_BRUTE, "range": lib.PCCD_BROAD_RANGE,
                "bvh": lib.PCCD_BROAD_BVH}


class Body:
    """A rigid body (Mesh or Spheres) on a Motion (None: stationary), with a name."""

    __slots__ = ("shape", "motion", "name")

    def __init__(self, shape, motion=None, name=None):
        if not isinstance(shape, (Mesh, Spheres)):
            raise InputError(f"shape: expected a polyccd.Mesh or polyccd.Spheres, got {show(shape)}")
        if motion is not None and not isinstance(motion, Motion):
            raise InputError(f"motion: expected a polyccd.Motion or None, got {show(motion)}")
        if name is not None and not isinstance(name, str):
            raise InputError(f"name: expected a string or None, got {show(name)}")
        object.__setattr__(self, "shape", shape)
        object.__setattr__(self, "motion", motion)
        object.__setattr__(self, "name", name)

    def __setattr__(self, name, value):
        raise AttributeError("a Body cannot be changed; make a new one")

    def __reduce__(self):
        """Pickles as (shape, motion, name), each pickled as its exact inputs."""
        return Body, (self.shape, self.motion, self.name)

    def __repr__(self):
        return f"Body({type(self.shape).__name__}, name={self.name!r})"


@dataclass(frozen=True)
class Contact:
    """A feature of body i and one of body j touching, with that pair's first time."""
    a: Tuple[str, int]
    b: Tuple[str, int]
    first_contact: ContactTime


@dataclass(frozen=True)
class PairResult:
    bodies: Tuple[int, int]
    names: Tuple[str, str]
    first_contact: ContactTime
    contacts: Tuple[Contact, ...]


@dataclass(frozen=True)
class SceneResult:
    collides: bool
    first_contact: Optional[ContactTime]
    pairs: Tuple[PairResult, ...]
    first: Tuple[PairResult, ...]
    stats: dict
    # The bodies solved (for to_png / to_trimesh): not compared, not pickled.
    bodies: tuple = field(default=(), compare=False, repr=False)

    def __getstate__(self):
        state = dict(self.__dict__)
        state.pop("bodies", None)  # a result travels without its bodies (see distributed)
        return state

    def feature_indices(self, body, *, pairs="first"):
        """{kind: int64 array} of the features of one body (an index or a name) that
        touch, sorted and unique, kind in "vertex", "edge", "triangle", "sphere" (only the
        kinds present). pairs="first": the contacts of the scene's first pairs;
        "all": of every pair in contact."""
        source = {"first": self.first, "all": self.pairs}.get(pairs)
        if source is None:
            raise InputError(f'pairs: expected "first" or "all", got {show(pairs)}')
        found = {}
        for p in source:
            for c in p.contacts:
                for who, name, (kind, k) in ((p.bodies[0], p.names[0], c.a),
                                             (p.bodies[1], p.names[1], c.b)):
                    if (who == body and not isinstance(body, str)) or name == body:
                        found.setdefault(kind, set()).add(k)
        return {kind: np.array(sorted(ks), dtype=np.int64) for kind, ks in sorted(found.items())}

    def to_png(self, path, *, bodies=None, t=None, **options):
        """Writes a PNG of the bodies at t (default: the first contact, else 0) with the
        touching features in red (polyccd.apps._render.render_scene, matplotlib);
        returns the path. bodies: default the ones this result was solved from."""
        from .apps._render import render_scene
        bodies = self._bodies_for(bodies)
        time = t if t is not None else (self.first_contact or 0)
        return render_scene(bodies, time, self, path, **options)

    def to_trimesh(self, *, bodies=None, t=None):
        """A trimesh.Scene of the bodies at t (default: the first contact, else 0), the
        touching triangles, edges, vertices and balls in red (polyccd.apps._export);
        drawing only: float poses and geometry. Needs trimesh."""
        from .apps._export import contact_scene
        bodies = self._bodies_for(bodies)
        return contact_scene(bodies, t if t is not None else (self.first_contact or 0), self)

    def _bodies_for(self, bodies):
        if bodies is None:
            bodies = self.bodies
        if not bodies:
            raise InputError("bodies: this result does not hold its bodies (it was "
                             "pickled or made elsewhere); pass bodies=[...]")
        return list(bodies)


_WHOLE = lib.PCCD_WHOLE


def _time(rep, pair, contact):
    needed = ffi.new("size_t *")
    texts = []
    for which in (0, 1):
        buf = ffi.new("char[]", 128)
        rc = lib.pccd_report_time(rep, pair, contact, which, buf, len(buf), needed)
        if rc == lib.PCCD_ERANGE:
            buf = ffi.new("char[]", needed[0])
            rc = lib.pccd_report_time(rep, pair, contact, which, buf, len(buf), needed)
        check(rc)
        texts.append(fraction_from_text(ffi.string(buf).decode("ascii")))
    exact = ffi.new("int *")
    approx = ffi.new("double *")
    check(lib.pccd_report_time_info(rep, pair, contact, exact, approx))
    lo, hi = texts
    return ContactTime(lo, hi, lo if exact[0] else None, approx[0])


def _names(bodies):
    return [b.name if b.name is not None else f"body{i}" for i, b in enumerate(bodies)]


def _bodies_list(bodies):
    try:
        bodies = list(bodies)
    except TypeError:
        raise InputError(f"bodies: expected a sequence of polyccd.Body, got {show(bodies)}") from None
    for i, b in enumerate(bodies):
        if not isinstance(b, Body):
            raise InputError(f"bodies[{i}]: expected a polyccd.Body, got {show(b)}")
    return bodies


def _options(time_tolerance, all_contacts, threads, broad_phase, want_exact):
    """(cfg, keep-alive, pccd_scene_options) of the keyword arguments of check/query."""
    if broad_phase not in BROAD_PHASES:
        raise InputError("broad_phase: expected \"auto\", \"boxes\", \"brute\", \"bvh\" or \"range\", "
                         f"got {show(broad_phase)}")
    if isinstance(threads, bool) or not isinstance(threads, int) or not 1 <= threads <= 1024:
        raise InputError(f"threads: expected an integer from 1 to 1024, got {show(threads)}")
    if all_contacts not in (True, False):
        raise InputError(f"all_contacts: expected True or False, got {show(all_contacts)}")
    cfg, keep = _config(time_tolerance, True, want_exact)
    opt = ffi.new("pccd_scene_options *")
    check(lib.pccd_scene_options_init(opt))
    opt.threads = threads
    opt.all_contacts = 1 if all_contacts else 0
    opt.broad_phase = BROAD_PHASES[broad_phase]
    return cfg, keep, opt


def _motion_handle(motion):
    return motion._handle if motion is not None else ffi.NULL


def _pair_index(x, names, place):
    """A body index from an int or a body name."""
    if isinstance(x, str):
        if names.count(x) != 1:
            raise InputError(f"{place}: {x!r} is not the name of exactly one body")
        return names.index(x)
    if isinstance(x, bool) or not isinstance(x, int):
        raise InputError(f"{place}: expected a body index or name, got {show(x)}")
    if not 0 <= x < len(names):
        raise InputError(f"{place}: {x} out of range ({len(names)} bodies)")
    return x


def check_scene(bodies, *, time_tolerance="1e-12", all_contacts=False, threads=1,
                broad_phase="auto", want_exact=True, skip_pairs=()):
    """Every body pair in contact and the scene's first contact (API.md, Scenes).
    skip_pairs: body pairs (i, j) (indices or names) not to check."""
    bodies = _bodies_list(bodies)
    if len(bodies) < 2:
        raise InputError(f"bodies: a scene needs at least 2 bodies, got {len(bodies)}")
    cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact)
    scene = handles.new("scene")
    for b in bodies:
        check(lib.pccd_scene_add(scene, b.shape._handle, _motion_handle(b.motion), ffi.NULL))
    names = _names(bodies)
    for k, pair in enumerate(_items(skip_pairs, "skip_pairs", "a list of body pairs")):
        items = _items(pair, f"skip_pairs[{k}]", "a pair (i, j)")
        if len(items) != 2:
            raise InputError(f"skip_pairs[{k}]: expected a pair (i, j), got {show(pair)}")
        i, j = (_pair_index(x, names, f"skip_pairs[{k}][{a}]") for a, x in enumerate(items))
        check(lib.pccd_scene_set_pair_check(scene, i, j, 0))
    rep = handles.new("report")
    check(lib.pccd_scene_solve(scene, cfg, opt, rep))
    return _read(rep, _names(bodies), bodies)


def _read(rep, names, bodies=()):
    out = ffi.new("int *")
    check(lib.pccd_report_collides(rep, out))
    collides = bool(out[0])
    count = ffi.new("size_t *")
    check(lib.pccd_report_pair_count(rep, count))
    bi, bj, fi, fj = ffi.new("size_t *"), ffi.new("size_t *"), ffi.new("int *"), ffi.new("int *")
    ii, ij = ffi.new("size_t *"), ffi.new("size_t *")
    pairs, first = [], []
    for p in range(count[0]):
        is_first = ffi.new("int *")
        check(lib.pccd_report_pair(rep, p, bi, bj, is_first))
        ncontacts = ffi.new("size_t *")
        check(lib.pccd_report_contact_count(rep, p, ncontacts))
        contacts = []
        for c in range(ncontacts[0]):
            check(lib.pccd_report_contact(rep, p, c, fi, ii, fj, ij))
            contacts.append(Contact((FEATURES[fi[0]], int(ii[0])), (FEATURES[fj[0]], int(ij[0])),
                                    _time(rep, p, c)))
        i, j = int(bi[0]), int(bj[0])
        pr = PairResult((i, j), (names[i], names[j]), _time(rep, p, _WHOLE), tuple(contacts))
        pairs.append(pr)
        if is_first[0]:
            first.append(pr)
    stats = ffi.new("pccd_scene_stats *")
    check(lib.pccd_report_stats(rep, stats))
    stat_dict = {k: int(getattr(stats, k)) for k in
                 ("pieces", "leaves", "candidates", "solved", "static_tests", "refined")}
    for k, name in ((1, "bounds"), (2, "bernstein"), (3, "interval"), (4, "exact")):
        stat_dict["stage_" + name] = int(stats.by_stage[k])
    whole = _time(rep, _WHOLE, _WHOLE) if collides else None
    return SceneResult(collides, whole, tuple(pairs), tuple(first), stat_dict, tuple(bodies))
