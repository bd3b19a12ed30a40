"""Robots from URDF: a kinematic chain (polyccd.Chain, C) with each link's collision
geometry as polyccd bodies, checked exactly over joint-space segments.

Reading only: the URDF is parsed by yourdfpy (links, joints, mimic joints, mesh file
names), meshes by trimesh; both are imported when a URDF is loaded, never by
`import polyccd`. The origins (xyz, rpy) are read from the URDF's own text, each number
the double nearest its decimal, which the chain then takes exactly (yourdfpy keeps only
a 4x4 matrix computed in floats). Every kinematic computation is the C library's
(pccd_chain_*, pccd_motion_*, pccd_scene_*). See docs/robots.md.

Policies (stated once, checked here or by the C library):
  - joints: fixed, revolute, continuous (a revolute joint without limits), prismatic;
    floating and planar joints are rejected (move the base yourself: each Motion of
    Robot.motions(q0, q1) composed with a base Motion, link.then(base)). A segment of a
    revolute or continuous joint must turn by less than 2 pi (split it; the C library
    decides and names the joint, "q1[2] (elbow): ...").
  - joint limits (URDF <limit lower upper>, actuated revolute and prismatic joints;
    continuous joints have none): Robot.check and check_path take
    joint_limits="error" (default): an InputError naming the waypoint, the joint and
    the value when q0 or q1 is outside [lower, upper] (closed; doubles compared as
    they are), or joint_limits="ignore". The ends suffice: each joint moves
    monotonically between its two end values (chain.h). Mimic joints follow their
    leader and are not checked against limits of their own.
  - mimic joints follow their leader at the segment's ends (value = multiplier * leader +
    offset, in doubles); in between a prismatic mimic follows exactly (both linear), a
    revolute one interpolates its own half-angle tangent.
  - geometry (collision by default): meshes as their triangles (vertices times the
    URDF scale in doubles, exactly equal vertices merged), boxes as 12 triangles,
    spheres as balls; a cylinder as the prism over a 16-gon circumscribing its circle (a
    stand-in that contains it: polyccd has no cylinder primitive). Solids where closed:
    boxes, cylinders and every mesh whose merged triangles are closed and consistently
    oriented (Mesh.from_trimesh's rule); other meshes stay surfaces.
  - each geometry with a nonzero origin is one more chain link under its URDF link, on
    a fixed joint (named "<link>#<i>"), so the origin rotation is exact as well.
"""
from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import (TYPE_CHECKING, Any, Dict, FrozenSet, Iterable, List, Optional, Sequence, Set,
                    Tuple, Union)

import numpy as np

from . import _joint_values as _jv
from . import _limits
from ._chain import Chain
from ._errors import InputError
from ._extras import need
from ._types import Number
from ._path import file_path
from ._solve import _items
from ._urdf_check import check_urdf
from ._urdf_geometry import _floats, _geometry, _origin

if TYPE_CHECKING:
    from ._limits import Limits
    from ._motion import Motion
    from ._scene import Body

# The public names (the generated reference lists each: tests/test_docs.py).
__all__ = ["load_urdf", "Robot", "RobotResult", "RobotContact", "PathResult", "RobotBatch", "SUPPORTED"]

#: The URDF joint types load_urdf reads (floating and planar joints are refused).
SUPPORTED = ("fixed", "revolute", "continuous", "prismatic")

class Robot:
    """A robot read from URDF (load_urdf). Attributes: name; links (URDF link names, in
    chain order); joints (the actuated joints' names: the order of q); chain (the
    polyccd.Chain, one link per URDF link plus one per offset geometry); shapes: list of
    (link name, geometry index, chain index, Mesh | Spheres) (a list: replace the
    geometry at will); tree: {URDF link: (parent link, joint type)} (root: None);
    joint_types: {joint: type}; mimic_joints: {joint: (leader, multiplier, offset)};
    limits: {actuated joint: (lower, upper) or None}."""

    def __init__(self, name: str, links: List[str], joints: List[str], chain: Chain, shapes: list,
                 joint_link: Dict[str, int], mimic: dict, limits: dict, tree: dict) -> None:
        self.name, self.links, self.joints = name, links, joints
        self.tree = tree                # URDF link -> (parent link, joint type); root: None
        self.chain, self.shapes = chain, shapes
        self._joint_link = joint_link   # actuated joint name -> chain index of its child link
        self._mimic = mimic             # chain index -> (leader name, multiplier, offset)
        self.limits = limits            # joint name -> (lower, upper) or None
        self.link_index = {n: i for i, n in enumerate(links)}  # URDF link -> chain index

    def chain_values(self, q: Sequence[float], place: str = "q") -> np.ndarray:
        """The chain's joint values (by chain link) of the actuated joint values q (real
        numbers, each exactly a double; InputError naming place otherwise)."""
        return _jv.expand(self, _jv.q_array(self, q, place))

    def motions(self, q0: Sequence[float], q1: Sequence[float]) -> List[Motion]:
        """The exact world Motion of every chain link over the segment q0 -> q1. A bad
        joint value is named by the C library in q's terms ("q1[2] (elbow): ...": load_urdf
        gives the chain each value's place, Chain.set_value_place)."""
        return self.chain.motions(self.chain_values(q0, "q0"), self.chain_values(q1, "q1"))

    def link_motions(self, q0: Sequence[float], q1: Sequence[float]) -> Dict[str, Motion]:
        """{URDF link name: Motion} over the segment q0 -> q1."""
        m = self.motions(q0, q1)
        return {n: m[i] for i, n in enumerate(self.links)}

    def joint_values(self, q0: Sequence[float], q1: Sequence[float], t: Number) -> Dict[str, float]:
        """{actuated joint name: value at time t} of the segment (floats; outputs)."""
        v = self.chain.joint_values(self.chain_values(q0, "q0"), self.chain_values(q1, "q1"), t)
        return {name: float(v[self._joint_link[name]]) for name in self.joints}

    def check_joint_limits(self, q0: Sequence[float], q1: Sequence[float],
                           joint_limits: str = "error") -> None:
        """The joint-limit policy of check() (see the module comment): InputError
        "q0[j] (joint): value is outside the joint limits [lower, upper]" unless
        joint_limits is "ignore". Non-finite values are left to the chain's check."""
        if joint_limits == "ignore":
            return
        if joint_limits != "error":
            raise InputError(f'joint_limits: {joint_limits!r} is not "error" or "ignore"')
        bounds = _jv.limit_arrays(self)
        for place, q in (("q0", q0), ("q1", q1)):
            _jv.check_limits(self, _jv.q_array(self, q, place), place, bounds)

    def adjacent_pairs(self) -> Set[FrozenSet[str]]:
        """The default allowed link pairs: URDF links joined by a path of joints with at
        most one moving joint (fixed joints merge links into one rigid group; a group and
        the group it hangs from by one moving joint are adjacent)."""
        def group(link):
            while self.tree[link] is not None and self.tree[link][1] == "fixed":
                link = self.tree[link][0]
            return link
        up = {}
        for link, pj in self.tree.items():
            if pj is not None and pj[1] != "fixed":
                up[link] = group(pj[0])  # a group root hangs from this group
        urdf_links = list(self.tree)
        out = set()
        for i, a in enumerate(urdf_links):
            for b in urdf_links[i + 1:]:
                ga, gb = group(a), group(b)
                if ga == gb or up.get(ga) == gb or up.get(gb) == ga:
                    out.add(frozenset((a, b)))
        return out

    def bodies(self, q0: Sequence[float], q1: Sequence[float]) -> Tuple[List[Body], List[str]]:
        """The robot's geometry as polyccd Bodies on their exact motions over q0 -> q1,
        named "<link>" (or "<link>[i]" for a link with several geometries), with the URDF
        link of each."""
        m = self.motions(q0, q1)
        count = {}
        for link, _, _, _ in self.shapes:
            count[link] = count.get(link, 0) + 1
        from ._scene import Body
        return ([Body(shape, m[k], name=link if count[link] == 1 else f"{link}[{i}]")
                 for link, i, k, shape in self.shapes],
                [link for link, _, _, _ in self.shapes])

    def check(self, q0: Sequence[float], q1: Sequence[float], obstacles: Iterable[Body] = (), *,
              self_collision: bool = True, allowed: Optional[Iterable[Tuple[str, str]]] = None,
              time_tolerance: Number = "1e-12", all_contacts: bool = False, threads: int = 1,
              broad_phase: str = "auto", min_distance: Optional[Number] = None,
              limits: Optional[Limits] = None, first_contact: bool = True, filter: bool = True,
              joint_limits: str = "error") -> RobotResult:
        """The exact first contact over the segment q0 -> q1 of the robot with the
        obstacles (polyccd.Body, stationary or moving) and, when self_collision, of its
        links with each other except the allowed pairs (an iterable of link-name pairs;
        None: adjacent_pairs() and the SRDF pairs of load_urdf(srdf=...)) and a link's own
        geometries; obstacle pairs are not checked. One C call (pccd_robot_check): the
        links' poses are enclosed straight from the joint path and the exact link motions
        are built only for the pairs that filter cannot separate (filter=False: every
        pair exactly, the same answer). first_contact=False: decide mode, the check
        stops at the first pair found in contact, with a witness (features and an
        enclosure of one of its contact times). result.free_until: a certified
        contact-free prefix (no contact at any t < free_until; a planner's last valid
        state). min_distance: delta >= 0 (pccd_config.min_distance): a contact is the
        first time the checked pairs come within delta. limits: a polyccd.Limits for the
        whole check. joint_limits: "error" (default) or "ignore", check_joint_limits().
        Returns a RobotResult (first contact, contacts by link name and feature, joint
        values at the ends of the time enclosure); its scene lists the pairs found in
        contact on the way (all of them with all_contacts)."""
        from ._robot_check import check_robot
        ends = _jv.checked_ends(self, q0, q1, joint_limits)
        r, free = check_robot(self, ends, obstacles, self_collision=self_collision,
                              allowed=allowed, time_tolerance=time_tolerance,
                              all_contacts=all_contacts, threads=threads,
                              broad_phase=broad_phase, min_distance=min_distance,
                              limits=limits, first_contact=first_contact, filter=filter)
        return RobotResult.of(r, self, q0, q1, free)

    def check_many(self, Q0: Any, Q1: Any, obstacles: Iterable[Body] = (), *,
                   first_contact: bool = False, self_collision: bool = True,
                   allowed: Optional[Iterable[Tuple[str, str]]] = None,
                   time_tolerance: Number = "1e-12", threads: int = 1,
                   min_distance: Optional[Number] = None, limits: Optional[Limits] = None,
                   filter: bool = True, joint_limits: str = "error", results: bool = False) -> Any:
        """Many segments Q0[k] -> Q1[k] (arrays of shape (n, len(joints)), or lists of
        joint vectors) in one C call (pccd_robot_check_many), shared by `threads` workers:
        entry k is check()'s answer on segment k (decide mode by default; options as
        check()). limits bound the whole batch (a LimitError ends it). A bad segment (a
        row of the wrong length, a NaN, a value outside the joint limits) gets its error,
        naming "segments[k]", in errors[k], and the others their answers. Returns a
        polyccd.robot.RobotBatch of numpy arrays; results=True adds a RobotResult per segment."""
        from ._robot_many import check_many
        return check_many(self, Q0, Q1, obstacles, states=False, first_contact=first_contact,
                          self_collision=self_collision, allowed=allowed,
                          time_tolerance=time_tolerance, threads=threads,
                          min_distance=min_distance, limits=limits, filter=filter,
                          joint_limits=joint_limits, results=results)

    def check_states(self, Q: Any, obstacles: Iterable[Body] = (), *, self_collision: bool = True,
                     allowed: Optional[Iterable[Tuple[str, str]]] = None, threads: int = 1,
                     min_distance: Optional[Number] = None, limits: Optional[Limits] = None,
                     filter: bool = True, joint_limits: str = "error", results: bool = False) -> Any:
        """State validity of many poses Q[k] (shape (n, len(joints))) in one C call
        (pccd_robot_check_states): entry k tells whether the robot at pose k touches an
        obstacle or itself, as check(Q[k], Q[k]); errors and options as check_many
        ("states[k]"). Returns a RobotBatch."""
        from ._robot_many import check_many
        return check_many(self, Q, None, obstacles, states=True, first_contact=False,
                          self_collision=self_collision, allowed=allowed, time_tolerance="1e-12",
                          threads=threads, min_distance=min_distance, limits=limits,
                          filter=filter, joint_limits=joint_limits, results=results)

    def allowed_from_srdf(self, path: Union[str, os.PathLike]) -> Set[FrozenSet[str]]:
        """The link pairs of an SRDF file's disable_collisions elements (frozensets of
        link names); e.g. allowed=robot.adjacent_pairs() | robot.allowed_from_srdf(p)."""
        from ._robot_check import read_srdf
        return read_srdf(path, self)

    def check_path(self, waypoints: Sequence[Sequence[float]], obstacles: Iterable[Body] = (),
                   **options: Any) -> PathResult:
        """Checks the segments waypoints[0] -> waypoints[1] -> ... in order and stops at
        the first that collides: a PathResult (segment index and its RobotResult, or
        segment None when no segment collides). Options as check()."""
        w = list(_items(waypoints, "waypoints", "a list of joint vectors"))
        for k, q in enumerate(w):
            self.chain_values(q, f"waypoints[{k}]")  # the type and shape checks
        obstacles = _items(obstacles, "obstacles", "an iterable of polyccd.Body")
        from ._scene import Body
        for k, o in enumerate(obstacles):
            if not isinstance(o, Body):
                raise InputError(f"obstacles[{k}]: expected a polyccd.Body, got {type(o).__name__}")
        if len(w) < 2:
            raise InputError(f"waypoints: a path needs at least 2 waypoints, got {len(w)}")
        for s in range(len(w) - 1):
            try:
                r = self.check(w[s], w[s + 1], obstacles, **options)
            except InputError as e:  # the same class (LimitError stays one), placed
                raise type(e)(f"waypoints[{s}] -> waypoints[{s + 1}]: {e}") from None
            if r.collides:
                return PathResult(s, r)
        return PathResult(None, None)


@dataclass(frozen=True)
class RobotContact:
    """Two touching features: (body name, feature kind, index) each, the pair's time."""
    a: tuple
    b: tuple
    first_contact: object


@dataclass(frozen=True)
class RobotResult:
    """The answer of Robot.check over one joint-space segment: whether anything touches,
    the first contact time, the feature pairs that may touch first, the joint values at
    the ends of the time's enclosure, the scene's answer and a certified contact-free
    prefix (free_until)."""
    collides: bool
    first_contact: object          # ContactTime or None
    contacts: tuple                # RobotContact of the pairs that may touch first
    joint_values: Optional[tuple]  # ({joint: value} at first_contact.lo, at .hi)
    scene: object                  # the SceneResult
    free_until: object = None      # Fraction: no contact at any t < free_until

    @staticmethod
    def of(r, robot, q0, q1, free_until=None):
        contacts = tuple(RobotContact((p.names[0],) + tuple(c.a), (p.names[1],) + tuple(c.b),
                                      c.first_contact) for p in r.first for c in p.contacts)
        values = None
        if r.collides:
            values = (robot.joint_values(q0, q1, r.first_contact.lo),
                      robot.joint_values(q0, q1, r.first_contact.hi))
        return RobotResult(r.collides, r.first_contact, contacts, values, r, free_until)


@dataclass(frozen=True)
class PathResult:
    """The answer of Robot.check_path: the first segment in contact and its RobotResult
    (both None when the whole path is contact-free)."""
    segment: Optional[int]   # the first colliding segment (waypoints[s] -> [s + 1]), or None
    result: Optional[RobotResult]

def load_urdf(path: Union[str, os.PathLike], *, geometry: str = "collision",
              srdf: Optional[Union[str, os.PathLike]] = None,
              limits: Optional[Limits] = None) -> Robot:
    """A Robot from the URDF file at path; geometry: "collision" (default) or "visual";
    srdf: an SRDF file whose disable_collisions pairs Robot.check allows by default (with
    the adjacent pairs).
    Mesh file names ("package://...", relative) are resolved by yourdfpy's default
    handler (relative to the URDF file and its parent folders). InputError for a
    missing or unreadable file, an unsupported joint type, a zero axis, a bad number,
    and for a file that is not a tree as urdfdom requires (_urdf_check: a duplicate link
    or joint name, a link with two parents, a cycle, parent == child, a missing link),
    naming the element and its line. limits: a polyccd.Limits for the building (the
    collision bodies, pccd_body_new_mesh_cfg_*), LimitError when reached."""
    yourdfpy = need("polyccd.robot.load_urdf", "robot", "yourdfpy")
    if geometry not in ("collision", "visual"):
        raise InputError(f'geometry: {geometry!r} is not "collision" or "visual"')
    path = file_path(path, "path")
    _limits.config(limits)  # InputError for a limits that is not a polyccd.Limits
    if not os.path.isfile(path):
        raise InputError(f"path: URDF file {str(path)!r} not found")
    check_urdf(path)
    try:
        urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=False,
                                  load_collision_meshes=False)
        xml = ET.parse(str(path)).getroot()
    except Exception as e:
        raise InputError(f"path: {str(path)!r} is not a readable URDF ({e})") from None
    robot = urdf.robot
    joints_xml = {j.get("name"): j for j in xml.findall("joint")}
    links_xml = {link.get("name"): link for link in xml.findall("link")}
    for j in robot.joints:
        if j.type not in SUPPORTED:
            raise InputError(f"joints.{j.name}: type {j.type!r} is not supported (polyccd "
                             f"chains take {', '.join(SUPPORTED)} joints; put a floating "
                             f"base on the robot's motions with Motion.then)")
    children = {}
    for j in robot.joints:
        children.setdefault(j.parent, []).append(j)
    child_links = {j.child for j in robot.joints}
    roots = [link.name for link in robot.links if link.name not in child_links]
    if len(roots) != 1:
        raise InputError(f"path: the URDF has {len(roots)} root links ({', '.join(roots)}), "
                         f"not one")

    chain, names, joint_link, mimic, joint_limits = Chain(), [], {}, {}, {}
    mimic_joint = {}  # chain index -> the mimic joint's name
    geometry_at = []  # (URDF link, geometry index, chain index, xml element, yourdfpy geometry)

    def add(parent, joint, axis, xyz, rpy, place):
        try:
            return chain.add_link(parent, joint, axis, xyz, rpy)
        except InputError as e:
            raise InputError(f"{place}.{e}") from None

    order = [(roots[0], None, -1)]
    while order:
        link_name, j, parent = order.pop(0)
        if j is None:
            k = add(-1, "fixed", None, [0, 0, 0], [0, 0, 0], f"links.{link_name}")
        else:
            xyz, rpy = _origin(joints_xml[j.name], f"joints.{j.name}")
            axis = None
            if j.type != "fixed":
                a = joints_xml[j.name].find("axis")
                axis = _floats(a.get("xyz") if a is not None else "1 0 0", f"joints.{j.name}.axis")
            k = add(parent, j.type, axis, xyz, rpy, f"joints.{j.name}")
            if j.type != "fixed":
                if j.mimic is not None:
                    mimic_joint[k] = j.name
                    mimic[k] = (j.mimic.joint, float(j.mimic.multiplier if j.mimic.multiplier is not None else 1),
                                float(j.mimic.offset or 0))
                else:
                    joint_link[j.name] = k
                    lim = j.limit
                    joint_limits[j.name] = (None if lim is None or j.type == "continuous"
                                      else (lim.lower, lim.upper))
        names.append(link_name)
        items = links_xml[link_name].findall(geometry)
        for i, g in enumerate(items):
            geometry_at.append((link_name, i, k, g))
        for child in children.get(link_name, []):
            order.append((child.child, child, k))
    actuated = [j.name for j in robot.joints if j.name in joint_link]
    for k, (leader, _, _) in mimic.items():
        if leader not in joint_link:
            raise InputError(f"joints: a mimic joint follows {leader!r}, which is not an "
                             f"actuated joint")
    # Chain errors name a value as the user's q does: "q1[2] (elbow)", "q1[3] (finger2,
    # mimic of finger1)" for the value a mimic joint derives from q[3].
    for j, name in enumerate(actuated):
        chain.set_value_place(joint_link[name], f"[{j}] ({name})")
    for k, (leader, _, _) in mimic.items():
        chain.set_value_place(k, f"[{actuated.index(leader)}] ({mimic_joint[k]}, mimic of {leader})")

    shapes = []
    for link_name, i, k, g in geometry_at:
        place = f"links.{link_name}.{geometry}[{i}]"
        xyz, rpy = _origin(g, place)
        if any(xyz) or any(rpy):
            k = add(k, "fixed", None, xyz, rpy, place)
            names.append(f"{link_name}#{i}")
        shape = _geometry(g.find("geometry"), urdf, place, limits)
        shapes.append((link_name, i, k, shape))
    tree = {j.child: (j.parent, j.type) for j in robot.joints}
    tree[roots[0]] = None
    out = Robot(robot.name, names, actuated, chain, shapes, joint_link, mimic, joint_limits, tree)
    out.joint_types = {j.name: j.type for j in robot.joints}
    out.mimic_joints = {j.name: (j.mimic.joint, float(j.mimic.multiplier if j.mimic.multiplier is not None else 1),
                                 float(j.mimic.offset or 0)) for j in robot.joints if j.mimic is not None}
    if srdf is not None:
        out.srdf_pairs = out.allowed_from_srdf(srdf)
    return out


from ._robot_many import RobotBatch  # noqa: E402 (the answers of check_many)
