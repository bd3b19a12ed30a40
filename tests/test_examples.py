"""Every example of examples/ runs as written and prints what it says it prints.

A Python example ends with a "# Prints:" comment block (each line "#   text"); the C
example prints the answer its comment names; the command-line example is a scene file
whose `expect` block the corpus runner checks, and `polyccd check` on it prints the
documented first contact. The README's quick starts are these same files
(tests/test_readme.py checks that they are verbatim copies)."""
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
PYTHON = sorted((EXAMPLES / "python").glob("*.py"))


def promised_output(path):
    """The lines of the "# Prints:" block at the end of an example."""
    text = path.read_text(encoding="utf-8")
    block = text.split("\n# Prints:\n", 1)
    assert len(block) == 2, f"{path.name}: no '# Prints:' block"
    return [re.sub(r"^#   ", "", line) for line in block[1].splitlines()]


@pytest.mark.parametrize("path", PYTHON, ids=[p.name for p in PYTHON])
def test_python_example_prints_what_it_says(path, tmp_path):
    # Run from an empty directory, as a user would run a downloaded example.
    out = subprocess.run([sys.executable, str(path)], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == promised_output(path)


def test_c_example_runs(tmp_path):
    exe = tmp_path / "first_contact"
    build = ROOT / "build"   # where `make` puts libpolyccd.so
    subprocess.run(["cc", "-std=c99", "-Wall", "-Werror", "-I" + str(ROOT / "include"),
                    str(EXAMPLES / "c" / "first_contact.c"), "-L" + str(build), "-lpolyccd",
                    "-Wl,-rpath," + str(build), "-o", str(exe)], check=True)
    out = subprocess.run([str(exe)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "first contact at t = 1/2\n"


def _polyccd(*args):
    return subprocess.run([sys.executable, "-m", "polyccd", *args], capture_output=True,
                          text=True, cwd=ROOT)


def test_cli_example():
    scene = EXAMPLES / "cli" / "box_meets_wall.json"
    out = _polyccd("check", str(scene.relative_to(ROOT)))
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert got["collides"] is True and got["first_contact"]["exact"] == "2/5"
    assert {tuple(f["bodies"]) for f in got["features"]} == {("box", "wall")}
    corpus = _polyccd("corpus", "examples/cli")
    assert corpus.returncode == 0 and corpus.stdout.strip().endswith("1 passed, 0 failed"), corpus.stdout
