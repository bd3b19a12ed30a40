"""polyccd.apps: the applications built on the polyccd bindings.

What a user calls (each documented in docs/python.md):
    polyccd.apps.load_scene(path_or_doc)          a polyccd/1 scene file -> (bodies, options, expect)
    polyccd.apps.to_png(result, path, ...)        a picture of a SceneResult (matplotlib)
    polyccd.apps.to_trimesh(result, ...)          a trimesh.Scene of a SceneResult
    polyccd.apps.spheres_from_gemmi(source, ...)  a molecule's atoms as balls (gemmi)
    polyccd.apps.load_mesh, load_pdb              example-data loaders (trimesh, gemmi)
    polyccd.apps.distributed                      batches on a dask cluster (import it)

Inside: the command line (cli, `polyccd ...`), the CSV query-set and JSON case/scene
readers (_csv, _json, _scene_file), the corpus and query-set runners (_corpus,
_queries), the example-data loaders (_data: trimesh, gemmi), the scene renderer
(_render: matplotlib; _export: trimesh) and the demo (_demo*). `import polyccd` never
imports this package and no core module imports it; each optional third-party module
is imported only by the function that needs it.
"""
from ._data import load_mesh, load_pdb, spheres_from_gemmi
from ._scene_file import load_scene
from .render import to_png, to_trimesh

__all__ = ["load_scene", "to_png", "to_trimesh", "spheres_from_gemmi", "load_mesh", "load_pdb"]
