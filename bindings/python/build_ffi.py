"""Builds the cffi extension polyccd/_pccd (API mode) in place, against build/libpolyccd.so.

Run from bindings/python (make venv does): python build_ffi.py

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

ffibuilder = FFI()
ffibuilder.cdef(header_cdef(REPO / "include" / "polyccd.h"))
ffibuilder.set_source(
    "polyccd._pccd",
    '#include "polyccd.h"',
    include_dirs=[str(REPO / "include")],
    library_dirs=[str(REPO / "build")],
    libraries=["polyccd"],
    # polyccd/_pccd*.so finds the library at <repo>/build without LD_LIBRARY_PATH.
    extra_link_args=["-Wl,-rpath,$ORIGIN/../../../build"],
    extra_compile_args=["-Werror"],
)

if __name__ == "__main__":
    ffibuilder.compile(tmpdir=str(HERE), verbose=False)
    # Keep only polyccd/_pccd.c and the extension (what `make clean` removes).
    (HERE / "polyccd" / "_pccd.o").unlink(missing_ok=True)
