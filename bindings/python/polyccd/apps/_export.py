"""A result's contact as a trimesh.Scene (polyccd.apps.to_trimesh): every body at a time
t, the touching features in red.

Drawing only, in floating point, like polyccd.apps._render: each body's pose at t is
taken exactly from its Motion and rounded once (_draw_geometry._float_pose), the geometry is
the shapes' float arrays (Mesh.vertices / .triangles, Spheres.centers / .radii). Balls
are icospheres (subdivision 1); touching edges are red line paths, touching vertices
red points, touching triangles and balls red faces.
"""
import numpy as np

from ..extras import need

from ._draw_geometry import BODY_COLORS, HIGHLIGHT, _arrays, _contacts, _edges_of, _float_pose, _parts


def _rgba(hex_color):
    return np.array([int(hex_color[k:k + 2], 16) for k in (1, 3, 5)] + [255], dtype=np.uint8)


def contact_scene(bodies, t, contacts):
    """A trimesh.Scene of bodies (polyccd.Body or (shape, motion[, name])) at time t
    (number, str or ContactTime) with the features of contacts (a SceneResult, PairResults
    or (body, (kind, k)) items) in red. Geometry node names: the body names, and
    "<name>/touching-edges", "<name>/touching-vertices" for the highlighted features."""
    # trimesh's paths (the touching edges) import scipy.
    trimesh = need("polyccd.apps.to_trimesh", "interop", "trimesh", "scipy.sparse")
    scene = trimesh.Scene()
    features = _contacts(contacts, len(bodies))
    red = _rgba(HIGHLIGHT)
    for i, body in enumerate(bodies):
        shape, motion, name = _parts(body, i)
        kind, a, b = _arrays(shape, None, i)
        R, o = _float_pose(motion, t)
        color = _rgba(BODY_COLORS[i % len(BODY_COLORS)])
        mine = [(k_kind, k) for j, k_kind, k in features if j == i]
        if kind == "mesh":
            world = a @ R.T + o
            mesh = trimesh.Trimesh(world, b, process=False, validate=False)
            colors = np.tile(color, (len(b), 1))
            for k_kind, k in mine:
                if k_kind == "triangle":
                    colors[k] = red
            mesh.visual.face_colors = colors
            scene.add_geometry(mesh, node_name=name, geom_name=name)
            edges = [k for k_kind, k in mine if k_kind == "edge"]
            if edges:
                ends = world[_edges_of(b)[edges]]
                path = trimesh.load_path(ends)
                path.colors = np.tile(red, (len(path.entities), 1))
                scene.add_geometry(path, node_name=f"{name}/touching-edges",
                                   geom_name=f"{name}/touching-edges")
            verts = [k for k_kind, k in mine if k_kind == "vertex"]
            if verts:
                cloud = trimesh.PointCloud(world[verts], colors=np.tile(red, (len(verts), 1)))
                scene.add_geometry(cloud, node_name=f"{name}/touching-vertices",
                                   geom_name=f"{name}/touching-vertices")
        else:
            centers = a @ R.T + o
            touching = {k for k_kind, k in mine if k_kind == "sphere"}
            unit = trimesh.creation.icosphere(subdivisions=1)
            nv, nf = len(unit.vertices), len(unit.faces)
            verts = (unit.vertices[None, :, :] * b[:, None, None] + centers[:, None, :])
            faces = unit.faces[None, :, :] + (np.arange(len(centers)) * nv)[:, None, None]
            balls = trimesh.Trimesh(verts.reshape(-1, 3), faces.reshape(-1, 3), process=False,
                                    validate=False)
            colors = np.tile(color, (len(centers) * nf, 1))
            for k in touching:
                colors[k * nf:(k + 1) * nf] = red
            balls.visual.face_colors = colors
            scene.add_geometry(balls, node_name=name, geom_name=name)
    return scene
