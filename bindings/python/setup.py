"""The pip build of polyccd: `pip install ./bindings/python`, `pip wheel`, the sdist.

Backend: setuptools (pyproject.toml holds the metadata), with two commands of its own:

- build_ext compiles libpolyccd from the C++ sources (lib/*/*.cpp, the flags of
  lib/flags.mk, the Makefile's own list, linked with the version script lib/exports.map
  and the soname libpolyccd.so.N), then the cffi extension polyccd._pccd against it
  (build_ffi.py, declarations generated from include/polyccd.h by gen_cdef.py). Both go
  into the package directory; the extension finds the library beside itself (rpath
  $ORIGIN), so an installed polyccd needs nothing from the checkout.
- sdist copies those sources (sources() below) into csrc/ of the source distribution, so
  an sdist builds alone; a checkout build reads them from ../../ instead.

GMP and CGAL come from the system (Debian: libgmp-dev, libcgal-dev; CGAL is header-only),
through pkg-config when it knows gmpxx, and Eigen's include directory is added when
pkg-config knows eigen3 (no source includes Eigen today). A compile probe checks them
first and says what is missing. CXX (default c++), CXXFLAGS (default -O2: no -g, the
wheel stays small), CPPFLAGS and LDFLAGS are honoured; POLYCCD_BUILD_JOBS sets the
number of parallel compiles (default: the CPU count). An in-tree build keeps the
library's objects in bindings/python/build/ and reuses one when the compile command and
the compiler's version are unchanged and it is newer than its source and every header of
lib/ and include/ (system headers are not tracked: delete that folder, or `make clean`,
after upgrading GMP or CGAL).

Editable installs are the checkout's dev venv (`make venv`): the Makefile builds the
library into build/ and build_ffi.py the extension in place, so build_ext builds nothing
in editable mode.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py
from setuptools.command.sdist import sdist

HERE = Path(__file__).absolute().parent
sys.path.insert(0, str(HERE))          # build_ffi, gen_cdef (build-time modules)

# The sources an sdist carries in csrc/, relative to the checkout's root.
SDIST_SOURCES = "csrc"
LEGAL = ("LICENSE", "COPYING")


def source_root():
    """Where lib/ and include/ are: csrc/ in an unpacked sdist, else the checkout."""
    for root in (HERE / SDIST_SOURCES, HERE.parent.parent):
        if (root / "include" / "polyccd.h").is_file() and (root / "lib" / "flags.mk").is_file():
            return root
    raise RuntimeError("polyccd build: no C sources: neither %s nor the checkout at %s "
                       "has include/polyccd.h and lib/flags.mk"
                       % (HERE / SDIST_SOURCES, HERE.parent.parent))


def sources(root):
    """Every file the library's build reads, relative to root (sorted): the header, the
    flags, the version script and lib/<layer>/*.cpp, *.h."""
    root = Path(root)
    files = ["include/polyccd.h", "lib/flags.mk", "lib/exports.map"]
    files += [p.relative_to(root).as_posix() for p in root.glob("lib/*/*")
              if p.suffix in (".cpp", ".h")]
    return sorted(files)


def make_variables(path):
    """The `NAME := words` assignments of a makefile such as lib/flags.mk, as lists."""
    text = Path(path).read_text().replace("\\\n", " ")
    out = {}
    for line in text.splitlines():
        m = re.match(r"\s*([A-Za-z_]\w*)\s*:?=\s*(.*)$", line.split("#", 1)[0])
        if m:
            out[m.group(1)] = shlex.split(m.group(2))
    return out


def library_version(root):
    m = re.search(r'^#define PCCD_VERSION_STRING "([^"]+)"',
                  (Path(root) / "include" / "polyccd.h").read_text(), re.M)
    if not m:
        raise RuntimeError("polyccd build: no PCCD_VERSION_STRING in include/polyccd.h")
    return m.group(1)


def pkg_config(*args):
    """pkg-config's words for args, or None when pkg-config or the package is missing."""
    if shutil.which("pkg-config") is None:
        return None
    r = subprocess.run(["pkg-config", *args], capture_output=True, text=True)
    return shlex.split(r.stdout) if r.returncode == 0 else None


def env_words(name, default=()):
    value = os.environ.get(name)
    return shlex.split(value) if value is not None else list(default)


class LibraryBuild:
    """The compile and link commands of libpolyccd for one source root."""

    def __init__(self, root, out_dir):
        self.root = Path(root)
        self.out_dir = Path(out_dir)
        flags = make_variables(self.root / "lib" / "flags.mk")
        self.cxx = env_words("CXX", ["c++"])
        self.version = library_version(self.root)
        self.soname = "libpolyccd.so." + flags["PCCD_SOVERSION"][0]
        system_cflags = (pkg_config("--cflags", "gmpxx") or []) + (pkg_config("--cflags", "eigen3") or [])
        self.compile_flags = (env_words("CXXFLAGS", ["-O2"]) + flags["PCCD_CXXFLAGS"]
                              + ["-I" + str(self.root / "include"), "-I" + str(self.root / "lib")]
                              + system_cflags + env_words("CPPFLAGS"))
        # The version script's path in flags.mk is relative to the source root.
        ldflags = [re.sub(r"(--version-script=)(?!/)", r"\g<1>" + str(self.root) + "/", f)
                   for f in flags["PCCD_LDFLAGS"]]
        libs = pkg_config("--libs", "gmpxx")
        libs = flags["PCCD_LIBS"] if libs is None else libs + ["-pthread"]
        self.link_flags = ldflags + ["-Wl,-soname," + self.soname] + env_words("LDFLAGS")
        self.libs = libs

    def run(self, cmd, what):
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError("polyccd build: %s failed:\n%s\n%s%s"
                               % (what, " ".join(map(shlex.quote, cmd)), r.stdout, r.stderr))

    def probe(self):
        """Compiles and links a program using gmpxx and CGAL, or says what is missing."""
        with tempfile.TemporaryDirectory() as tmp:
            src = Path(tmp) / "probe.cpp"
            src.write_text("#include <gmpxx.h>\n#include <CGAL/version.h>\n"
                           "int main() { mpq_class q(1, 3); return CGAL_VERSION_NR > 0 && q > 0 ? 0 : 1; }\n")
            cmd = self.cxx + self.compile_flags + [str(src), "-o", str(Path(tmp) / "probe")] + self.libs
            r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError(
                "polyccd build: cannot compile against GMP (gmpxx) and CGAL with %s; install them "
                "(Debian: apt-get install g++ libgmp-dev libcgal-dev) or point CPPFLAGS/LDFLAGS "
                "at them.\n%s" % (" ".join(self.cxx), r.stderr[-3000:]))

    def build(self, dest, jobs):
        """Compiles every lib/*/*.cpp and links dest/<soname>; returns its path."""
        self.probe()
        srcs = [self.root / f for f in sources(self.root) if f.endswith(".cpp")]
        objs = [self.out_dir / (Path(s).relative_to(self.root / "lib").with_suffix(".o")) for s in srcs]
        for o in objs:
            o.parent.mkdir(parents=True, exist_ok=True)

        # An object is reused when its command is unchanged and it is newer than its source
        # and every header (any header change recompiles everything).
        stamp = self.out_dir / "command.txt"
        version = subprocess.run(self.cxx + ["--version"], capture_output=True, text=True).stdout
        command = " ".join(self.cxx + self.compile_flags) + "\n" + version
        fresh = stamp.is_file() and stamp.read_text() == command
        newest_header = max((self.root / f).stat().st_mtime for f in sources(self.root)
                            if not f.endswith(".cpp"))

        def compile_one(pair):
            src, obj = pair
            if fresh and obj.is_file() and obj.stat().st_mtime > max(src.stat().st_mtime, newest_header):
                return
            self.run(self.cxx + self.compile_flags + ["-c", str(src), "-o", str(obj)],
                     "compiling " + src.relative_to(self.root).as_posix())
            print("polyccd build: compiled", src.relative_to(self.root).as_posix(), flush=True)

        stamp.unlink(missing_ok=True)
        print("polyccd build: libpolyccd %s, %d sources, %d jobs: %s"
              % (self.version, len(srcs), jobs, " ".join(self.cxx + self.compile_flags)), flush=True)
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            list(pool.map(compile_one, zip(srcs, objs)))
        stamp.write_text(command)
        Path(dest).mkdir(parents=True, exist_ok=True)
        lib = Path(dest) / self.soname
        self.run(self.cxx + self.link_flags + ["-o", str(lib)] + [str(o) for o in objs] + self.libs,
                 "linking " + self.soname)
        return lib


class BuildPy(build_py):
    """The package's modules, into a package directory emptied first: an in-tree build
    (pip install ./bindings/python) reuses bindings/python/build/, where a module or
    library of an earlier build must not linger into the wheel."""

    def run(self):
        if not getattr(self, "editable_mode", False):
            shutil.rmtree(Path(self.build_lib) / "polyccd", ignore_errors=True)
        super().run()


class BuildExt(build_ext):
    """libpolyccd, then the cffi extension linked with it, both in the package directory.
    Both are linked on every build (cffi leaves an unchanged C file untouched, so
    setuptools would otherwise keep an extension linked with other arguments)."""

    def run(self):
        if getattr(self, "editable_mode", False):
            print("polyccd build: editable install: the extension is `make venv`'s (build_ffi.py)")
            return
        self.force = True
        from build_ffi import extension_kwargs, ffibuilder

        root = source_root()
        package_dir = Path(self.get_ext_fullpath("polyccd._pccd")).parent
        jobs = int(os.environ.get("POLYCCD_BUILD_JOBS") or os.cpu_count() or 1)
        lib = LibraryBuild(root, Path(self.build_temp) / "libpolyccd").build(package_dir, max(1, jobs))
        kwargs = dict(libraries=(), extra_objects=[lib], rpath="$ORIGIN")
        c_file = Path(self.build_temp).absolute() / "cffi" / "_pccd.c"
        c_file.parent.mkdir(parents=True, exist_ok=True)
        ffibuilder(root / "include", **kwargs).emit_c_code(str(c_file))
        # The placeholder of setup() (setuptools prepared it in finalize_options) gets the
        # generated source and cffi's arguments.
        (ext,) = self.extensions
        ext.sources = [str(c_file)]
        for name, value in extension_kwargs(root / "include", **kwargs).items():
            setattr(ext, name, value)
        super().run()


class Sdist(sdist):
    """The package plus csrc/: the library's sources and the legal files of the checkout."""

    def make_release_tree(self, base_dir, files):
        super().make_release_tree(base_dir, files)
        root = source_root()
        out = Path(base_dir) / SDIST_SOURCES
        for rel in sources(root) + [f for f in LEGAL if (root / f).is_file()]:
            (out / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(root / rel, out / rel)


setup(
    # One placeholder: build_ext replaces it by cffi's generated extension.
    ext_modules=[Extension("polyccd._pccd", sources=[])],
    cmdclass={"build_py": BuildPy, "build_ext": BuildExt, "sdist": Sdist},
)
