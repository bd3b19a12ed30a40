"""The reference documentation builds without a warning, and the repository cites nothing
outside itself.

`make docs` runs the same sphinx-build (warnings are errors): the Markdown pages of docs/,
the Python API from the docstrings (autodoc imports the package of this venv) and the C
API from include/polyccd.h (docs/_ext/c_header.py, which raises on a declaration it
cannot read, so a new kind of declaration cannot silently drop out of the reference).
"""
import importlib
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


# The modules of the Python reference (docs/python-api.rst): each public name (its
# __all__) has an entry in the API page and in the general index.
MODULES = ["polyccd", "polyccd.robot", "polyccd.ompl", "polyccd.apps", "polyccd.apps.distributed",
           "polyccd.texts", "polyccd.extras"]


@pytest.fixture(scope="module")
def html(tmp_path_factory):
    """The reference, built once as `make docs` builds it (warnings are errors)."""
    out_dir = tmp_path_factory.mktemp("docs") / "html"
    out = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                          str(ROOT / "docs"), str(out_dir)], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    return out_dir


def public_names(module):
    """module.__all__ without dunders (__version__ is an attribute, not an API entry)."""
    mod = importlib.import_module(module)
    return [n for n in mod.__all__ if not n.startswith("__")]


def test_every_public_python_name_is_in_the_reference_and_index(html):
    page = (html / "python-api.html").read_text(encoding="utf-8")
    index = (html / "genindex.html").read_text(encoding="utf-8")
    names = [f"{m}.{n}" for m in MODULES for n in public_names(m)]
    assert {"polyccd.robot.Robot", "polyccd.robot.load_urdf", "polyccd.ompl.MotionValidator",
            "polyccd.ompl.StateValidityChecker", "polyccd.apps.distributed.check_map"} <= set(names)
    assert not [n for n in names if f'id="{n}"' not in page], "not in python-api.html"
    assert not [n for n in names if f'python-api.html#{n}"' not in index], "not in genindex.html"


def test_c_reference_is_prose_with_short_section_titles(html):
    """Header comments are paragraphs and lists, not code blocks (whose highlighter
    coloured C comments as Python); section titles are a few words each."""
    page = (html / "c-api.html").read_text(encoding="utf-8")
    body = page.split('<div class="body"', 1)[1]
    assert '<div class="highlight' not in body and "<pre>" not in body
    titles = re.findall(r"<h2>(.*?)<a class=\"headerlink\"", body)
    assert len(titles) >= 8 and all(len(t) <= 40 for t in titles), titles
    assert "Scenes" in titles and "Robots" in titles, titles


def test_sphinx_builds_without_warnings(html):
    page = (html / "c-api.html").read_text(encoding="utf-8")
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
