"""Robot models validated and robot checks that have nothing to check (issue 33).

- corpus/urdf-bad/: every bad URDF is refused with the exact InputError its second line
  states (the element and the file's line); the shapes that made load_urdf hang (a
  link with two parents forming a cycle, a joint whose parent is its child) are loaded
  in a subprocess with a timeout, so a regression fails instead of hanging the suite.
- load_urdf(limits=): the collision bodies are built under the limits (LimitError).
- A robot without collision geometry checked against an obstacle: no contact (it was
  "obstacles: nothing to check"), as is a lone link without obstacles.
"""
import re
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from helpers import box  # noqa: E402
from polyccd import InputError  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402

BAD = Path(__file__).resolve().parents[1] / "corpus" / "urdf-bad"
FILES = sorted(BAD.glob("*.urdf"))


def expected(path):
    """(message, hang) from the file's second and third lines."""
    lines = path.read_text().splitlines()
    m = re.fullmatch(r"<!-- expect: (.*) -->", lines[1])
    assert m, f"{path.name}: line 2 is not <!-- expect: MESSAGE -->"
    return m.group(1), "(hang)" in lines[2]


def test_the_corpus_covers_every_rule():
    assert len(FILES) >= 9
    assert sum(expected(p)[1] for p in FILES) == 2  # the two shapes that hung


@pytest.mark.parametrize("path", [p for p in FILES if not expected(p)[1]], ids=lambda p: p.name)
def test_bad_urdf_is_refused_by_name(path):
    message, _ = expected(path)
    with pytest.raises(InputError) as e:
        load_urdf(str(path))
    assert str(e.value) == message


@pytest.mark.parametrize("path", [p for p in FILES if expected(p)[1]], ids=lambda p: p.name)
def test_shapes_that_hung_end_with_an_input_error(path):
    """Before issue 33 these never returned (memory grew); in a subprocess so that a
    regression is a failure after 120 s, not a hung test run."""
    message, _ = expected(path)
    code = ("import sys, polyccd\nfrom polyccd.robot import load_urdf\n"
            "try:\n    load_urdf(sys.argv[1])\nexcept polyccd.InputError as e:\n"
            "    print(e)\n    sys.exit(0)\nsys.exit(3)\n")
    try:
        run = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True,
                             text=True, timeout=120)
    except subprocess.TimeoutExpired:
        pytest.fail(f"load_urdf({path.name}) did not return within 120 s")
    assert run.returncode == 0, run.stderr[-2000:]
    assert run.stdout.strip() == message


OBJ = "".join(f"v {x} {y} {z}\n" for x in (0, 1) for y in (0, 1) for z in (0, 1)) + """\
f 1 3 2
f 2 3 4
f 5 6 7
f 6 8 7
f 1 2 5
f 2 6 5
f 3 7 4
f 4 7 8
f 1 5 3
f 3 5 7
f 2 4 6
f 4 8 6
"""

MESHED = """<?xml version="1.0"?>
<robot name="meshed">
  <link name="base"><collision><geometry><mesh filename="cube.obj"/></geometry></collision></link>
  <link name="arm"><collision><geometry><mesh filename="cube.obj"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="3 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def test_load_urdf_builds_under_limits(tmp_path):
    pytest.importorskip("trimesh")
    (tmp_path / "cube.obj").write_text(OBJ)
    path = tmp_path / "meshed.urdf"
    path.write_text(MESHED)
    with pytest.raises(P.LimitError, match=r"^links\.base\.collision\[0\]\.geometry\.mesh: "
                                           r"config\.max_work: the limit of 1 work steps"):
        load_urdf(str(path), limits=P.Limits(max_work=1))
    robot = load_urdf(path, limits=P.Limits(max_work=10 ** 6))  # an os.PathLike too
    free = load_urdf(str(path))
    assert [s.n_triangles for *_, s in robot.shapes] == [s.n_triangles for *_, s in free.shapes] == [12, 12]
    with pytest.raises(InputError, match=r"^limits: expected a polyccd\.Limits or None, got 5"):
        load_urdf(str(path), limits=5)
    with pytest.raises(InputError, match=r"^path: expected a file path \(str or os\.PathLike\), got 5"):
        load_urdf(5)


BARE = """<?xml version="1.0"?>
<robot name="bare">
  <link name="base"/>
  <link name="arm"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def test_robot_without_geometry_has_no_contact(tmp_path):
    """Issue 33 finding 4: no collision geometry against one obstacle said "obstacles:
    nothing to check (one body, no obstacle)"; nothing can touch, so no contact."""
    path = tmp_path / "bare.urdf"
    path.write_text(BARE)
    robot = load_urdf(str(path))
    assert robot.shapes == []
    post = P.Body(box([0.2, -1, -1], [2, 1, 1]), name="post")  # where the arm is
    r = robot.check([0], [1], [post])
    assert not r.collides and r.first_contact is None and r.free_until == 1
    assert not robot.check([0], [1]).collides
    # the visual geometry is a body: it overlaps the post from t = 0
    seen = load_urdf(str(path), geometry="visual")
    assert seen.check([0], [1], [post]).first_contact.lo == 0
    # one link, nothing else: no pair, no contact
    assert not seen.check([0], [1]).collides
