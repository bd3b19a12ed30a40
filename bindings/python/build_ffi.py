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


# Ctrl-C for long calls (polyccd/_interrupt.py). cffi releases the GIL around every C
# call, but Python runs its SIGINT handler only between bytecodes, so a KeyboardInterrupt
# would wait for the call to end. This C handler, installed in front of Python's,
# sets the pccd_cancel of the main thread's running call (the call then ends with
# PCCD_ELIMIT at its next work step) and chains to the handler it replaced, which
# schedules the KeyboardInterrupt. pccd_cancel_set is an atomic store, signal-safe.
SIGINT_SHIM = r"""
#include <signal.h>
#include <stdatomic.h>
#include <string.h>

static pccd_cancel *_Atomic polyccd_py_target; /* a caller's own flag, during a call */
static pccd_cancel *polyccd_py_own; /* the main thread's flag, for calls given none */
static volatile long polyccd_py_hits; /* SIGINTs seen (Python resets polyccd_py_own) */
static struct sigaction polyccd_py_prev;

static void polyccd_py_on_sigint(int sig, siginfo_t *info, void *ctx) {
  pccd_cancel *c = atomic_load(&polyccd_py_target);
  if (c) pccd_cancel_set(c);
  if (polyccd_py_own) pccd_cancel_set(polyccd_py_own);
  polyccd_py_hits = polyccd_py_hits + 1;
  if (polyccd_py_prev.sa_flags & SA_SIGINFO) {
    if (polyccd_py_prev.sa_sigaction) polyccd_py_prev.sa_sigaction(sig, info, ctx);
  } else if (polyccd_py_prev.sa_handler != SIG_IGN && polyccd_py_prev.sa_handler != SIG_DFL) {
    polyccd_py_prev.sa_handler(sig);
  }
}

/* 1 when the handler is (now) in front of SIGINT's; 0 when it cannot chain (the current
 * disposition is SIG_DFL or SIG_IGN: Python does not handle SIGINT then). */
static int polyccd_py_sigint_install(void) {
  struct sigaction cur, mine;
  if (!polyccd_py_own && pccd_cancel_new(&polyccd_py_own) != PCCD_OK) return 0;
  if (sigaction(SIGINT, NULL, &cur) != 0) return 0;
  if ((cur.sa_flags & SA_SIGINFO) && cur.sa_sigaction == polyccd_py_on_sigint) return 1;
  if (!(cur.sa_flags & SA_SIGINFO) && (cur.sa_handler == SIG_DFL || cur.sa_handler == SIG_IGN))
    return 0;
  memset(&mine, 0, sizeof mine);
  mine.sa_sigaction = polyccd_py_on_sigint;
  mine.sa_flags = SA_SIGINFO | (cur.sa_flags & SA_ONSTACK);
  sigemptyset(&mine.sa_mask);
  polyccd_py_prev = cur;
  return sigaction(SIGINT, &mine, NULL) == 0;
}

/* Around a main-thread call given its own flag: Ctrl-C sets that flag too. */
static void polyccd_py_target_set(pccd_cancel *c) { atomic_store(&polyccd_py_target, c); }
static pccd_cancel *polyccd_py_own_flag(void) { return polyccd_py_own; }
static long polyccd_py_hit_count(void) { return polyccd_py_hits; }
"""

SIGINT_CDEF = """
int polyccd_py_sigint_install(void);
void polyccd_py_target_set(pccd_cancel *c);
pccd_cancel *polyccd_py_own_flag(void);
long polyccd_py_hit_count(void);
"""


def ffibuilder(include_dir, **kwargs):
    """An FFI builder of polyccd._pccd, its cdef generated from include_dir/polyccd.h (the
    arguments of extension_kwargs), plus the SIGINT shim above."""
    ffi = FFI()
    ffi.cdef(header_cdef(Path(include_dir) / "polyccd.h") + SIGINT_CDEF)
    ffi.set_source("polyccd._pccd", '#include "polyccd.h"\n' + SIGINT_SHIM,
                   **extension_kwargs(include_dir, **kwargs))
    return ffi


if __name__ == "__main__":
    # polyccd/_pccd*.so finds the library at <repo>/build without LD_LIBRARY_PATH.
    ffi = ffibuilder(REPO / "include", library_dirs=[REPO / "build"],
                     rpath="$ORIGIN/../../../build")
    ffi.compile(tmpdir=str(HERE), verbose=False)
    # Keep only polyccd/_pccd.c and the extension (what `make clean` removes).
    (HERE / "polyccd" / "_pccd.o").unlink(missing_ok=True)
