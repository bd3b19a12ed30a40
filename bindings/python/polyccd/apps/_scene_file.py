"""Scene files (formats.md, polyccd/1): read with exact numbers (numbers stay texts until
the C library parses them) into polyccd.Body objects. An error names its JSON path
(bodies[1].motion.rotation[2][0]), the path of the object in front of the binding's
own PLACE."""
import dataclasses
from dataclasses import dataclass
from typing import Optional

import numpy as np

from .. import Body, InputError, Mesh, Motion, Spheres
from ..texts import int_from_text, show
from ._json import (EXPECT_KEYS, SCENE_FORMAT, _expect_at, _list_at, _object_at, _string_at,
                    describe, known_keys, load, min_distance_option, number_at,
                    options_and_labels)
from ._reading import tick


@dataclass(frozen=True)
class SceneOptions:
    time_tolerance: Optional[str]
    # options.min_distance (an optional extension of formats.md; None: 0)
    min_distance: Optional[str] = None


def _traj_lists(value, path, count, what):
    comps = _list_at(value, path, what, count)
    return [[number_at(c, f"{path}[{k}][{i}]")
             for i, c in enumerate(_list_at(comp, f"{path}[{k}]", "a list of coefficients"))]
            for k, comp in enumerate(comps)]


def _points_at(value, path):
    """The number texts of a list of [x, y, z]."""
    out = []
    for i, v in enumerate(_list_at(value, path, "a list of [x, y, z]")):
        tick()
        out.append([number_at(c, f"{path}[{i}][{a}]")
                    for a, c in enumerate(_list_at(v, f"{path}[{i}]", "[x, y, z]", 3))])
    return out


def _with_place(path, fn, *args):
    """Runs a constructor; an InputError gets the JSON path in front."""
    try:
        return fn(*args)
    except InputError as e:
        raise type(e)(f"{path}.{e}" if not str(e).startswith("[") else f"{path}{e}") from None


def _body_at(value, path, index):
    obj = _object_at(value, path)
    known_keys(obj, path, ("name", "mesh", "spheres", "motion", "solid"))
    name = _string_at(obj["name"], f"{path}.name") if "name" in obj else f"body{index}"
    shapes = [k for k in ("mesh", "spheres") if k in obj]
    if len(shapes) != 1:
        raise InputError(f"{path}: expected exactly one of \"mesh\" or \"spheres\", got "
                         f"{' and '.join(shapes) if shapes else 'neither'}")
    if shapes[0] == "mesh":
        m = _object_at(obj["mesh"], f"{path}.mesh")
        known_keys(m, f"{path}.mesh", ("vertices", "triangles"))
        for key in ("vertices", "triangles"):
            if key not in m:
                raise InputError(f"{path}.mesh.{key}: missing")
        verts = _points_at(m["vertices"], f"{path}.mesh.vertices")
        tris = []
        for i, t in enumerate(_list_at(m["triangles"], f"{path}.mesh.triangles", "a list of [i, j, k]")):
            tick()
            row = []
            for a, x in enumerate(_list_at(t, f"{path}.mesh.triangles[{i}]", "[i, j, k]", 3)):
                text = str(x) if isinstance(x, str) else None
                if (text is None or type(x).__name__ != "JsonNumber" or not text.isascii()
                        or not text.isdigit()):
                    raise InputError(f"{path}.mesh.triangles[{i}][{a}]: expected a vertex index "
                                     f"(an integer >= 0), got {describe(x)}")
                row.append(int_from_text(text))  # any length (int() stops at 4,300 digits)
            tris.append(row)
        if all(x < 2 ** 63 for row in tris for x in row):  # the Mesh's fast path for arrays
            tris = np.array(tris, dtype=np.int64).reshape(len(tris), 3)
        solid = obj.get("solid", False)
        if solid is not True and solid is not False:
            raise InputError(f"{path}.solid: expected true or false, got {describe(solid)}")
        shape = _with_place(f"{path}.mesh", Mesh, verts, tris, solid)
    else:
        if "solid" in obj:
            raise InputError(f"{path}.solid: only a mesh body takes \"solid\" (balls are "
                             f"solid already)")
        s = _object_at(obj["spheres"], f"{path}.spheres")
        known_keys(s, f"{path}.spheres", ("centers", "radii"))
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
        known_keys(mo, f"{path}.motion", ("translation", "rotation"))
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
    known_keys(top, "(top level)", ("format", "name", "source", "bodies", "options", "expect"))
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
        expect = _expect_at(top["expect"], "expect", EXPECT_KEYS + ("pairs", "features"))
        ex = _object_at(top["expect"], "expect")
        if "pairs" in ex:
            pairs = []
            for k, p in enumerate(_list_at(ex["pairs"], "expect.pairs", "a list of [nameA, nameB]")):
                pair = _list_at(p, f"expect.pairs[{k}]", "[nameA, nameB]", 2)
                for q, n in enumerate(pair):
                    if _string_at(n, f"expect.pairs[{k}][{q}]") not in names:
                        raise InputError(f"expect.pairs[{k}][{q}]: no body is named {show(n)}")
                if pair[0] == pair[1]:
                    raise InputError(f"expect.pairs[{k}]: a pair of one body ({show(pair[0])}) "
                                     "with itself (a pair is two different bodies)")
                pairs.append(tuple(sorted(pair, key=names.index)))
            order = sorted(set(pairs), key=lambda x: (names.index(x[0]), names.index(x[1])))
            expect = dataclasses.replace(expect, pairs=tuple(order))
    return bodies, SceneOptions(tolerance, min_distance_option(top)), expect


def load_scene(path_or_doc):
    """(bodies, options, expect) of a polyccd/1 scene file (or an already parsed dict)."""
    doc = path_or_doc if isinstance(path_or_doc, dict) else load(path_or_doc)
    return scene_from_doc(doc)
