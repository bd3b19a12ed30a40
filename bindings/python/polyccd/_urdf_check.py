"""The structure of a URDF checked as urdfdom checks it (issue 33), before anything is
built from it: unique link and joint names, each joint with a parent and a child that
are links of the file and differ, at most one parent joint per link, no kinematic
cycle, exactly one root link. Each rule is an InputError naming the element and its
line in the file ("joints.elbow (line 12): ..."); a file breaking none of them is a
tree, so walking it from its root ends.

The file is read with expat (the standard library's XML parser), which gives each
element's line; only the robot's direct <link> and <joint> children and a joint's
<parent> and <child> are looked at (the rest is left to the reader, polyccd.robot).
"""
import xml.parsers.expat
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

from ._errors import InputError


@dataclass
class Element:
    tag: str
    name: Optional[str]
    line: int
    links: Dict[str, Tuple[Optional[str], int]] = field(default_factory=dict)  # joint: parent/child


def _elements(path):
    """(links, joints): the robot's <link> and <joint> elements in file order."""
    links: List[Element] = []
    joints: List[Element] = []
    stack: List[str] = []  # the open elements' tags, the robot's first
    parser = xml.parsers.expat.ParserCreate()

    def start(tag, attrs):
        line = parser.CurrentLineNumber
        if len(stack) == 1 and tag in ("link", "joint"):
            (links if tag == "link" else joints).append(Element(tag, attrs.get("name"), line))
        elif len(stack) == 2 and stack[1] == "joint" and tag in ("parent", "child"):
            joints[-1].links.setdefault(tag, (attrs.get("link"), line))
        stack.append(tag)

    def end(tag):
        stack.pop()

    parser.StartElementHandler, parser.EndElementHandler = start, end
    try:
        with open(path, "rb") as f:
            parser.ParseFile(f)
    except (xml.parsers.expat.ExpatError, OSError) as e:
        raise InputError(f"path: {str(path)!r} is not a readable URDF ({e})") from None
    return links, joints


def _place(kind, e, k):
    return f"{kind}.{e.name}" if e.name else f"{kind}[{k}]"


def check_urdf(path) -> None:
    """InputError for the first rule the URDF at path breaks (see the module comment)."""
    links, joints = _elements(path)
    first: Dict[str, Element] = {}
    for kind, elements in (("links", links), ("joints", joints)):
        first.clear()
        for k, e in enumerate(elements):
            if not e.name:
                raise InputError(f"{kind}[{k}] (line {e.line}): <{e.tag}> has no name")
            if e.name in first:
                raise InputError(f"{kind}.{e.name} (line {e.line}): a second <{e.tag}> named "
                                 f"{e.name!r} (the first is at line {first[e.name].line})")
            first[e.name] = e
    names = {e.name for e in links}
    parent_joint: Dict[str, Element] = {}  # link -> the joint whose child it is
    for k, j in enumerate(joints):
        place = f"joints.{j.name} (line {j.line})"
        for role in ("parent", "child"):
            link, line = j.links.get(role, (None, j.line))
            if link is None:
                raise InputError(f"{place}: no <{role} link=...>")
            if link not in names:
                raise InputError(f"joints.{j.name}.{role} (line {line}): {link!r} is not a "
                                 f"<link> of the URDF")
        parent, child = j.links["parent"][0], j.links["child"][0]
        if parent == child:
            raise InputError(f"{place}: parent and child are the same link {parent!r}")
        if child in parent_joint:
            other = parent_joint[child]
            raise InputError(f"links.{child}: has two parent joints, {other.name!r} (line "
                             f"{other.line}) and {j.name!r} (line {j.line}); a URDF is a tree")
        parent_joint[child] = j
    _check_tree(links, parent_joint)


def _check_tree(links, parent_joint):
    """No cycle (each link's chain of parents ends at a root) and exactly one root."""
    done = set()
    for e in links:
        seen: List[str] = []
        link = e.name
        while link not in done and link in parent_joint:
            if link in seen:
                cycle = seen[seen.index(link):] + [link]
                raise InputError(f"joints.{parent_joint[link].name} (line "
                                 f"{parent_joint[link].line}): closes a kinematic cycle "
                                 f"(links {' -> '.join(reversed(cycle))}); a URDF is a tree")
            seen.append(link)
            link = parent_joint[link].links["parent"][0]
        done.update(seen)
    roots = [e.name for e in links if e.name not in parent_joint]
    if len(roots) != 1:
        raise InputError(f"path: the URDF has {len(roots)} root links ({', '.join(roots)}), "
                         f"not one")
