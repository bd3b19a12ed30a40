"""examples/ompl_panda.py runs: RRTConnect plans the Panda over a 2 mm wall and below a
2 mm shelf with polyccd.ompl's exact validators (a small time budget), and the returned
path is free by polyccd's check of every segment and by exact static checks of poses
every 0.05 rad along the same joint path (the example exits 1 otherwise). The straight
joint path from start to goal hits the wall (so the planner had to go around it)."""
import importlib.util
import os

import pytest

pytest.importorskip("ompl")
pytest.importorskip("yourdfpy")
from test_robot_fk import needs_robots  # noqa: E402

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "examples", "ompl_panda.py")


@needs_robots
def test_ompl_panda_example(capsys):
    spec = importlib.util.spec_from_file_location("ompl_panda", EXAMPLE)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    assert example.main(["--time", "60", "--step", "0.05", "--seed", "3"]) == 0
    out = capsys.readouterr().out
    print(out)
    assert "the straight joint path hits wall" in out
    assert "RRTConnect (seed 3): solved" in out
    assert "polyccd check of every segment" in out and "): FREE (" in out
    assert "each checked exactly: FREE (" in out
