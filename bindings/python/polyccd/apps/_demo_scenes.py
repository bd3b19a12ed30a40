"""The two demo scenes on real data of Debian's libcgal-demo package (polyccd.data):

- mechanical_scene(): two copies of CGAL's pinion (a 10-tooth gear) in mesh; one
  approaches the other along a cubic Bezier path while turning about its own axis.
- ligand_scene(): darunavir (residue "017") and the HIV-1 protease of PDB 1t7i, both as
  van der Waals balls; the ligand moves along a cubic Bezier path with a small rotation,
  the protease is stationary.

Each returns (bodies, description): bodies are polyccd.Body objects (or, before the
Scenes API exists, (shape, motion, name) tuples with the same fields), description a
text that says what the scene is and what answer to expect. Every motion is exact: its
coefficients are rationals written here (or exact doubles of the meshes), so the scene
is the same on every machine. The float checks of the tests (trimesh / python-fcl) are
sanity checks of the construction only, never a contact decision.
"""
from collections import namedtuple
from fractions import Fraction as F

import numpy as np

from ._data import cgal_data_file, load_mesh, load_pdb
from .. import Motion

SceneBody = namedtuple("SceneBody", "shape motion name")

# The pinion of pinion.off: 10 teeth, root radius 0.57, tip radius 0.75, bore radius
# 0.35, length 1, its axis along PINION_AXIS (measured on the file's end-cap normals:
# (-0.82774, -0.31405, 0.46499); rounded to 4 decimals, a 1e-4 tilt at most).
PINION_AXIS = (F("-0.8277"), F("-0.3141"), F("0.4650"))
PINION_ROOT, PINION_TIP = 0.57, 0.75


def _body(shape, motion, name):
    import polyccd
    if hasattr(polyccd, "Body"):
        return polyccd.Body(shape, motion, name)
    return SceneBody(shape, motion, name)


def bezier_coefficients(ctrl):
    """The power-basis coefficients [[x0..x3], [y0..y3], [z0..z3]] (exact Fractions) of
    the cubic Bezier curve of 4 control points (same curve as Motion.bezier)."""
    c0, c1, c2, c3 = ([F(x) for x in p] for p in ctrl)
    return [[c0[k], 3 * (c1[k] - c0[k]), 3 * (c2[k] - 2 * c1[k] + c0[k]),
             c3[k] - 3 * c2[k] + 3 * c1[k] - c0[k]] for k in range(3)]


def _turning_bezier(ctrl, axis, tau0, tau1, pivot=(0, 0, 0)):
    """The motion x(t) = R(r(t)) (p - pivot) + B(t) with B the cubic Bezier curve of ctrl
    and r(t) = 1 + tau(t) axis, tau linear from tau0 to tau1: the body turns about the
    axis through its point `pivot`, which travels along B."""
    tau0, tau1 = F(tau0), F(tau1)
    rotation = [[1]] + [[tau0 * F(a), (tau1 - tau0) * F(a)] for a in axis]
    motion = Motion(translation=bezier_coefficients(ctrl), rotation=rotation)
    if any(F(x) for x in pivot):
        motion = motion.compose([1, 0, 0, 0], [-F(x) for x in pivot], side="body")
    return motion


# ------------------------------------------------------------------ the gear pair ---

def pinion_pose():
    """The rational quaternion q turning PINION_AXIS to z: q = (1 + a_z, a_y, -a_x, 0)
    (any length; exact)."""
    ax, ay, az = PINION_AXIS
    return [1 + az, ay, -ax, F(0)]


# The path of the moving pinion's centre (z = 0 plane) and its turn about its axis.
# The centre moves in the plane z = z_offset (default 0.2: the end caps of the two
# pinions are not coplanar; 0 makes them coplanar, a harder degenerate case).
GEAR_PATH = [["2.6", "1.4"], ["2.0", "0.5"], ["1.5", "0.1"], ["1.05", "0"]]
GEAR_TAU = ("0", "0.3")  # tan(angle / 2) goes from 0 to 0.3: a turn of 33.4 degrees


def mechanical_scene(z_offset="0.2", *, install=False):
    """Two pinions of pinion.off (650 vertices, 1300 triangles each), centred on their
    bounding boxes (in float; these doubles are the bodies) and turned by pinion_pose()
    so their axes are z. Pinion A stays at the origin. Pinion B's centre follows the
    cubic Bezier path GEAR_PATH from (2.6, 1.4) to (1.05, 0) in the plane z = z_offset
    (an exact number; B is shifted along its axis by it) while it turns about
    its own axis by 2 atan(0.3) = 33.4 degrees. At t = 0 the centres are 2.96 apart
    (> 2 x tip radius 1.5: apart); at t = 1 they are 1.05 apart (< 2 x root radius 1.14:
    the gear bodies overlap, so their surfaces cross). The first contact is a tooth tip
    of one pinion meeting the other."""
    mesh = load_mesh(cgal_data_file("pinion.off", install=install), center=True)
    q = pinion_pose()
    fixed = Motion().compose(q, [0, 0, 0], side="body")
    path = [xy + [F(z_offset)] for xy in GEAR_PATH]
    moving = _turning_bezier(path, (0, 0, 1), *GEAR_TAU).compose(q, [0, 0, 0],
                                                                      side="body")
    bodies = [_body(mesh, fixed, "pinion A"), _body(mesh, moving, "pinion B")]
    description = (
        "mechanical: two CGAL pinions (pinion.off, 10 teeth, 1300 triangles each). "
        "Pinion A is fixed at the origin, axis z. Pinion B approaches along a cubic "
        f"Bezier path, centre (2.6, 1.4, {z_offset}) -> (1.05, 0, {z_offset}), turning "
        "33.4 degrees about its axis. Expected: apart at t = 0 (centres 2.96 apart, tips reach 1.5), "
        "overlapping at t = 1 (centres 1.05 apart < 2 x root radius 1.14); first "
        "contact when a tooth tip of one pinion meets the other, at a centre distance "
        "between 1.14 and 1.5, i.e. some t in (0.6, 1); features: vertex/edge of a "
        "tooth with a triangle/edge of the other.")
    return bodies, description


# --------------------------------------------------------------- ligand and pocket ---

# HIV-1 protease / darunavir (1t7i). The ligand's path is chosen from the structure:
# EXIT is the unit-ish direction from the midpoint of the two catalytic Asp25 CA atoms to
# the midpoint of the two flap-tip Ile50 CA atoms (0.004, 0.547, -0.837), rounded to 3
# decimals; SIDE is a direction across it. The ligand turns about ROT_AXIS through its
# bounding-box centre by 2 atan(LIGAND_TAU) = 28 degrees over the path.
EXIT = (F("0.004"), F("0.547"), F("-0.837"))
SIDE = (F("-0.99"), F("0.1"), F("0.06"))
ROT_AXIS = (F("0.6"), F("0.0"), F("0.8"))
LIGAND_TAU = F("0.25")
LIGAND_LEAVE = ((0, 0), (8, 0), (16, 3), (24, 6))  # (along EXIT, along SIDE) in angstrom


def ligand_path(direction="enter"):
    """The 4 Bezier control points (exact) of the ligand's displacement: direction
    "leave" from the crystal pose (0) out through the flaps to 24 A along EXIT and 6 A
    along SIDE; "enter" is the same curve traversed backwards."""
    ctrl = [[a * e + s * w for e, w in zip(EXIT, SIDE)] for a, s in LIGAND_LEAVE]
    return ctrl if direction == "leave" else ctrl[::-1]


def ligand_scene(direction="enter", *, install=False):
    """The protease (polymer atoms of 1t7i, first altloc, 1492 balls) stationary, and
    darunavir (residue 017, 38 balls) on a cubic Bezier path with a small rotation,
    van der Waals radii (Bondi 1964). direction="enter" (default): the ligand comes
    from 24 A out along the flap direction and ends in its crystal pose at t = 1;
    "leave": the same path backwards (crystal pose at t = 0, outside at t = 1).

    In the crystal pose the ligand's balls already overlap the protease's (hydrogen
    bonds are shorter than the sum of van der Waals radii: Asp25 OD1 (chain B) to O18 is
    2.54 A against 1.52 + 1.52), so "leave" touches at t = 0 trivially, while "enter"
    has a first contact inside (0, 1): the time the leaving ligand would get free is
    1 - t*. The atoms' labels are in bodies[i].shape.info (AtomInfo)."""
    if direction not in ("enter", "leave"):
        raise ValueError(f'direction: {direction!r} is not "enter" or "leave"')
    path = cgal_data_file("1t7i.pdb", install=install)
    protein, _ = load_pdb(path, "protein")
    ligand, info = load_pdb(path, "017")
    coords = np.array(info.coordinates, dtype=object)
    pivot = [(min(coords[:, k]) + max(coords[:, k])) / 2 for k in range(3)]  # exact
    ctrl = [[pivot[k] + d[k] for k in range(3)] for d in ligand_path(direction)]
    tau = (0, LIGAND_TAU) if direction == "leave" else (LIGAND_TAU, 0)
    motion = _turning_bezier(ctrl, ROT_AXIS, *tau, pivot=pivot)
    bodies = [_body(protein, None, "protease"), _body(ligand, motion, "darunavir")]
    if direction == "enter":
        expect = ("apart at t = 0 (24 A out along the flaps, > 3 A clear), overlapping "
                  "at t = 1 (crystal pose: 9 atom pairs overlap, up to 0.50 A); first "
                  "contact inside (0, 1) with atoms of the flaps (residues 45-55) or the "
                  "rim of the pocket. Leaving along the same path, the ligand is free "
                  "after 1 - t*.")
    else:
        expect = ("first contact at t = 0: the crystal pose already overlaps (e.g. B:ASP25 "
                  "OD1 with O18 of darunavir, 0.50 A)")
    description = (f"ligand ({direction}): darunavir (1t7i residue 017, 38 atoms) and the "
                   "HIV-1 protease (1492 atoms, waters excluded), van der Waals balls; "
                   "cubic Bezier path along the flap direction with a 28 degree turn. "
                   f"Expected: {expect}")
    return bodies, description
