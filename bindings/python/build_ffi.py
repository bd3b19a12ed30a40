"""The cffi extension polyccd/_pccd (API mode), for the two builds:

- `make venv` runs `python build_ffi.py` from bindings/python: the extension is built in
  place against build/libpolyccd.so of the checkout (the repo's editable dev venv);
- the pip build (setup.py) calls ffibuilder() with the sdist's or checkout's include
  directory and the libpolyccd it has just compiled, found beside the extension ($ORIGIN).

The declarations are generated from include/polyccd.h by gen_cdef.py at each build. The
generated C file includes the real header and is compiled with -Werror, so a declaration
the generator got wrong fails the build; enum and #define values come from the compiler,
and the struct layouts are checked by cffi when the module is loaded
(polyccd/__init__.py imports it).
"""
from pathlib import Path

from cffi import FFI

from gen_cdef import header_cdef

HERE = Path(__file__).absolute().parent
REPO = HERE.parent.parent


def extension_kwargs(include_dir, libraries=("polyccd",), library_dirs=(), extra_objects=(),
                     rpath="$ORIGIN"):
    """The compile and link arguments of polyccd._pccd (cffi's set_source, or a
    setuptools Extension): the real header from include_dir, compiled with -Werror, linked
    with libpolyccd (by -l through library_dirs, or as extra_objects), found at run time
    through rpath."""
    return dict(include_dirs=[str(include_dir)],
                library_dirs=[str(d) for d in library_dirs],
                libraries=list(libraries),
                extra_objects=[str(o) for o in extra_objects],
                extra_link_args=["-Wl,-rpath," + rpath],
                extra_compile_args=["-Werror"])


def ffibuilder(include_dir, **kwargs):
    """An FFI builder of polyccd._pccd, its cdef generated from include_dir/polyccd.h (the
    arguments of extension_kwargs)."""
    ffi = FFI()
    ffi.cdef(header_cdef(Path(include_dir) / "polyccd.h"))
    ffi.set_source("polyccd._pccd", '#include "polyccd.h"',
                   **extension_kwargs(include_dir, **kwargs))
    return ffi


if __name__ == "__main__":
    # polyccd/_pccd*.so finds the library at <repo>/build without LD_LIBRARY_PATH.
    ffi = ffibuilder(REPO / "include", library_dirs=[REPO / "build"],
                     rpath="$ORIGIN/../../../build")
    ffi.compile(tmpdir=str(HERE), verbose=False)
    # Keep only polyccd/_pccd.c and the extension (what `make clean` removes).
    (HERE / "polyccd" / "_pccd.o").unlink(missing_ok=True)
