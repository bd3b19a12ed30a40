"""The robot cases of corpus/robots/ (README there): each case's expected answer from the
filtered check, the unfiltered exact check (filter=False) and decide mode."""
import json
import os
from fractions import Fraction as F

import pytest

pytest.importorskip("yourdfpy")
import polyccd as P  # noqa: E402
from polyccd.robot import load_urdf  # noqa: E402

HERE = os.path.join(os.path.dirname(__file__), "..", "corpus", "robots")
CASES = sorted(f for f in os.listdir(HERE) if f.endswith(".robot"))


@pytest.mark.parametrize("name", CASES)
def test_robot_corpus_case(tmp_path, name):
    with open(os.path.join(HERE, name)) as f:
        case = json.load(f)
    assert case["format"] == "polyccd-robot/1" and case["name"] + ".robot" == name
    path = tmp_path / "robot.urdf"
    path.write_text(case["urdf"])
    robot = load_urdf(str(path))
    obstacles = [P.Body(P.Mesh([[F(x) for x in v] for v in o["mesh"]["vertices"]], o["mesh"]["triangles"]),
                        name=o["name"]) for o in case["obstacles"]]
    want = case["expect"]
    for kw in (dict(), dict(filter=False), dict(first_contact=False)):
        r = robot.check(case["q0"], case["q1"], obstacles, **case["options"], **kw)
        assert r.collides == want["collides"], (name, kw)
        if "first_contact" in want and kw.get("first_contact", True):
            assert r.first_contact.exact == F(want["first_contact"]), (name, kw, r.first_contact)
