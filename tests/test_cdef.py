"""The generated cffi declarations cover the whole C API.

bindings/python/gen_cdef.py turns include/polyccd.h into the cdef at build time. Every
function the header declares and every pccd_ function the shared library exports must be
declared there, and the built extension must expose each one on `lib`. The names of the
header are read here with a regular expression of their own, not with the generator,
so a declaration the generator loses is noticed.
"""
import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADER = os.path.join(ROOT, "include", "polyccd.h")
LIBRARY = os.path.join(ROOT, "build", "libpolyccd.so")
sys.path.insert(0, os.path.join(ROOT, "bindings", "python"))
from gen_cdef import cdef_from_header   # noqa: E402


def function_names(c_text):
    """Names of the pccd_ functions declared in C text: after the comments are removed,
    a pccd_ name followed by `(` is a function (the API has no function-like pccd_ macro
    and no function pointer)."""
    code = re.sub(r"/\*.*?\*/|//[^\n]*", " ", c_text, flags=re.S)
    return set(re.findall(r"\b(pccd_\w+)\s*\(", code))


def exported_functions(library=LIBRARY):
    """The pccd_ functions the shared library exports (`nm -D --defined-only`, type T)."""
    out = subprocess.run(["nm", "-D", "--defined-only", library], capture_output=True,
                         text=True, check=True).stdout
    return {m.group(1) for m in re.finditer(r" T (pccd_\w+)$", out, re.M)}


def cdef_problems(header_text, cdef_text, exported):
    """What the cdef lacks: one line per function of the header or of the library's
    exports that it does not declare (empty when it is complete)."""
    declared = function_names(cdef_text)
    return (["%s: declared in include/polyccd.h, not in the cdef" % f
             for f in sorted(function_names(header_text) - declared)]
            + ["%s: exported by libpolyccd.so, not in the cdef" % f
               for f in sorted(exported - declared)])


def without_declaration(cdef_text, name):
    """cdef_text with the declaration of function `name` (up to its `;`) removed."""
    doctored, n = re.subn(r"[^;{}]*\b%s\s*\([^;]*;" % name, "", cdef_text)
    assert n == 1, "no single declaration of %s in the cdef" % name
    return doctored


@pytest.fixture(scope="module")
def header_text():
    with open(HEADER, encoding="utf-8") as f:
        return f.read()


@pytest.fixture(scope="module")
def exported():
    names = exported_functions()
    assert "pccd_version" in names, "nm found no pccd_ export in %s" % LIBRARY
    return names


def test_cdef_declares_every_function(header_text, exported):
    assert cdef_problems(header_text, cdef_from_header(header_text), exported) == []


def test_check_fails_on_a_function_missing_from_the_cdef(header_text, exported):
    # The check above can fail: a cdef without pccd_report_stats is reported twice, as
    # a header function and as an export.
    doctored = without_declaration(cdef_from_header(header_text), "pccd_report_stats")
    assert cdef_problems(header_text, doctored, exported) == [
        "pccd_report_stats: declared in include/polyccd.h, not in the cdef",
        "pccd_report_stats: exported by libpolyccd.so, not in the cdef"]


def test_check_fails_on_an_export_missing_from_the_header(header_text, exported):
    # A function exported by the library but forgotten in the header (hence in the cdef).
    header = without_declaration(header_text, "pccd_motion_validate")
    cdef = cdef_from_header(header)
    assert cdef_problems(header, cdef, exported) == [
        "pccd_motion_validate: exported by libpolyccd.so, not in the cdef"]


def test_extension_exposes_every_function(header_text, exported):
    from polyccd._pccd import lib
    missing = sorted(f for f in function_names(header_text) | exported if not hasattr(lib, f))
    assert missing == []


def test_constants_reach_python():
    # #define values come from the compiler: a string, an integer, a cast expression.
    from polyccd._pccd import ffi, lib
    assert ffi.string(lib.PCCD_VERSION_STRING).decode() == "0.1.0"
    assert lib.PCCD_MAX_BODY_ELEMENTS == 50000000
    assert lib.PCCD_WHOLE == 2 ** (8 * ffi.sizeof("size_t")) - 1


def test_generator_layout():
    # Comments, the extern "C" and platform blocks and PCCD_API go; the include guard's
    # body, multi-line declarations, enums (values elided) and structs stay.
    header = """/* top */
#ifndef X_H
#define X_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
#if defined(_WIN32)
#define PCCD_API
#else
#define PCCD_API __attribute__((visibility("default")))
#endif
#define PCCD_NAME "x /* not a comment */"
#define PCCD_N 12 /* twelve */
#define PCCD_ALL ((size_t)-1)
#define PCCD_TWICE(a) ((a) * 2)
typedef enum pccd_e { PCCD_A = 0, /* a */
  PCCD_B = -1 // b
} pccd_e;
typedef struct pccd_s {
  int a; /* one
            two */
  double b[2];
} pccd_s;
PCCD_API int pccd_f(pccd_s *s,
                    const char *t);
#ifdef __cplusplus
}
#endif
#endif
"""
    body = cdef_from_header(header).split("\n", 1)[1]
    assert body == """static char *const PCCD_NAME;
#define PCCD_N ...
#define PCCD_ALL ...
typedef enum pccd_e { PCCD_A = ...,
  PCCD_B = ...
} pccd_e;
typedef struct pccd_s {
  int a;
  double b[2];
} pccd_s;
int pccd_f(pccd_s *s,
                    const char *t);
"""


def test_generator_refuses_an_unknown_define():
    with pytest.raises(ValueError, match="PCCD_HALF"):
        cdef_from_header("#define PCCD_HALF 0.5\n")
