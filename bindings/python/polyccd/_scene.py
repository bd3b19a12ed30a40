"""Scenes: bodies on motions, checked exactly (docs/python.md, "Scenes").

Only conversion here: two bodies are solved in C by one call (pccd_pair_solve), more
as a scene (pccd_scene, pccd_scene_solve), and the answers are read back from a
pccd_report (one per thread, reused). Scene files are read, and results drawn, by the
applications (polyccd.apps.load_scene, to_png, to_trimesh).
"""
import struct
import threading
from dataclasses import dataclass, field
from typing import Iterable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _handles as handles
from . import _limits
from ._body import Mesh, Spheres
from ._contact import ContactGeometry, contact_geometry as _contact_geometry
from ._errors import InputError, check
from ._flags import flag
from ._motion import Motion
from ._numbers import fraction_from_text, show
from ._pccd import ffi, lib
from ._results import ContactTime
from ._solve import _config, _items
from ._types import Number, Pose

FEATURES = ("vertex", "edge", "triangle", "sphere", "solid")
BROAD_PHASES = {"auto": lib.PCCD_BROAD_AUTO, "boxes": lib.PCCD_BROAD_BOXES,
                "brute": lib.PCCD_BROAD_BRUTE, "range": lib.PCCD_BROAD_RANGE,
                "bvh": lib.PCCD_BROAD_BVH}


class Body:
    """A rigid body (Mesh or Spheres) on a Motion (None: stationary), with a name.

    pose: a static body placed at a pose instead of a motion, a 4x4 pose matrix or a
    (position, quaternion w x y z) pair, exactly as Motion.fixed(pose) (the Body's motion
    is then that Motion)."""

    __slots__ = ("shape", "motion", "name")

    def __init__(self, shape: Union[Mesh, Spheres], motion: Optional[Motion] = None,
                 name: Optional[str] = None, pose: Optional[Pose] = None) -> None:
        if not isinstance(shape, (Mesh, Spheres)):
            raise InputError(f"shape: expected a polyccd.Mesh or polyccd.Spheres, got {show(shape)}")
        if pose is not None:
            if motion is not None:
                raise InputError("pose: give a motion or a pose, not both (compose a pose "
                                 "into a motion with Motion.compose)")
            motion = Motion.fixed(pose)
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
    # The bodies solved (for contact_geometry, polyccd.apps.to_png / to_trimesh): not compared, not pickled.
    bodies: tuple = field(default=(), compare=False, repr=False)

    def __getstate__(self):
        state = dict(self.__dict__)
        state.pop("bodies", None)  # a result travels without its bodies (see distributed)
        return state

    def feature_indices(self, body, *, pairs="first"):
        """{kind: int64 array} of the features of one body (an index or a name) that
        touch, sorted and unique, kind in "vertex", "edge", "triangle", "sphere", "solid" (only the
        kinds present). pairs="first": the contacts of the scene's first pairs;
        "all": of every pair in contact."""
        source = {"first": self.first, "all": self.pairs}.get(pairs) if isinstance(pairs, str) else None
        if source is None:
            raise InputError(f'pairs: expected "first" or "all", got {show(pairs)}')
        names = _names(self.bodies)  # () for a result without its bodies: any index or name
        if isinstance(body, (bool, np.bool_)) or not isinstance(body, (str, int, np.integer)) or \
                (self.bodies and (body not in names if isinstance(body, str)
                                  else not 0 <= body < len(self.bodies))):
            raise InputError(f"body: expected the index or the name of a body of this result, "
                             f"got {show(body)}")
        found = {}
        for p in source:
            for c in p.contacts:
                for who, name, (kind, k) in ((p.bodies[0], p.names[0], c.a),
                                             (p.bodies[1], p.names[1], c.b)):
                    if (who == body and not isinstance(body, str)) or name == body:
                        found.setdefault(kind, set()).add(k)
        return {kind: np.array(sorted(ks), dtype=np.int64) for kind, ks in sorted(found.items())}

    def contact_geometry(self, pair: int = 0, contact: int = 0, *,
                         bodies: Optional[Sequence[Body]] = None) -> ContactGeometry:
        """The contact point and normal (a polyccd.ContactGeometry: enclosures,
        and exact Fractions when the time is exact) of contact `contact` of pair `pair`
        (indices into self.pairs and its contacts) at that contact's first time.
        pccd_contact_geometry_compute has the definitions; a result of a solve with
        min_distance > 0 is refused when its features are apart. bodies: default the
        ones this result was solved from."""
        bodies = self.bodies if bodies is None else _items(bodies, "bodies", "a list of polyccd.Body")
        for k, b in enumerate(bodies):
            if not isinstance(b, Body):
                raise InputError(f"bodies[{k}]: expected a polyccd.Body, got {show(b)}")
        if not bodies:
            raise InputError("bodies: this result does not hold its bodies (it was "
                             "pickled or made elsewhere); pass bodies=[...]")
        p = _item(self.pairs, pair, "pair")
        c = _item(p.contacts, contact, "contact")
        if max(p.bodies) >= len(bodies):
            raise InputError(f"bodies: pair {pair} is of bodies {p.bodies}, but {len(bodies)} "
                             f"bodies were given")
        return _contact_geometry(bodies[p.bodies[0]], c.a, bodies[p.bodies[1]], c.b, c.first_contact)


_WHOLE = lib.PCCD_WHOLE


def _item(items, k, place):
    if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k < len(items):
        raise InputError(f"{place}: expected an index from 0 to {len(items) - 1}, got {show(k)}")
    return items[k]


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


# _options of recent keyword sets (the library only reads cfg and opt, so one set serves
# every call and thread). Keys carry the types: 1, 1.0 and True are equal, but True is
# not a thread count.
_OPTIONS = {}
_OPTIONS_MAX = 64


def _options(time_tolerance, all_contacts, threads, broad_phase, want_exact, limits=None,
             min_distance=None, want_time=True):
    """(cfg, keep-alive, pccd_scene_options) of the keyword arguments of check/query
    (want_time False: decide mode, pccd_config.want_time = 0).
    Only conversions are cached, by value (the library reads and checks cfg and opt on
    every call); a call with limits converts them each time (a Limits holds a Cancel
    and a clock, so it is no cache key)."""
    key = (time_tolerance, type(time_tolerance), all_contacts, type(all_contacts), threads,
           type(threads), broad_phase, want_exact, type(want_exact),
           min_distance, type(min_distance), want_time, type(want_time))
    if limits is not None:
        return _new_options(time_tolerance, all_contacts, threads, broad_phase, want_exact,
                            limits, min_distance, want_time)
    try:
        return _OPTIONS[key]
    except KeyError:
        pass
    except TypeError:  # an unhashable argument: built each time (and checked there)
        return _new_options(time_tolerance, all_contacts, threads, broad_phase, want_exact,
                            limits, min_distance, want_time)
    out = _new_options(time_tolerance, all_contacts, threads, broad_phase, want_exact, limits,
                       min_distance, want_time)
    if len(_OPTIONS) < _OPTIONS_MAX:
        _OPTIONS[key] = out
    return out


def _new_options(time_tolerance, all_contacts, threads, broad_phase, want_exact, limits=None,
                 min_distance=None, want_time=True):
    if not isinstance(broad_phase, str) or broad_phase not in BROAD_PHASES:
        raise InputError("broad_phase: expected \"auto\", \"boxes\", \"brute\", \"bvh\" or \"range\", "
                         f"got {show(broad_phase)}")
    threads = _limits.thread_count(threads)
    _limits.warn_threads(threads)
    all_contacts = flag(all_contacts, "all_contacts")
    want_time = flag(want_time, "first_contact")
    want_exact = flag(want_exact, "want_exact")
    cfg, keep = _config(time_tolerance, want_time, want_exact, limits, min_distance)
    opt = ffi.new("pccd_scene_options *")
    check(lib.pccd_scene_options_init(opt))
    opt.threads = threads
    opt.all_contacts = 1 if all_contacts else 0
    opt.broad_phase = BROAD_PHASES[broad_phase]
    return cfg, keep, opt


_NULL = ffi.NULL
_run, _pair_solve = _limits.run, lib.pccd_pair_solve


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


def check_scene(bodies: Iterable[Body], *, time_tolerance: Number = "1e-12",
                all_contacts: bool = False, threads: int = 1, broad_phase: str = "auto",
                want_exact: bool = True, limits: Optional[_limits.Limits] = None,
                min_distance: Optional[Number] = None,
                skip_pairs: Iterable[Tuple[Union[int, str], Union[int, str]]] = (),
                first_contact: bool = True) -> SceneResult:
    """Every body pair in contact during t in [0, 1] and the scene's first contact,
    decided exactly (polyccd.check; docs/python.md, "Scenes").

    bodies: two or more polyccd.Body (a Mesh or Spheres on a Motion, None: stationary).
    Meshes touch when their surfaces share a point, balls when two balls of different
    bodies do; touching, grazing and contacts at t = 0 or 1 count.

    time_tolerance: the widest enclosure of an irrational first contact time (a rational
    one is reported exactly when want_exact). all_contacts: every touching feature pair
    with its own first time, instead of the pairs touching first. threads: workers
    (answers never depend on them). broad_phase: "auto" (chosen from the bodies: see
    docs/design.md), "bvh", "boxes", "range" or "brute"; the answers are the same.
    limits: a polyccd.Limits (time, work steps, cancellation, input size) or None.
    min_distance: delta >= 0: a contact is a time when bodies come within delta.
    skip_pairs: body pairs (i, j) (indices or names) not to check.
    first_contact=False: decide mode (pccd_config.want_time = 0): the solve stops at the
    first pair found in contact, reported alone with a witness (some touching features,
    an enclosure of one of its contact times, not necessarily the first).

    Returns a SceneResult: collides, first_contact (a ContactTime: lo <= t* <= hi, exact
    when rational), pairs (PairResult per body pair in contact, with its contacts and
    time), first (the pairs that may touch first), feature_indices(body) (numpy arrays),
    contact_geometry(pair, contact) (contact point and normal). Raises InputError (or
    LimitError) with the library's message, which names the bad argument.

    Example: a unit box sliding from x = -3 to 3 into a box at the origin first
    touches it at t = 1/3 exactly:
    ``polyccd.check([polyccd.Body(box, polyccd.Motion.linear((-3, 0, 0), (3, 0, 0))),
    polyccd.Body(box)]).first_contact.exact == Fraction(1, 3)``."""
    bodies = _bodies_list(bodies)  # fewer than 2: pccd_scene_solve says so
    skip_pairs = _items(skip_pairs, "skip_pairs", "a list of body pairs")
    cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact,
                               limits, min_distance, first_contact)
    rep = _scratch.report
    if len(bodies) == 2 and not skip_pairs:  # one call, no scene (pccd_pair_solve: the same)
        a, b = bodies
        ma, mb = a.motion, b.motion
        rc = _run(cfg, _pair_solve, a.shape._handle, _NULL if ma is None else ma._handle,
                  b.shape._handle, _NULL if mb is None else mb._handle, cfg, opt, rep)
        if rc:
            check(rc)
        return _read(rep, bodies)
    scene = handles.new("scene")
    for b in bodies:
        check(lib.pccd_scene_add(scene, b.shape._handle, _motion_handle(b.motion), ffi.NULL))
    names = _names(bodies)
    for k, pair in enumerate(skip_pairs):
        items = _items(pair, f"skip_pairs[{k}]", "a pair (i, j)")
        if len(items) != 2:
            raise InputError(f"skip_pairs[{k}]: expected a pair (i, j), got {show(pair)}")
        i, j = (_pair_index(x, names, f"skip_pairs[{k}][{a}]") for a, x in enumerate(items))
        check(lib.pccd_scene_set_pair_check(scene, i, j, 0))
    check(_run(cfg, lib.pccd_scene_solve, scene, cfg, opt, rep))
    return _read(rep, bodies)


class _Scratch(threading.local):
    """Per-thread report handle and output cells, reused by every check (_read copies
    every answer out, so nothing refers to them afterwards)."""

    def __init__(self):
        self.report = handles.new("report")
        self.int_out = ffi.new("int *")
        self.size_out = ffi.new("size_t *")
        self.stats = ffi.new("pccd_scene_stats *")
        self.stats_bytes = ffi.buffer(self.stats)
        self.read = (self.int_out, self.size_out, self.stats, self.stats_bytes)  # one lookup


_scratch = _Scratch()


# pccd_scene_stats read at once: six counters, then by_stage[5], all unsigned long long
# (so no padding); by_stage[0] (no stage) is skipped.
_STATS = struct.Struct("=6Q8x4Q")
assert ffi.sizeof("pccd_scene_stats") == _STATS.size == 11 * 8
assert [f for f, _ in ffi.typeof("pccd_scene_stats").fields] == [
    "pieces", "leaves", "candidates", "solved", "static_tests", "refined", "by_stage"]
assert set(SceneResult.__dataclass_fields__) == {"collides", "first_contact", "pairs", "first",
                                                  "stats", "bodies"}


def _read(rep, bodies):
    """The SceneResult held by a solved report of these bodies (names: the bodies')."""
    out, count, stats, stats_bytes = _scratch.read
    rc = lib.pccd_report_collides(rep, out)
    if rc:
        check(rc)
    collides = bool(out[0])
    pairs, first = [], []
    if collides:  # else the report has no pairs (pccd_report_pair_count would say 0)
        names = _names(bodies)
        check(lib.pccd_report_pair_count(rep, count))
        bi, bj, fi, fj = ffi.new("size_t *"), ffi.new("size_t *"), ffi.new("int *"), ffi.new("int *")
        ii, ij = ffi.new("size_t *"), ffi.new("size_t *")
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
    rc = lib.pccd_report_stats(rep, stats)
    if rc:
        check(rc)
    v = _STATS.unpack_from(stats_bytes)
    stat_dict = {"pieces": v[0], "leaves": v[1], "candidates": v[2], "solved": v[3],
                 "static_tests": v[4], "refined": v[5], "stage_bounds": v[6],
                 "stage_bernstein": v[7], "stage_interval": v[8], "stage_exact": v[9]}
    whole = _time(rep, _WHOLE, _WHOLE) if collides else None
    return _scene_result(collides, whole, tuple(pairs), tuple(first), stat_dict, tuple(bodies))


_new = object.__new__


def _scene_result(collides, first_contact, pairs, first, stats, bodies):
    """SceneResult(...) with its fields set directly: the frozen dataclass's __init__
    costs 0.7 us, an eighth of a far-apart check from Python (same object: equal to
    the one __init__ makes, and the fields are exactly SceneResult's)."""
    r = _new(SceneResult)
    d = r.__dict__
    d["collides"] = collides
    d["first_contact"] = first_contact
    d["pairs"] = pairs
    d["first"] = first
    d["stats"] = stats
    d["bodies"] = bodies
    return r
