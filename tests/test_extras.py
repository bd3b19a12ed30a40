"""A feature whose optional package is missing says which package and which extra of
pyproject.toml brings it (issue 24: to_trimesh ended in "ModuleNotFoundError: scipy"
under the documented extras), and each extra lists what its features import."""
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXTRAS = tomllib.loads((ROOT / "bindings" / "python" / "pyproject.toml").read_text())["project"][
    "optional-dependencies"]

SCENE = """
import polyccd, polyccd.apps as apps
box = polyccd.Mesh.box((1, 1, 1))
r = polyccd.check([polyccd.Body(box, polyccd.Motion.linear((-3, 0, 0), (3, 0, 0))), polyccd.Body(box)])
"""


def _without(module, code):
    """Runs code with `module` made unimportable (as if not installed)."""
    prelude = f"import sys\nsys.modules[{module!r}] = None\n"
    return subprocess.run([sys.executable, "-c", prelude + SCENE + code], capture_output=True, text=True)


@pytest.mark.parametrize("module, call, extra", [
    ("scipy", "apps.to_trimesh(r)", "interop"),
    ("trimesh", "apps.to_trimesh(r)", "interop"),
    ("matplotlib", "apps.to_png(r, '/dev/null')", "interop"),
    ("yourdfpy", "polyccd.robot.load_urdf('x.urdf')", "robot"),
])
def test_missing_package_names_the_extra(module, call, extra):
    out = _without(module, "import polyccd.robot\n" + call)
    assert out.returncode != 0
    last = out.stderr.strip().splitlines()[-1]
    assert last.startswith("ModuleNotFoundError: ") and f"'{module}'" in last, last
    assert f'pip install "polyccd[{extra}]"' in last, last


def test_to_trimesh_works_with_the_interop_extra_installed():
    """The dev venv has what `interop` lists (tests/requirements.txt): the scene builds."""
    out = subprocess.run([sys.executable, "-c", SCENE + "s = apps.to_trimesh(r)\nprint(len(s.geometry))"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert int(out.stdout) >= 2


def test_extras_list_what_their_features_import():
    names = {e: {d.split(">")[0].split("<")[0].split("=")[0].split("[")[0].strip() for d in deps}
             for e, deps in EXTRAS.items()}
    assert {"trimesh", "scipy", "matplotlib", "gemmi"} <= names["interop"]
    assert {"trimesh", "scipy", "matplotlib", "gemmi", "yourdfpy", "example-robot-data"} <= names["demo"]
    assert {"yourdfpy", "trimesh", "scipy"} <= names["robot"]


def test_demo_without_the_demo_extra_runs_what_it_can(tmp_path):
    """polyccd demo with trimesh, gemmi and matplotlib missing: no traceback, a message
    naming the demo extra, and the parts that need none of them still run and pass."""
    code = ("import sys\nfor m in ('trimesh', 'gemmi', 'matplotlib'):\n    sys.modules[m] = None\n"
            "from polyccd.apps.cli import main\n"
            f"sys.exit(main(['demo', '--out', {str(tmp_path)!r}]))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    assert "Traceback" not in out.stderr
    assert 'real scenes and robot skipped' in out.stdout and 'pip install "polyccd[demo]"' in out.stdout
    assert "simulator step" in out.stdout and "first contact at" in out.stdout
    assert "(no picture:" in out.stdout           # the cloth's picture needs matplotlib
