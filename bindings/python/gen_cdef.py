"""Generates the cffi declarations (the cdef) of include/polyccd.h from the header itself.

build_ffi.py calls cdef_from_header() at build time, so the Python bindings declare
exactly what the header declares: there is no hand copy to keep in sync. Run
`python gen_cdef.py` to print the generated text.

cffi's parser takes plain C declarations, without a preprocessor. From the header:

- comments go (block and line comments; string literals are left alone);
- preprocessor lines go, and so does the whole body of every conditional block (#if,
  #ifdef, #ifndef ... #endif, with its #else / #elif branches: the extern "C" guards and
  the platform choice of the export macro), except the include guard (#ifndef X followed
  by #define X), whose body is the header;
- the export macro PCCD_API goes from the declarations;
- every enum value becomes `...` and so does every integer #define: cffi then takes the
  values from the compiler when it builds the extension, so they cannot drift;
- a #define of a string literal becomes `static char *const NAME;` (cffi's form for a
  string constant, read at build time too);
- function-like macros and #defines without a value are dropped (cffi cannot declare
  them). Any other #define (a floating-point value, another macro's name) stops the build
  with its name: say here how to declare it rather than lose it silently.

build_ffi.py compiles the extension against the real header with -Werror, so anything
this module turned into a wrong declaration fails the build, and tests/test_cdef.py
checks that every function of the header and of the library's exports is declared.
"""
import re
import sys
from pathlib import Path

HEADER = Path(__file__).absolute().parent.parent.parent / "include" / "polyccd.h"

# Macros that only decorate declarations (symbol visibility): erased as words.
EXPORT_MACROS = ("PCCD_API",)

_INTEGER = re.compile(r"(0[xX][0-9a-fA-F]+|[0-9]+)[uUlL]*")
# Words allowed in an integer #define besides literals: the types of a cast such as
# ((size_t)-1). cffi's `#define NAME ...` accepts any integer constant expression.
_CAST_WORDS = {"size_t", "unsigned", "signed", "int", "long", "short", "char"}
_OPERATORS = set("()+-*/%~<>&|^!")


def strip_comments(text):
    """text without /* */ and // comments. A comment becomes one space, plus the line
    breaks it spanned, so line structure (and so directives) stays as it was."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in "\"'":                       # a string or character literal: copy it whole
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise ValueError("unterminated /* comment")
            out.append(" " + "\n" * text.count("\n", i, j))
            i = j + 2
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j            # keep the line break itself
            out.append(" ")
        else:
            out.append(c)
            i += 1
    return "".join(out)


def _directive(line):
    """(name, rest) of a preprocessor line such as '#  define X 1', else None."""
    m = re.match(r"\s*#\s*(\w*)\s*(.*)$", line)
    return (m.group(1), m.group(2).strip()) if m else None


def _is_integer_expression(value):
    for tok in re.findall(r"\w+|\S", value):
        if not (_INTEGER.fullmatch(tok) or tok in _CAST_WORDS or tok in _OPERATORS):
            return False
    return True


def _define(rest):
    """The cdef line for `#define rest`, or None when cffi cannot take it."""
    m = re.match(r"(\w+)(\(?)\s*(.*)$", rest)
    name, function_like, value = m.group(1), m.group(2), m.group(3).strip()
    if function_like or not value:
        return None
    if re.fullmatch(r'"([^"\\]|\\.)*"', value):
        return "static char *const %s;" % name
    if _is_integer_expression(value):
        return "#define %s ..." % name
    raise ValueError("#define %s %s: neither an integer nor a string constant; "
                     "teach bindings/python/gen_cdef.py how to declare it" % (name, value))


def _enum_values_elided(text):
    """Every `= value` inside an enum body becomes `= ...` (values come from the compiler)."""
    def body(m):
        return m.group(1) + re.sub(r"=[^,}]*?(\s*)(?=[,}]|$)", r"= ...\1", m.group(2)) + m.group(3)
    return re.sub(r"(\benum\b[^{;]*\{)([^}]*)(\})", body, text)


def cdef_from_header(text):
    """The cffi cdef text of a C header (see the module docstring for the rules)."""
    text = text.replace("\\\n", " ")
    lines = strip_comments(text).split("\n")
    # A line that held only a comment is dropped, not left blank inside a struct or enum.
    was_blank = [not line.strip() for line in text.split("\n")]
    kept = []
    # One entry per open conditional block: True when its body is kept (the include
    # guard), False when it is dropped.
    blocks = []
    for k, line in enumerate(lines):
        d = _directive(line)
        dropping = not all(blocks)
        if d is None:
            if not dropping and (line.strip() or was_blank[k]):
                kept.append(line)
            continue
        name, rest = d
        if name in ("if", "ifdef", "ifndef"):
            blocks.append(not dropping and name == "ifndef" and _guard_follows(lines, k, rest))
        elif name in ("else", "elif"):
            if blocks and blocks[-1]:
                raise ValueError("#%s in the include guard's block" % name)
        elif name == "endif":
            if not blocks:
                raise ValueError("#endif without #if")
            blocks.pop()
        elif name == "define" and not dropping:
            decl = _define(rest)
            if decl is not None:
                kept.append(decl)
        # #include, #undef, #pragma, #error, the guard's own #define: nothing to declare.
    if blocks:
        raise ValueError("#if without #endif")
    body = "\n".join(kept)
    for macro in EXPORT_MACROS:
        body = re.sub(r"\b%s\b[ \t]*" % macro, "", body)
    body = _enum_values_elided(body)
    body = re.sub(r"[ \t]+\n", "\n", body)   # trailing blanks
    body = re.sub(r"\n{3,}", "\n\n", body).strip()
    return "/* Generated from include/polyccd.h by bindings/python/gen_cdef.py; do not edit. */\n" \
        + body + "\n"


def _guard_follows(lines, k, name):
    """Whether `#ifndef name` at line k is an include guard: the next non-blank line is
    `#define name` with no value."""
    for line in lines[k + 1:]:
        if line.strip():
            d = _directive(line)
            return d is not None and d[0] == "define" and d[1] == name
    return False


def header_cdef(header=HEADER):
    """The cdef of include/polyccd.h (or of another header)."""
    return cdef_from_header(Path(header).read_text(encoding="utf-8"))


if __name__ == "__main__":
    sys.stdout.write(header_cdef(*sys.argv[1:]))
