#!/usr/bin/env python3
"""The robot, obstacles and queries of an OMPL problem as a plain text file for the C++
side (bindings/ompl/polyccd_ompl.hpp's test and benchmark: tests/ompl/scene_file.hpp
reads it back through the C API). polyccd's URDF reader is Python (polyccd.robot.load_urdf:
yourdfpy, trimesh); this writes what it built, so that the C++ robot is the same robot:
the chain's links as given to pccd_chain_add_link, every body's exact inputs (doubles as
repr, which reads back to the same double, or the exact texts the Mesh was made of), the
groups and the allowed pairs, the actuated joints (chain column, limits, mimic) and
the fixed values. Tokens are separated by white space, one record a line:

    polyccd-ompl-scene 1
    links N            then N lines: parent joint ax ay az x y z roll pitch yaw  (axis "- - -" when none)
    joints M           then M lines: name column lo hi                 (lo, hi: "-inf" / "inf")
    mimic K            then K lines: column leader_joint_index multiplier offset
    bodies B           then per body: "mesh link group solid nv nt d|s", nv lines x y z, nt lines a b c
    allowed P          then P lines: group group
    obstacles O        then as bodies, link and group 0 (stationary meshes only)
    planned D          the state's dimensions: D joint indices, then "fixed" and the
                       value of every actuated joint (the planned ones' values unused)
    queries Q          then Q lines: D start values, D goal values
Run alone: .venv/bin/python tests/ompl/scene_file.py OUT (the Panda of example-robot-data,
the wall and shelf of examples/ompl_panda.py, its query); exits 3 when the robot packages
are missing (the caller skips)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def _mesh_lines(shape, link, group):
    import numpy as np
    nv, doubles, texts, tris, solid = shape._inputs
    tris = np.asarray(tris).reshape(-1)
    doubles = None if doubles is None else np.asarray(doubles, dtype=np.float64).reshape(-1)
    texts = None if texts is None else list(np.asarray(texts, dtype=object).reshape(-1))
    kind = "d" if doubles is not None else "s"
    out = [f"mesh {link} {group} {int(solid)} {nv} {len(tris) // 3} {kind}"]
    if doubles is not None:
        out += [" ".join(repr(float(x)) for x in doubles[3 * i:3 * i + 3]) for i in range(nv)]
    else:
        out += [" ".join(texts[3 * i:3 * i + 3]) for i in range(nv)]
    out += [" ".join(str(int(x)) for x in tris[3 * i:3 * i + 3]) for i in range(len(tris) // 3)]
    return out


def _num(x):
    return repr(float(x))


def write(path, robot, obstacles, planned, fixed, queries, allowed=None):
    """Writes the file. planned: joint names (the state's dimensions, in order); fixed:
    {joint: value} of the other actuated joints; queries: [(start, goal)] as planned-joint
    vectors; allowed: link-name pairs (default: the robot's adjacent pairs and SRDF's)."""
    from polyccd import Mesh
    lines = ["polyccd-ompl-scene 1", f"links {len(robot.chain._links)}"]
    for parent, joint, axis, xyz, rpy, *_ in robot.chain._links:
        ax = "- - -" if axis is None else " ".join(map(_num, axis))
        lines.append(f"{parent} {joint} {ax} {' '.join(map(_num, xyz))} {' '.join(map(_num, rpy))}")
    lines.append(f"joints {len(robot.joints)}")
    for name in robot.joints:
        lo, hi = robot.limits.get(name) or (float("-inf"), float("inf"))
        lines.append(f"{name} {robot._joint_link[name]} {_num(lo)} {_num(hi)}")
    lines.append(f"mimic {len(robot._mimic)}")
    for k, (leader, mult, off) in robot._mimic.items():
        lines.append(f"{k} {robot.joints.index(leader)} {_num(mult)} {_num(off)}")
    groups = {name: g for g, name in enumerate(robot.tree)}
    lines.append(f"bodies {len(robot.shapes)}")
    for link, _, k, shape in robot.shapes:
        if not isinstance(shape, Mesh):
            raise SystemExit(f"scene_file: {link}: only meshes are written")
        lines += _mesh_lines(shape, k, groups[link])
    pairs = sorted(tuple(sorted(p)) for p in (robot.adjacent_pairs() | robot.__dict__.get("srdf_pairs", set())
                                               if allowed is None else allowed))
    lines.append(f"allowed {len(pairs)}")
    lines += [f"{groups[a]} {groups[b]}" for a, b in pairs]
    lines.append(f"obstacles {len(obstacles)}")
    for o in obstacles:
        if o.motion is not None or not isinstance(o.shape, Mesh):
            raise SystemExit("scene_file: obstacles must be stationary meshes")
        lines += _mesh_lines(o.shape, 0, 0)
    values = [fixed.get(n, 0.0) for n in robot.joints]
    lines.append(f"planned {len(planned)} {' '.join(str(robot.joints.index(n)) for n in planned)} "
                 f"fixed {' '.join(map(_num, values))}")
    lines.append(f"queries {len(queries)}")
    lines += [" ".join(map(_num, list(a) + list(b))) for a, b in queries]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) != 1:
        raise SystemExit("usage: scene_file.py OUT")
    sys.path.insert(0, os.path.join(HERE, "..", "..", "examples"))
    try:
        import yourdfpy  # noqa: F401
        from polyccd.apps._demo_robot import PANDA_URDF, example_robot_file
        if example_robot_file(PANDA_URDF) is None:
            raise ImportError("example-robot-data")
    except ImportError as e:
        print(f"scene_file: skipped ({e} is not installed)")
        return 3
    import ompl_panda as ex
    robot, plates = ex.scene()
    planned = [n for n in robot.joints if n != "panda_finger_joint1"]
    write(argv[0], robot, plates, planned, {"panda_finger_joint1": ex.FINGER},
          [(ex.START, ex.GOAL)])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
