"""Reading a URDF's geometry and origins for polyccd.robot: numbers from the URDF's own
text (each the double nearest its decimal), <geometry> elements as polyccd bodies (boxes
and cylinders as solids, meshes as solids where closed; see robot.py's policies)."""
import os

import numpy as np

from ._body import Mesh, Spheres
from ._errors import InputError
from ._extras import need


def _floats(text, place, n=3):
    try:
        values = [float(x) for x in (text or "").split()]
    except ValueError:
        raise InputError(f"{place}: {text!r} is not {n} numbers") from None
    if len(values) != n:
        raise InputError(f"{place}: {text!r} is not {n} numbers")
    return values


def _origin(element, place):
    """(xyz, rpy) of an element's <origin> child (URDF defaults: zeros)."""
    o = element.find("origin") if element is not None else None
    if o is None:
        return [0.0] * 3, [0.0] * 3
    return (_floats(o.get("xyz", "0 0 0"), place + ".origin.xyz"),
            _floats(o.get("rpy", "0 0 0"), place + ".origin.rpy"))


def _mesh_file(filename, scale, place, limits):
    trimesh = need("polyccd.robot.load_urdf (mesh files)", "robot", "trimesh")
    if not os.path.isfile(filename):
        raise InputError(f"{place}: mesh file {filename!r} not found")
    try:
        m = trimesh.load(filename, force="mesh", process=False)
    except Exception as e:  # trimesh raises many kinds
        raise InputError(f"{place}: mesh file {filename!r} could not be read ({e})") from None
    vertices = np.asarray(m.vertices, dtype=np.float64)
    faces = np.asarray(m.faces, dtype=np.int64)
    if len(faces) == 0:
        raise InputError(f"{place}: mesh file {filename!r} has no triangles")
    if scale is not None:
        vertices = vertices * np.asarray(scale, dtype=np.float64)
    vertices, inverse = np.unique(vertices, axis=0, return_inverse=True)
    try:
        return Mesh(vertices, inverse.reshape(-1)[faces], limits=limits)._as_solid(required=False)
    except InputError as e:  # LimitError stays one
        raise type(e)(f"{place}: {e}") from None


def _geometry(g, urdf, place, limits):
    """The Mesh or Spheres of a URDF <geometry> element."""
    if g is None or len(g) == 0:
        raise InputError(f"{place}.geometry: missing")
    e = g[0]
    if e.tag == "box":
        return Mesh.box(_floats(e.get("size"), place + ".geometry.box.size"), solid=True)
    if e.tag == "sphere":
        r = _floats(e.get("radius"), place + ".geometry.sphere.radius", 1)[0]
        return Spheres([[0, 0, 0]], [r])
    if e.tag == "cylinder":
        r = _floats(e.get("radius"), place + ".geometry.cylinder.radius", 1)[0]
        h = _floats(e.get("length"), place + ".geometry.cylinder.length", 1)[0]
        return Mesh.cylinder(r, h, solid=True)
    if e.tag == "mesh":
        name = e.get("filename")
        if not name:
            raise InputError(f"{place}.geometry.mesh: no filename")
        scale = e.get("scale")
        scale = _floats(scale, place + ".geometry.mesh.scale") if scale else None
        return _mesh_file(urdf._filename_handler(name), scale, place + ".geometry.mesh", limits)
    raise InputError(f"{place}.geometry: unknown shape <{e.tag}>")
