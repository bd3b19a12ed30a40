"""The body demo: the two scenes of polyccd.apps._demo_scenes (two CGAL pinions meshing;
darunavir and the HIV-1 protease of 1t7i) checked exactly with polyccd.check, printed,
and drawn at their first contact time (scene_mechanical.png, scene_ligand.png)."""
import time
from pathlib import Path

from ._demo_scenes import ligand_scene, mechanical_scene
from ..texts import ratio_text
from ._render import _float_pose, render_scene


def _q(x):
    return ratio_text(x.numerator, x.denominator)


def time_text(ct):
    """An exact first contact time, or its enclosure, with its float value."""
    if ct is None:
        return "none"
    if ct.exact is not None:
        return f"t = {_q(ct.exact)} (= {ct.approx:.15g}, exact)"
    return (f"t in [{_q(ct.lo)}, {_q(ct.hi)}] (width {float(ct.hi - ct.lo):.2g}), "
            f"t ~ {ct.approx:.15g}")


def _feature_text(body, feature, t):
    """A touching feature named for people: atoms by residue and atom name, mesh
    features by index with their position at t (float)."""
    kind, k = feature
    shape = body.shape
    info = getattr(shape, "info", None)
    if kind == "sphere" and info is not None:
        return f"{body.name} atom {info.label(k)} ({info.elements[k]}, r = {shape.radii[k]:g} A)"
    if hasattr(shape, "vertices"):
        R, o = _float_pose(body.motion, t)
        if kind == "vertex":
            p = [shape.vertices[k]]
        elif kind == "edge":
            p = shape.vertices[shape.edges[k]]
        elif kind == "triangle":
            p = shape.vertices[shape.triangles[k]]
        else:
            p = [shape.centers[k]]
        at = ", ".join("(" + " ".join(f"{x:.4f}" for x in q @ R.T + o) + ")" for q in p)
        return f"{body.name} {kind} {k} at {at}"
    return f"{body.name} {kind} {k}"


def run_scene(label, bodies, description, out_dir, *, threads=2, out=print):
    """Checks one scene, prints its answer and writes out_dir/scene_<label>.png at the
    first contact time; returns (SceneResult, seconds, png path or None)."""
    import polyccd
    out(f"== {label}")
    out(description)
    start = time.perf_counter()
    result = polyccd.check(bodies, threads=threads)
    seconds = time.perf_counter() - start
    out(f"collides: {result.collides}")
    out(f"first contact: {time_text(result.first_contact)}")
    t = result.first_contact
    contacts = []
    for pair in result.first:
        a, b = (bodies[i] for i in pair.bodies)
        out(f"pair {pair.names[0]} / {pair.names[1]}: {time_text(pair.first_contact)}")
        for c in pair.contacts:
            out(f"  touching: {_feature_text(a, c.a, t)}  <->  {_feature_text(b, c.b, t)}")
            contacts.append((pair.bodies[0], tuple(c.a)))
            contacts.append((pair.bodies[1], tuple(c.b)))
    stats = ", ".join(f"{k} {v}" for k, v in result.stats.items())
    out(f"wall time of polyccd.check (threads={threads}): {seconds:.3f} s  [{stats}]")
    png = None
    if result.collides:
        labels = {i: getattr(b.shape, "info", None) for i, b in enumerate(bodies)}
        png = render_scene(bodies, t, contacts, Path(out_dir) / f"scene_{label}.png",
                           title=f"{label}: first contact, {time_text(t)}", labels=labels)
        out(f"picture: {png}")
    return result, seconds, png


def run_demo_scenes(out_dir="build/demo", *, threads=2, out=print):
    """Runs the scenes; returns {label: (SceneResult, seconds, png path)}."""
    results = {}
    # The ligand twice: leaving the pocket from its crystal pose (it already overlaps the
    # protease there with van der Waals balls, so the answer is a clash at t = 0, with
    # the atoms), and entering along the same path reversed (the first contact from
    # outside; a leaving ligand is free after 1 - t*).
    scenes = (("mechanical", mechanical_scene), ("ligand", ligand_scene),
              ("ligand_leaving", lambda: ligand_scene("leave")))
    for label, make in scenes:
        start = time.perf_counter()
        bodies, description = make()
        out(f"(scene {label} loaded in {time.perf_counter() - start:.2f} s)")
        results[label] = run_scene(label, bodies, description, out_dir, threads=threads,
                                   out=out)
    return results


if __name__ == "__main__":  # python -m polyccd._demo_bodies [OUT_DIR]
    import sys
    run_demo_scenes(sys.argv[1] if len(sys.argv) > 1 else "build/demo")
