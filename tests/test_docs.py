"""The reference documentation builds without a warning, and the repository cites nothing
outside itself.

`make docs` runs the same sphinx-build (warnings are errors): the Markdown pages of docs/,
the Python API from the docstrings (autodoc imports the package of this venv) and the C
API from include/polyccd.h (docs/_ext/c_header.py, which raises on a declaration it
cannot read, so a new kind of declaration cannot silently drop out of the reference).
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_sphinx_builds_without_warnings(tmp_path):
    out = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                          str(ROOT / "docs"), str(tmp_path / "html")], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    page = (tmp_path / "html" / "c-api.html").read_text(encoding="utf-8")
    header = (ROOT / "include" / "polyccd.h").read_text(encoding="utf-8")
    # Every exported function of the header has its entry in the C reference.
    names = re.findall(r"PCCD_API\s+[^;]*?\b(pccd_\w+)\s*\(", header)
    assert len(names) > 50
    missing = [n for n in names if f'id="c.{n}"' not in page]
    assert not missing, missing


def test_no_file_points_outside_the_repository():
    """Formats, the paper and the design notes are described in the repository's own
    words (docs/formats.md, docs/design.md); no file sends a reader to ../shared. The
    shared query set is data found through $POLYCCD_QUERY_DIR, not a citation."""
    tracked = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    bad = []
    for name in tracked:
        path = ROOT / name
        if path.is_symlink() or not path.is_file() or path.suffix in (".png", ".off", ".pdb"):
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for m in re.finditer(r"shared/(design|paper|peers/(?!tight-inclusion))\S*", text):
            bad.append(f"{name}: {m.group(0)}")
    assert not bad, "\n".join(bad)


# Absolute paths that belong to one machine: home and work folders, mounts, network
# file systems (a path such as /usr/local or /tmp/x in an example is not one).
MACHINE_PATH = re.compile(r"(?<![\w.$}~/-])/(work|home|root|Users|mnt|srv|scratch|data|opt|media"
                          r"|nfs|gpfs|lustre)/|\b[A-Za-z]:\\(Users|Documents)\b")


def test_no_tracked_file_names_a_machine_path():
    """Nothing tracked depends on where one machine keeps its files: data is found through
    $POLYCCD_QUERY_DIR or beside the checkout, never at a path of the machine it was
    written on."""
    tracked = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    assert len(tracked) > 100
    bad = []
    for name in tracked:
        path = ROOT / name
        if path.is_symlink() or not path.is_file():
            continue
        text = path.read_bytes().decode("utf-8", errors="replace")
        bad += [f"{name}: {m.group(0)}" for m in MACHINE_PATH.finditer(text)]
    assert not bad, "\n".join(bad)
