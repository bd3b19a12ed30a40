"""Scenes: bodies on motions, checked exactly (bindings/python/API.md, "Scenes").

Only conversion here: the scene is built in C (pccd_scene), solved there
(pccd_scene_solve) and read back from the pccd_report. Scene files (formats.md,
polyccd/1) are read with exact numbers (numbers stay texts until C parses them).
"""
import dataclasses
from dataclasses import dataclass
from fractions import Fraction
from typing import Optional, Tuple

from ._body import Mesh, Spheres
from ._errors import InputError, check, error_for, last_error
from ._json import (SCENE_FORMAT, _expect_at, _list_at, _object_at, _string_at, describe, load,
                    number_at, options_and_labels)
from ._motion import Motion
from ._numbers import fraction_from_text, show
from ._pccd import ffi, lib
from ._results import ContactTime
from ._solve import _config

FEATURES = ("vertex", "edge", "triangle", "sphere")
BROAD_PHASES = {"auto": lib.PCCD_BROAD_AUTO, "boxes": lib.PCCD_BROAD_BOXES,
                "brute": lib.PCCD_BROAD_BRUTE, "range": lib.PCCD_BROAD_RANGE}


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


def _new(kind):
    out = ffi.new(f"pccd_{kind} **")
    check(getattr(lib, f"pccd_{kind}_new")(out))
    return ffi.gc(out[0], getattr(lib, f"pccd_{kind}_free"))


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
        raise InputError("broad_phase: expected \"auto\", \"boxes\", \"brute\" or \"range\", "
                         f"got {show(broad_phase)}")
    if isinstance(threads, bool) or not isinstance(threads, int) or not 1 <= threads <= 1024:
        raise InputError(f"threads: expected an integer from 1 to 1024, got {show(threads)}")
    if all_contacts not in (True, False):
        raise InputError(f"all_contacts: expected True or False, got {show(all_contacts)}")
    cfg, keep = _config(time_tolerance, True, want_exact, "time_tolerance")
    opt = ffi.new("pccd_scene_options *")
    check(lib.pccd_scene_options_init(opt))
    opt.threads = threads
    opt.all_contacts = 1 if all_contacts else 0
    opt.broad_phase = BROAD_PHASES[broad_phase]
    return cfg, keep, opt


def _motion_handle(motion):
    return motion._handle if motion is not None else ffi.NULL


def _solved(rc):
    """Raises the error of a failed solve (the message without the C function's name; a
    bad tolerance is named by its keyword argument, as solve() names it, not by the C
    field config.time_tolerance)."""
    if rc != 0:
        message = last_error().split(": ", 1)[-1]
        if message.startswith("config.time_tolerance:"):
            message = message[len("config."):]
        raise error_for(rc, message)


def check_scene(bodies, *, time_tolerance="1e-12", all_contacts=False, threads=1,
                broad_phase="auto", want_exact=True):
    """Every body pair in contact and the scene's first contact (API.md, Scenes)."""
    bodies = _bodies_list(bodies)
    if len(bodies) < 2:
        raise InputError(f"bodies: a scene needs at least 2 bodies, got {len(bodies)}")
    cfg, _keep, opt = _options(time_tolerance, all_contacts, threads, broad_phase, want_exact)
    scene = _new("scene")
    for b in bodies:
        check(lib.pccd_scene_add(scene, b.shape._handle, _motion_handle(b.motion), ffi.NULL))
    rep = _new("report")
    _solved(lib.pccd_scene_solve(scene, cfg, opt, rep))
    return _read(rep, _names(bodies))


def _read(rep, names):
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
    return SceneResult(collides, whole, tuple(pairs), tuple(first), stat_dict)


# ---------------------------------------------------------------- scene files

@dataclass(frozen=True)
class SceneOptions:
    time_tolerance: Optional[str]


def _traj_lists(value, path, count, what):
    comps = _list_at(value, path, what, count)
    return [[number_at(c, f"{path}[{k}][{i}]")
             for i, c in enumerate(_list_at(comp, f"{path}[{k}]", "a list of coefficients"))]
            for k, comp in enumerate(comps)]


def _points_at(value, path):
    """The number texts of a list of [x, y, z]."""
    return [[number_at(c, f"{path}[{i}][{a}]") for a, c in
             enumerate(_list_at(v, f"{path}[{i}]", "[x, y, z]", 3))]
            for i, v in enumerate(_list_at(value, path, "a list of [x, y, z]"))]


def _with_place(path, fn, *args):
    """Runs a constructor; an InputError gets the JSON path in front."""
    try:
        return fn(*args)
    except InputError as e:
        raise type(e)(f"{path}.{e}" if not str(e).startswith("[") else f"{path}{e}") from None


def _body_at(value, path, index):
    obj = _object_at(value, path)
    name = _string_at(obj["name"], f"{path}.name") if "name" in obj else f"body{index}"
    shapes = [k for k in ("mesh", "spheres") if k in obj]
    if len(shapes) != 1:
        raise InputError(f"{path}: expected exactly one of \"mesh\" or \"spheres\", got "
                         f"{' and '.join(shapes) if shapes else 'neither'}")
    if shapes[0] == "mesh":
        m = _object_at(obj["mesh"], f"{path}.mesh")
        for key in ("vertices", "triangles"):
            if key not in m:
                raise InputError(f"{path}.mesh.{key}: missing")
        verts = _points_at(m["vertices"], f"{path}.mesh.vertices")
        tris = []
        for i, t in enumerate(_list_at(m["triangles"], f"{path}.mesh.triangles", "a list of [i, j, k]")):
            row = []
            for a, x in enumerate(_list_at(t, f"{path}.mesh.triangles[{i}]", "[i, j, k]", 3)):
                text = str(x) if isinstance(x, str) else None
                if text is None or type(x).__name__ != "JsonNumber" or not text.isdigit():
                    raise InputError(f"{path}.mesh.triangles[{i}][{a}]: expected a vertex index "
                                     f"(an integer >= 0), got {describe(x)}")
                row.append(int(text))
            tris.append(row)
        shape = _with_place(f"{path}.mesh", Mesh, verts, tris)
    else:
        s = _object_at(obj["spheres"], f"{path}.spheres")
        for key in ("centers", "radii"):
            if key not in s:
                raise InputError(f"{path}.spheres.{key}: missing")
        centers = _points_at(s["centers"], f"{path}.spheres.centers")
        radii = [number_at(r, f"{path}.spheres.radii[{i}]")
                 for i, r in enumerate(_list_at(s["radii"], f"{path}.spheres.radii", "a list of radii"))]
        shape = _with_place(f"{path}.spheres", Spheres, centers, radii)
    motion = None
    if "motion" in obj:
        mo = _object_at(obj["motion"], f"{path}.motion")
        translation = (_traj_lists(mo["translation"], f"{path}.motion.translation", 3,
                                   "[xs, ys, zs]") if "translation" in mo else None)
        rotation = (_traj_lists(mo["rotation"], f"{path}.motion.rotation", 4,
                                "[ws, xs, ys, zs]") if "rotation" in mo else None)
        motion = _with_place(f"{path}.motion", Motion, translation, rotation)
    return Body(shape, motion, name)


def scene_from_doc(doc):
    """(bodies, options, expect) of a parsed polyccd/1 document."""
    top = _object_at(doc, "(top level)")
    if top.get("format") != SCENE_FORMAT:
        got = "missing" if "format" not in top else describe(top.get("format"))
        raise InputError(f'format: expected "{SCENE_FORMAT}", got {got}')
    if "bodies" not in top:
        raise InputError("bodies: missing (a scene needs at least 2 bodies)")
    items = _list_at(top["bodies"], "bodies", "a list of bodies")
    bodies = [_body_at(b, f"bodies[{i}]", i) for i, b in enumerate(items)]
    names = [b.name for b in bodies]
    for i, n in enumerate(names):
        if names.index(n) != i:
            raise InputError(f"bodies[{i}].name: \"{n}\" is used by bodies[{names.index(n)}] too")
    if len(bodies) < 2:
        raise InputError(f"bodies: a scene needs at least 2 bodies, got {len(bodies)}")
    tolerance = options_and_labels(top)
    expect = None
    if "expect" in top:
        expect = _expect_at(top["expect"], "expect")
        ex = _object_at(top["expect"], "expect")
        if "pairs" in ex:
            pairs = []
            for k, p in enumerate(_list_at(ex["pairs"], "expect.pairs", "a list of [nameA, nameB]")):
                pair = _list_at(p, f"expect.pairs[{k}]", "[nameA, nameB]", 2)
                for q, n in enumerate(pair):
                    if _string_at(n, f"expect.pairs[{k}][{q}]") not in names:
                        raise InputError(f"expect.pairs[{k}][{q}]: no body is named \"{n}\"")
                pairs.append(tuple(sorted(pair, key=names.index)))
            order = sorted(set(pairs), key=lambda x: (names.index(x[0]), names.index(x[1])))
            expect = dataclasses.replace(expect, pairs=tuple(order))
    return bodies, SceneOptions(tolerance), expect


def load_scene(path_or_doc):
    """(bodies, options, expect) of a polyccd/1 scene file (or an already parsed dict)."""
    doc = path_or_doc if isinstance(path_or_doc, dict) else load(path_or_doc)
    return scene_from_doc(doc)
