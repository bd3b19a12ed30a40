"""Pictures of results: polyccd.apps.to_png and polyccd.apps.to_trimesh (drawing only,
floating point; see _render and _export). A SceneResult keeps the bodies it was solved
from (not pickled); a result that travelled (pickled, e.g. from a dask worker) needs
them passed back with bodies=[...]."""
from .. import InputError
from ._export import contact_scene
from ._render import render_scene


def _bodies_of(result, bodies):
    bodies = result.bodies if bodies is None else bodies
    if not bodies:
        raise InputError("bodies: this result does not hold its bodies (it was "
                         "pickled or made elsewhere); pass bodies=[...]")
    return list(bodies)


def _time_of(result, t):
    """t, else the result's first contact, else 0."""
    return t if t is not None else (result.first_contact or 0)


def to_png(result, path, *, bodies=None, t=None, **options):
    """Writes a PNG of the bodies of a SceneResult at t (default: the first contact,
    else 0) with the touching features in red (render_scene, matplotlib; options are
    its keywords); returns the path. bodies: default the ones the result was solved
    from."""
    return render_scene(_bodies_of(result, bodies), _time_of(result, t), result, path,
                        **options)


def to_trimesh(result, *, bodies=None, t=None):
    """A trimesh.Scene of the bodies of a SceneResult at t (default: the first contact,
    else 0), the touching triangles, edges, vertices and balls in red (contact_scene);
    drawing only: float poses and geometry. Needs trimesh."""
    return contact_scene(_bodies_of(result, bodies), _time_of(result, t), result)
