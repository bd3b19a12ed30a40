"""The layers of lib/ include only the layers before them (docs/design.md, "Layout").

Order: arith -> poly -> motion -> pred -> narrow -> enclose -> boxes -> bvh -> range -> scene
-> step -> api, with
util (threads) below every layer that needs it. Only lib/api includes the public
header; inner layers keep their own copies of its constants (lib/api/constants.cpp).
Also house rules checked on every file: no file in lib/, bindings/ or tests/ is over 450
lines, and the Python core (polyccd outside polyccd/apps) imports no application.
"""
import ast
import re
from pathlib import Path

import pytest

LIB = Path(__file__).resolve().parent.parent / "lib"
ORDER = ["util", "arith", "poly", "motion", "pred", "narrow", "enclose", "boxes", "bvh", "range", "scene", "step",
         "api"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def sources():
    return sorted(p for p in LIB.rglob("*") if p.suffix in (".h", ".cpp"))


def violations(path, text):
    """The includes of one file that break the layer order, as readable strings."""
    layer = path.relative_to(LIB).parts[0]
    rank = ORDER.index(layer)
    bad = []
    for inc in INCLUDE.findall(text):
        if inc == "polyccd.h":
            if layer != "api":
                bad.append(f"{path.relative_to(LIB)} includes the public header")
            continue
        target = inc.split("/")[0]
        if target not in ORDER:
            bad.append(f"{path.relative_to(LIB)} includes {inc}, not in a layer")
        elif ORDER.index(target) > rank:
            bad.append(f"{path.relative_to(LIB)} ({layer}) includes {inc} ({target}, a later layer)")
    return bad


def test_every_folder_is_a_layer_with_a_readme():
    folders = sorted(p.name for p in LIB.iterdir() if p.is_dir())
    assert folders == sorted(ORDER)
    for name in ORDER:
        assert (LIB / name / "README.md").is_file(), f"lib/{name} has no README.md"


def test_design_layout_names_every_folder_in_layer_order():
    """docs/design.md's layout table has one row per lib/ folder, in the layer order."""
    design = (LIB.parent / "docs" / "design.md").read_text(encoding="utf-8")
    layout = design.split("\n## Layout\n", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `lib/(\w+)` \|", layout, re.M)
    assert rows == ORDER, rows


def test_layers_include_only_earlier_layers():
    bad = [v for p in sources() for v in violations(p, p.read_text())]
    assert bad == []


@pytest.mark.parametrize("text,layer_file", [
    ('#include "scene/scene.h"\n', "narrow/pair_ctx.h"),
    ('#include "polyccd.h"\n', "motion/body.h"),
    ('#include "broad/narrow.h"\n', "range/range_index.cpp"),
])
def test_the_check_catches_a_violation(text, layer_file):
    assert violations(LIB / layer_file, text)


# ------------------------------------------------------------ every file, every folder

ROOT = LIB.parent
CAPPED = ("lib", "bindings", "tests")  # every text file there (house style: under 450 lines)
TEXT = {".py", ".c", ".h", ".cpp", ".md", ".sh", ".mk", ".txt", ".toml", ".json", ".map", ".in"}
SKIP = {"__pycache__", "build", "dist", ".venv", ".pytest_cache"}


def capped_files():
    for top in CAPPED:
        for p in sorted((ROOT / top).rglob("*")):
            parts = p.relative_to(ROOT).parts
            # A symlink (bindings/python/README.md: the checkout's README for the wheel)
            # is the file it points to, outside these folders.
            if (p.is_file() and not p.is_symlink() and p.suffix in TEXT
                    and not SKIP & set(parts) and not any(x.endswith(".egg-info") for x in parts)
                    and not p.name.startswith("_pccd")):  # the generated cffi extension
                yield p


def test_no_file_is_over_450_lines():
    long = [f"{p.relative_to(ROOT)}: {n}" for p in capped_files()
            if (n := len(p.read_text(errors="replace").splitlines())) > 450]
    assert long == []


# ------------------------------------------------ the Python core imports no application

PACKAGE = ROOT / "bindings" / "python" / "polyccd"
# python -m polyccd: the command line's entry point, run, never imported by the core.
ENTRY_POINTS = {"__main__.py"}


def imported_modules(path, text):
    """Every module name an import statement of path (a file of the polyccd package)
    names, absolute: "from .apps import x" in polyccd/_scene.py gives polyccd.apps and
    polyccd.apps.x; imports inside functions count as well."""
    package = ["polyccd", *path.relative_to(PACKAGE).parts[:-1]]
    out = []
    for node in ast.walk(ast.parse(text, str(path))):
        if isinstance(node, ast.Import):
            out += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package[:len(package) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            out.append(module)
            out += [f"{module}.{alias.name}" for alias in node.names]
    return out


def apps_imports(path, text):
    return [m for m in imported_modules(path, text)
            if m == "polyccd.apps" or m.startswith("polyccd.apps.")]


def core_files():
    return [p for p in sorted(PACKAGE.rglob("*.py"))
            if "apps" not in p.relative_to(PACKAGE).parts[:-1] and p.name not in ENTRY_POINTS]


def test_the_python_core_imports_no_application():
    assert len(core_files()) > 10
    bad = [f"{p.relative_to(PACKAGE)} imports {m}" for p in core_files()
           for m in apps_imports(p, p.read_text())]
    assert bad == []


@pytest.mark.parametrize("text", [
    "from .apps._render import render_scene\n",
    "def f():\n    from .apps import load_scene\n",
    "from . import apps\n",
    "import polyccd.apps.cli\n",
    "from polyccd.apps import to_png\n",
])
def test_the_import_check_catches_an_application_import(text):
    assert apps_imports(PACKAGE / "_scene.py", text)
    assert not apps_imports(PACKAGE / "_scene.py", "from ._body import Mesh\nimport numpy\n")


# ------------------------------------------------ the applications use the public API only

def private_imports(path, text):
    """Modules of the core's private side an application file imports: any polyccd.X
    (outside polyccd.apps) whose name starts with "_" ("from .. import _numbers" and
    "from .._numbers import show" both count)."""
    out = []
    for m in imported_modules(path, text):
        parts = m.split(".")
        if parts[0] == "polyccd" and len(parts) > 1 and parts[1] != "apps" \
                and any(q.startswith("_") and q != "__version__" for q in parts[1:]):
            out.append(m)
    return out


def app_files():
    return [p for p in sorted((PACKAGE / "apps").rglob("*.py"))]


def test_the_applications_use_only_the_public_api():
    assert len(app_files()) > 10
    bad = [f"{p.relative_to(PACKAGE)} imports {m}" for p in app_files()
           for m in private_imports(p, p.read_text())]
    assert bad == []


@pytest.mark.parametrize("text", [
    "from .._numbers import show\n",
    "from .. import _solve\n",
    "def f():\n    import polyccd._pccd\n",
    "from polyccd._limits import Limits\n",
])
def test_the_private_import_check_catches_one(text):
    app = PACKAGE / "apps" / "_csv.py"
    assert private_imports(app, text)
    assert not private_imports(app, "from .. import Limits, __version__\nfrom ..texts import show\n"
                                    "from ._json import load\nimport numpy\n")
