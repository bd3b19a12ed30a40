"""Scene files (formats.md, polyccd/1) through `polyccd check`: answers and clear input
errors that name the JSON path of the bad value (exit 2)."""
import copy
import json
import subprocess
import sys

import pytest

TET = {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
       "triangles": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]}
# B slides from x = 3 to x = -1. B lies in x >= 3 - 4t and A in x + y + z <= 1 with
# y, z >= 0, so they first meet when B's vertex 0, at (3 - 4t, 0, 0), reaches A's vertex
# 1 = (1, 0, 0): t = 1/2, where the two tetrahedra touch at that single point.
SCENE = {"format": "polyccd/1",
         "bodies": [{"name": "A", "mesh": TET},
                    {"name": "B", "mesh": TET, "motion": {"translation": [[3, -4], [0], [0]]}}],
         "expect": {"collides": True, "first_contact": "1/2"}}


def run(tmp_path, doc):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(doc) if not isinstance(doc, str) else doc)
    return subprocess.run([sys.executable, "-m", "polyccd", "check", str(path)],
                          capture_output=True, text=True)


def test_answer(tmp_path):
    p = run(tmp_path, SCENE)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["collides"] and out["first_contact"]["exact"] == "1/2"
    assert out["bodies"] == ["A", "B"] and out["pairs"][0]["bodies"] == ["A", "B"]
    # Every feature pair through the common point: A's vertex 1 with B's triangles at
    # vertex 0 (0, 1, 2), B's vertex 0 with A's triangles at vertex 1 (0, 1, 3), and
    # A's edges at vertex 1 (0 = 01, 3 = 12, 4 = 13) with B's at vertex 0 (0, 1, 2).
    got = {(tuple(f["a"]), tuple(f["b"])) for f in out["features"]}
    want = ({(("vertex", 1), ("triangle", k)) for k in (0, 1, 2)} |
            {(("triangle", k), ("vertex", 0)) for k in (0, 1, 3)} |
            {(("edge", i), ("edge", j)) for i in (0, 3, 4) for j in (0, 1, 2)})
    assert got == want
    assert all(f["bodies"] == ["A", "B"] and f["first_contact"]["exact"] == "1/2"
               for f in out["features"])


def edited(path, value):
    doc = copy.deepcopy(SCENE)
    node = doc
    for key in path[:-1]:
        node = node[key]
    if value is KeyError:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return doc


@pytest.mark.parametrize("path, value, message", [
    (["bodies", 1, "motion", "rotation"], [[1, -2], [0], [0], [0]], "bodies[1].motion: "),
    (["bodies", 1, "motion", "rotation"], [[1], [0], ["abc"], [0]], "bodies[1].motion.rotation[2][0]"),
    (["bodies", 0, "mesh", "triangles"], [[0, 1, 7]], "bodies[0].mesh.triangles[0][2]"),
    (["bodies", 0, "mesh", "triangles"], [[0, 1, -1]], "bodies[0].mesh.triangles[0][2]"),
    (["bodies", 0, "mesh", "vertices"], [[0, 0]], "bodies[0].mesh.vertices[0]"),
    (["bodies", 0, "mesh"], KeyError, "bodies[0]: expected exactly one of"),
    (["bodies", 1, "name"], "A", "bodies[1].name: \"A\" is used"),
    (["bodies"], [], "bodies: a scene needs at least 2 bodies"),
    (["expect", "pairs"], [["A", "C"]], "expect.pairs[0][1]: no body is named"),
    (["options"], {"time_tolerance": "-1"}, "time_tolerance"),
])
def test_input_errors(tmp_path, path, value, message):
    p = run(tmp_path, edited(path, value))
    assert p.returncode == 2, (p.stdout, p.stderr)
    assert message in p.stderr, p.stderr


def test_vanishing_rotation_gives_the_time(tmp_path):
    p = run(tmp_path, edited(["bodies", 1, "motion", "rotation"], [[1, -2], [0], [0], [0]]))
    assert "1/2" in p.stderr, p.stderr
