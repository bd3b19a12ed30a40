# The flags libpolyccd is built with: one list for the Makefile (which includes this file)
# and for the pip build (bindings/python/setup.py reads these variables, so keep each one
# a plain `NAME := words`, `\` continuations allowed, no make functions). Include paths are
# each build's own (-Iinclude -Ilib here, the sdist's csrc/ there).
#
# -ffp-contract=off: no fused multiply-add may change a rounding the interval layer relies
# on (see lib/arith/interval.h; tests/c/check.h checks it is not fused). -frounding-math:
# the interval layer switches the rounding mode. -fvisibility=hidden with the version
# script lib/exports.map: only the C API (pccd_*) is exported (`make check-symbols`).
PCCD_CXXFLAGS := -std=c++17 -fPIC -fvisibility=hidden -fvisibility-inlines-hidden \
                 -ffp-contract=off -frounding-math -Wall -Wextra -Wno-unused-parameter \
                 -pthread -DPCCD_BUILDING
# Linking the shared library: the version script's path is relative to the source root.
PCCD_LDFLAGS  := -shared -Wl,--version-script=lib/exports.map
PCCD_LIBS     := -lgmpxx -lgmp -pthread
# The soname's number (libpolyccd.so.0): the major version of PCCD_VERSION_STRING
# (include/polyccd.h); the real file is libpolyccd.so.<PCCD_VERSION_STRING>.
PCCD_SOVERSION := 0
