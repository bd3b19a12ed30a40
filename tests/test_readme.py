"""The README's quick starts are the examples of examples/, verbatim, and run as written
(tests/test_examples.py runs every example; here: the copies match, the command-line
quick start prints what the README shows, and install, Python and C come first)."""
import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _blocks(lang):
    return re.findall(r"```" + lang + r"\n(.*?)```", README, re.S)


def test_python_quick_start_is_the_example():
    (block,) = _blocks("python")
    assert block == (ROOT / "examples" / "python" / "meshes_between_poses.py").read_text(encoding="utf-8")


def test_c_quick_start_is_the_example():
    (block,) = _blocks("c")
    assert block == (ROOT / "examples" / "c" / "first_contact.c").read_text(encoding="utf-8")


def test_cli_quick_start_prints_what_it_shows():
    block = next(b for b in _blocks("sh") if "polyccd check" in b)
    command, shown = block.splitlines()[:2]
    args = command.split()[1:]
    out = subprocess.run([sys.executable, "-m", "polyccd", *args], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert shown.startswith("# ") and shown.endswith("...")
    assert out.stdout.startswith(shown[2:-3]), (out.stdout, shown)
    assert json.loads(out.stdout)["first_contact"]["exact"] == "2/5"


def test_a_new_user_finds_install_and_quick_starts_first():
    """Install, the Python and the C quick starts begin within the first 100 lines, and
    the README stays a door (about 200 lines), the details living in docs/."""
    lines = README.splitlines()
    heads = {line: i + 1 for i, line in enumerate(lines) if line.startswith("## ")}
    for title in ("## Install", "## Quick start: Python", "## Quick start: C"):
        assert heads[title] <= 100, (title, heads)
    assert len(lines) <= 200, len(lines)
    for page in re.findall(r"`(docs/[\w.]+\.md)`", README):
        assert (ROOT / page).is_file(), page
