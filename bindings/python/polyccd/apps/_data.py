"""Example data for polyccd (polyccd.apps._data): meshes and molecules of Debian's
libcgal-demo package, read into exact polyccd bodies.

- cgal_data_file(name): a file of the libcgal-demo tarballs (data, examples, demo),
  extracted once into the cache directory ($POLYCCD_DATA_DIR, default build/data at the
  repository root, else ~/.cache/polyccd/data).
- load_mesh(path): an OFF / OBJ / STL / PLY file as a Mesh (read by trimesh).
- load_pdb(path, select): the atoms of a PDB (or mmCIF) file as balls of van der Waals
  radii (read by gemmi), with exact coordinates taken from the file's decimal text.

The bodies returned are subclasses of Mesh / Spheres that also carry the float arrays
they were built from (LoadedMesh.vertices / .triangles, LoadedSpheres.centers / .radii),
for drawing (polyccd.apps._render). trimesh and gemmi are imported only when needed.
"""
import os
import subprocess
import tarfile
import tempfile
from fractions import Fraction
from pathlib import Path

import numpy as np

from .. import InputError, Mesh, Spheres

# Where Debian puts the tarballs of libcgal-demo (/usr/share/doc/libcgal-demo is a
# symbolic link to libcgal-dev's folder in bookworm).
CGAL_DEMO_DIRS = ("/usr/share/doc/libcgal-demo", "/usr/share/doc/libcgal-dev")
CGAL_TARBALLS = ("data.tar.gz", "examples.tar.gz", "demo.tar.gz")  # searched in this order
APT_COMMAND = "apt-get install libcgal-demo"

# Bondi (1964), J. Phys. Chem. 68, 441: van der Waals radii in angstrom, as exact decimal
# texts. Other elements: gemmi's Element.vdw_r (a table of 2-decimal values stored as
# float32), rounded back to its 2 decimals.
BONDI_RADII = {"H": "1.20", "C": "1.70", "N": "1.55", "O": "1.52", "S": "1.80",
               "P": "1.80", "F": "1.47", "Cl": "1.75"}
WATERS = frozenset({"HOH", "WAT", "H2O", "DOD", "D2O", "TIP", "TIP3", "SOL"})


# --------------------------------------------------------------------------- cache ---

def data_dir():
    """The cache directory: $POLYCCD_DATA_DIR, else build/data at the repository root
    (this package in a checkout), else ~/.cache/polyccd/data. Not created here."""
    env = os.environ.get("POLYCCD_DATA_DIR")
    if env:
        return Path(env)
    root = Path(__file__).resolve().parents[4]
    if (root / "Makefile").is_file() and (root / "bindings" / "python").is_dir():
        return root / "build" / "data"
    return Path.home() / ".cache" / "polyccd" / "data"


def _tarballs():
    """The existing libcgal-demo tarballs, in search order."""
    for folder in CGAL_DEMO_DIRS:
        found = [Path(folder) / name for name in CGAL_TARBALLS]
        if all(p.is_file() for p in found):
            return found
    return []


def install_cgal_demo():
    """Installs libcgal-demo with apt-get when its tarballs are missing and this process
    runs as root (tests and the demo call it); returns True when the tarballs exist."""
    if _tarballs():
        return True
    if os.geteuid() != 0:
        return False
    env = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
    if subprocess.run(["apt-get", "install", "-y", "-qq", "libcgal-demo"], env=env,
                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode:
        subprocess.run(["apt-get", "update", "-qq"], env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        subprocess.run(["apt-get", "install", "-y", "-qq", "libcgal-demo"], env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return bool(_tarballs())


def _missing_package_error(name):
    where = " or ".join(CGAL_DEMO_DIRS)
    return InputError(
        f"{name}: the CGAL example data is missing (no {', '.join(CGAL_TARBALLS)} in "
        f"{where}); install Debian's package libcgal-demo: `{APT_COMMAND}` (as root). If "
        "the package is installed, a dpkg path-exclude rule for /usr/share/doc "
        "(/etc/dpkg/dpkg.cfg.d) may have dropped its files")


def cgal_data_file(name, *, install=False):
    """The path of the libcgal-demo file `name`, extracted into data_dir() (once).

    name: a base name ("pinion.off", "1t7i.pdb") or the end of a path in the tarballs
    ("meshes/pinion.off") when a base name is ambiguous. The tarballs are searched in the
    order data, examples, demo; the first member whose path ends with /name is taken.
    install=True: install the package with apt-get first when it is missing (root only).
    InputError when the package is absent (with the apt command) or no member matches."""
    if not isinstance(name, str) or not name or name.startswith("/") or ".." in name:
        raise InputError(f"name: {name!r} is not a file name of the CGAL data")
    target = data_dir() / "cgal" / name
    if target.is_file():
        return target
    tarballs = _tarballs()
    if not tarballs and install:
        install_cgal_demo()
        tarballs = _tarballs()
    if not tarballs:
        raise _missing_package_error(name)
    for tarball in tarballs:
        with tarfile.open(tarball) as tar:
            for member in tar:
                if member.isfile() and ("/" + member.name).endswith("/" + name):
                    target.parent.mkdir(parents=True, exist_ok=True)
                    source = tar.extractfile(member)
                    # Written to a temporary file and renamed: concurrent callers never
                    # see a partial file.
                    fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=".part-")
                    try:
                        with os.fdopen(fd, "wb") as out:
                            while True:
                                chunk = source.read(1 << 20)
                                if not chunk:
                                    break
                                out.write(chunk)
                        os.chmod(tmp, 0o644)
                        os.replace(tmp, target)
                    finally:
                        if os.path.exists(tmp):
                            os.unlink(tmp)
                    return target
    raise InputError(f"{name}: no such file in the libcgal-demo tarballs "
                     f"({', '.join(str(t) for t in tarballs)})")


# ---------------------------------------------------------------------------- meshes ---

class LoadedMesh(Mesh):
    """A Mesh read from a file. vertices: the (n, 3) float64 array the body was built
    from (its exact binary values are the body's coordinates); triangles: (m, 3) int64."""

    __slots__ = ("vertices", "triangles", "source")

    def __init__(self, vertices, triangles, source=None):
        vertices = np.array(vertices, dtype=np.float64)
        triangles = np.array(triangles, dtype=np.int64).reshape(-1, 3)
        super().__init__(vertices, triangles)
        vertices.flags.writeable = False
        triangles.flags.writeable = False
        object.__setattr__(self, "vertices", vertices)
        object.__setattr__(self, "triangles", triangles)
        object.__setattr__(self, "source", source)


def _trimesh_arrays(loaded, path):
    """(vertices, faces) of a trimesh.Trimesh or Scene (its geometries concatenated in
    their scene poses, in the order of the scene graph)."""
    import trimesh
    if isinstance(loaded, trimesh.Scene):
        parts = []
        for node in loaded.graph.nodes_geometry:
            transform, geometry_name = loaded.graph[node]
            geometry = loaded.geometry[geometry_name]
            if not isinstance(geometry, trimesh.Trimesh):
                continue
            v = np.asarray(geometry.vertices, dtype=np.float64)
            if not np.array_equal(transform, np.eye(4)):
                v = v @ np.asarray(transform[:3, :3]).T + np.asarray(transform[:3, 3])
            parts.append((v, np.asarray(geometry.faces, dtype=np.int64)))
        if not parts:
            raise InputError(f"{path}: no triangle mesh in the file")
        vertices, faces, offset = [], [], 0
        for v, f in parts:
            vertices.append(v)
            faces.append(f + offset)
            offset += len(v)
        return np.concatenate(vertices), np.concatenate(faces)
    if not isinstance(loaded, trimesh.Trimesh):
        raise InputError(f"{path}: not a triangle mesh ({type(loaded).__name__})")
    return (np.asarray(loaded.vertices, dtype=np.float64),
            np.asarray(loaded.faces, dtype=np.int64))


def load_mesh(path, *, scale=None, center=False):
    """A LoadedMesh of an OFF / OBJ / STL / PLY file, read by trimesh with process=False
    (vertices and triangles as in the file; polygons are fanned into triangles by
    trimesh). The coordinates are the file's numbers parsed as doubles, passed as their
    exact binary values.

    center=True: the bounding-box centre (computed in float) is subtracted first;
    scale: then every coordinate is multiplied by scale (in float64). The float array
    after these steps is exactly what the body uses (LoadedMesh.vertices)."""
    import trimesh
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    try:
        loaded = trimesh.load(str(path), process=False, validate=False)
    except Exception as e:  # trimesh raises many kinds
        raise InputError(f"{path}: cannot read it as a mesh ({e})") from e
    vertices, faces = _trimesh_arrays(loaded, path)
    if len(faces) == 0:
        raise InputError(f"{path}: the mesh has no triangles")
    vertices = vertices.copy()
    if center:
        vertices -= (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    if scale is not None:
        vertices *= float(scale)
    return LoadedMesh(vertices, faces, source=str(path))


# ------------------------------------------------------------------------- molecules ---

class LoadedSpheres(Spheres):
    """A Spheres read from a molecule file. centers / radii: float64 arrays (nearest
    doubles of the exact decimal values the body uses), for drawing; info: the
    AtomInfo of load_pdb (names of the balls)."""

    __slots__ = ("centers", "radii", "source", "info")

    def __init__(self, centers, radii, float_centers, float_radii, source=None, info=None):
        super().__init__(centers, radii)
        float_centers = np.array(float_centers, dtype=np.float64).reshape(-1, 3)
        float_radii = np.array(float_radii, dtype=np.float64)
        float_centers.flags.writeable = False
        float_radii.flags.writeable = False
        object.__setattr__(self, "centers", float_centers)
        object.__setattr__(self, "radii", float_radii)
        object.__setattr__(self, "source", source)
        object.__setattr__(self, "info", info)


def vdw_radius(element):
    """The van der Waals radius (angstrom, exact Fraction) used for an element symbol:
    Bondi 1964 for H C N O S P F Cl, else gemmi's table rounded to its 2 decimals."""
    import gemmi
    symbol = element if isinstance(element, str) else element.name
    symbol = symbol.strip().capitalize()
    if symbol in BONDI_RADII:
        return Fraction(BONDI_RADII[symbol])
    r = gemmi.Element(symbol).vdw_r
    if not r > 0:
        raise InputError(f"element {symbol!r}: no van der Waals radius known")
    return Fraction(f"{r:.2f}")


def _pdb_coordinate_texts(path):
    """{(serial, name, altloc, resname, chain, seqnum, icode): (x, y, z) texts} of the
    ATOM / HETATM records of the first model of a PDB file (columns 31-54)."""
    texts = {}
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            record = line[:6]
            if record in ("ATOM  ", "HETATM"):
                key = (line[6:11].strip(), line[12:16].strip(), line[16].strip(),
                       line[17:20].strip(), line[21].strip(), line[22:26].strip(),
                       line[26].strip())
                texts.setdefault(key, (line[30:38].strip(), line[38:46].strip(),
                                       line[46:54].strip()))
            elif record == "ENDMDL":
                break
    return texts


def _cif_coordinate_texts(path):
    """The same map for an mmCIF file (first model), from the _atom_site table."""
    import gemmi
    block = gemmi.cif.read(str(path)).sole_block()
    tags = ["id", "label_atom_id", "label_alt_id", "label_comp_id", "auth_asym_id",
            "auth_seq_id", "pdbx_PDB_ins_code", "Cartn_x", "Cartn_y", "Cartn_z",
            "pdbx_PDB_model_num"]
    table = block.find("_atom_site.", tags)
    texts, first_model = {}, None
    for row in table:
        def get(i):
            return gemmi.cif.as_string(row[i]) if row.has(i) else ""
        model = get(10)
        if first_model is None:
            first_model = model
        elif model != first_model:
            break
        key = (get(0), get(1).strip('"'), get(2).replace(".", "").replace("?", ""),
               get(3), get(4), get(5), get(6).replace("?", "").replace(".", ""))
        texts.setdefault(key, (get(7), get(8), get(9)))
    return texts


class AtomInfo:
    """What each ball of a molecule is, for reporting: lists indexed like the balls."""

    __slots__ = ("chains", "residue_names", "residue_numbers", "atom_names", "elements",
                 "serials", "coordinates", "source")

    def __init__(self, source):
        self.source = source
        self.chains, self.residue_names, self.residue_numbers = [], [], []
        self.atom_names, self.elements, self.serials, self.coordinates = [], [], [], []

    def __len__(self):
        return len(self.atom_names)

    def label(self, k):
        """A readable name of ball k: "A:ASP25 OD1" (chain:residue number atom)."""
        chain = f"{self.chains[k]}:" if self.chains[k] else ""
        name = self.residue_names[k]
        sep = "" if name[-1:].isalpha() else "-"
        return f"{chain}{name}{sep}{self.residue_numbers[k]} {self.atom_names[k]}"

    def __repr__(self):
        return f"<polyccd AtomInfo: {len(self)} atoms from {self.source}>"


def _selector(select, path):
    """A predicate (residue, entity type name) -> bool for the select argument."""
    if select is None:
        return lambda residue, kind: True
    if callable(select):
        return lambda residue, kind: bool(select(residue))
    if select == "protein":
        return lambda residue, kind: kind == "Polymer"
    if isinstance(select, str):
        names = {select}
    else:
        try:
            names = set(select)
        except TypeError:
            raise InputError(f"select: {select!r} is not None, \"protein\", a residue name, "
                             "a list of residue names or a callable") from None
    return lambda residue, kind: residue.name in names


def load_pdb(path, select=None, *, waters=False, altloc="first", radius_scale=1):
    """(LoadedSpheres, AtomInfo) of the atoms of a PDB or mmCIF file (first model),
    read by gemmi, as balls of van der Waals radius (vdw_radius; times radius_scale, an
    exact number such as Fraction or str, default 1).

    select: None (every atom), "protein" (residues of polymer entities), a residue name
    such as "017" (darunavir in 1t7i), a list of residue names, or a callable taking a
    gemmi.Residue. Waters are excluded unless waters=True. altloc="first": of atoms with
    alternative locations keep those of the first one in the file (blank or "A" usually);
    altloc=None keeps them all. Coordinates are exact: the decimal texts of the file
    (Fraction("14.264"), not the nearest double). InputError when nothing is selected."""
    import gemmi
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    try:
        structure = gemmi.read_structure(str(path))
    except Exception as e:
        raise InputError(f"{path}: cannot read it as a molecule ({e})") from e
    is_cif = path.suffix.lower() in (".cif", ".mmcif") or path.name.lower().endswith(".cif.gz")
    if len(structure) == 0:
        raise InputError(f"{path}: no model in the file")
    texts = _cif_coordinate_texts(path) if is_cif else _pdb_coordinate_texts(path)
    return _atoms(structure, str(path), texts, select, waters, altloc, radius_scale)


def spheres_from_gemmi(source, select=None, *, waters=False, altloc="first", radius_scale=1):
    """The atoms of a molecule as balls of van der Waals radius (Bondi 1964 for H C N O
    S P F Cl, else gemmi's table to its 2 decimals; times radius_scale, exact).

    source: a PDB or mmCIF path (str or os.PathLike): the centres are the decimal texts
    of the file exactly ("14.264" is 14264/1000, not a double; load_pdb); or a
    gemmi.Structure / gemmi.Model in memory: the centres are gemmi's float64 positions
    at their exact binary values. First model only; select, waters, altloc as load_pdb.
    Returns a LoadedSpheres (a polyccd.Spheres) whose .info (an AtomInfo) names each
    ball. Needs gemmi."""
    import gemmi
    if isinstance(source, (str, os.PathLike)):
        return load_pdb(source, select, waters=waters, altloc=altloc,
                        radius_scale=radius_scale)[0]
    if isinstance(source, gemmi.Model):
        structure = gemmi.Structure()
        structure.add_model(source)
    elif isinstance(source, gemmi.Structure):
        structure = source
    else:
        raise InputError(f"source: expected a PDB or mmCIF path, a gemmi.Structure or a "
                         f"gemmi.Model, got {type(source).__name__}")
    if len(structure) == 0:
        raise InputError("source: no model in the structure")
    return _atoms(structure, "source", None, select, waters, altloc, radius_scale)[0]


def _atoms(structure, where, texts, select, waters, altloc, radius_scale):
    """(LoadedSpheres, AtomInfo) of the first model of a gemmi structure. texts: the
    coordinate texts of the file (exact decimals; checked against gemmi's positions),
    or None: gemmi's float64 positions, at their exact binary values."""
    structure = structure.clone()
    structure.setup_entities()
    keep = _selector(select, where)
    try:
        scale = Fraction(radius_scale)
    except (TypeError, ValueError):
        raise InputError(f"radius_scale: {radius_scale!r} is not a number") from None
    if scale <= 0:
        raise InputError(f"radius_scale: {radius_scale!r} is not > 0")
    info = AtomInfo(where)
    centers, radii, float_centers, float_radii = [], [], [], []
    radius_of = {}
    for chain in structure[0]:
        for residue in chain:
            kind = residue.entity_type.name
            if (kind == "Water" or residue.name in WATERS) and not waters:
                continue
            if not keep(residue, kind):
                continue
            first_alt = None
            for atom in residue:
                if atom.altloc != "\0" and altloc == "first":
                    first_alt = first_alt or atom.altloc
                    if atom.altloc != first_alt:
                        continue
                alt = "" if atom.altloc == "\0" else atom.altloc
                seq = f"{residue.seqid.num}"
                icode = residue.seqid.icode.strip()
                pos = (atom.pos.x, atom.pos.y, atom.pos.z)
                if texts is None:
                    exact = tuple(Fraction(p) for p in pos)  # the doubles' binary values
                    xyz = exact
                else:
                    key = (str(atom.serial), atom.name, alt, residue.name, chain.name, seq, icode)
                    xyz = texts.get(key)
                    if xyz is None:
                        raise InputError(f"{where}: cannot find the coordinate text of atom "
                                         f"{atom.serial} {atom.name} of {residue.name}{seq}")
                    exact = tuple(Fraction(x) for x in xyz)
                    if any(abs(float(e) - p) > 1e-6 * max(1.0, abs(p)) for e, p in zip(exact, pos)):
                        raise InputError(f"{where}: atom {atom.serial}: text {xyz} differs from "
                                         f"gemmi's position {pos}")
                element = atom.element.name
                if element not in radius_of:
                    radius_of[element] = vdw_radius(element) * scale
                r = radius_of[element]
                centers.append(list(xyz))
                radii.append(r)
                float_centers.append([float(e) for e in exact])
                float_radii.append(float(r))
                info.chains.append(chain.name)
                info.residue_names.append(residue.name)
                info.residue_numbers.append(residue.seqid.num)
                info.atom_names.append(atom.name)
                info.elements.append(element)
                info.serials.append(atom.serial)
                info.coordinates.append(exact)
    if not centers:
        raise InputError(f"{where}: no atom selected by select={select!r}")
    return LoadedSpheres(centers, radii, float_centers, float_radii, where, info), info
