# polyccd build. `make` = library + Python venv (it prints the library's path);
# `make test` = install what is missing (deps), then `make check` = build and run every
# test with what is installed; `make bench`; `make demo`. Run as root on a fresh Debian
# machine, missing system packages are installed with apt-get (see deps).

CXX      ?= g++
CC       ?= gcc
PYTHON   ?= python3
BUILD    := build
# Every build product is under build/ (lib/ is source only).
LIB      := $(BUILD)/libpolyccd.so
VENV     := .venv
VPY      := $(VENV)/bin/python
# The library's own flags (-ffp-contract=off, -frounding-math, hidden visibility, ...) are
# in lib/flags.mk, shared with the pip build (bindings/python/setup.py).
include lib/flags.mk
CXXFLAGS ?= -O2 -g
CXXFLAGS += $(PCCD_CXXFLAGS) -Iinclude -Ilib
LDLIBS   := $(PCCD_LIBS)
# The shared library: the real file libpolyccd.so.VERSION (VERSION from polyccd.h) with the
# soname libpolyccd.so.SOVERSION, and the symlinks libpolyccd.so.SOVERSION (what programs
# load) and libpolyccd.so (what -lpolyccd links), as installed by `make install`.
VERSION  := $(shell sed -n 's/^\#define PCCD_VERSION_STRING "\(.*\)"/\1/p' include/polyccd.h)
SONAME   := libpolyccd.so.$(PCCD_SOVERSION)
LIB_REAL := $(BUILD)/libpolyccd.so.$(VERSION)
ifeq ($(VERSION),)
$(error no PCCD_VERSION_STRING in include/polyccd.h)
endif
SAN      ?=

SRCS := $(sort $(wildcard lib/*/*.cpp))
OBJS := $(patsubst lib/%.cpp,$(BUILD)/%.o,$(SRCS))
DEPS := $(OBJS:.o=.d)

# The test programs, found by name so that a new tests/c/test_*.c or tests/cpp/test_*.cpp
# needs no Makefile edit: C tests link the shared library (the public API only), C++
# tests link the library's objects (internal code). Headers they include are tracked by
# -MMD, never listed here.
C_TESTS   := $(patsubst tests/c/%.c,$(BUILD)/%,$(sort $(wildcard tests/c/test_*.c)))
CPP_TESTS := $(patsubst tests/cpp/%.cpp,$(BUILD)/%,$(sort $(wildcard tests/cpp/test_*.cpp)))

# The system packages, one list shared with .ci/run (comments after # dropped).
APT_PKGS := $(strip $(shell sed 's/\#.*//' .ci/apt-packages.txt))

# Parallel by default: the entry points below build with -j<number of CPUs> unless the
# command line gave its own -j (seen in MAKEFLAGS only inside recipes, hence `=`).
# GNU nproc also honours OMP_NUM_THREADS / OMP_THREAD_LIMIT (set to 1 by dask's nanny and
# by many HPC shells): the build's job count is the CPU count, not an OpenMP setting.
NPROC    := $(shell env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc 2>/dev/null || echo 2)
PAR       = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(NPROC))

.PHONY: all deps lib venv wheel docs install install-dirs-absolute uninstall check test test-c test-py check-header check-symbols bench demo clean sanitize valgrind tsan

# The entry points of a fresh machine (all, test, demo, bench, valgrind, sanitize) run
# deps first, then make the rest in a sub-make, so nothing compiles while apt-get is still
# installing (also under -j). `make check` and the targets below it use what is installed.
all: deps
	@$(MAKE) --no-print-directory $(PAR) lib venv
	@echo "libpolyccd: $(abspath $(LIB))"

# Installs what is missing, only when run as root (CI, fresh machines).
deps:
	@missing=""; for p in $(APT_PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then echo "installing:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "missing system packages:$$missing (run as root or install them)"; exit 1; fi; fi

lib: $(LIB)

$(LIB_REAL): $(OBJS) lib/exports.map lib/flags.mk
	$(CXX) $(PCCD_LDFLAGS) -Wl,-soname,$(SONAME) -o $@ $(OBJS) $(LDLIBS) $(SAN)

$(LIB): $(LIB_REAL)
	ln -sf $(notdir $(LIB_REAL)) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $@

$(BUILD)/%.o: lib/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(SAN) -MMD -MP -c $< -o $@

# The dev venv: runtime requirements (bindings/python/requirements.txt) and those of the
# tests, the editable build and the demo (tests/requirements.txt, which includes them).
$(VENV)/.stamp: bindings/python/requirements.txt tests/requirements.txt
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/pip install -q --upgrade pip
	$(VENV)/bin/pip install -q -r tests/requirements.txt
	touch $@

# The editable install: build_ffi.py generates the cffi declarations from
# include/polyccd.h and builds the extension in place against build/libpolyccd.so, then
# pip installs the package in editable mode. Redone only when its inputs change (the
# stamp is under build/, so `make clean`, which removes the extension, redoes it): the
# header, the two build scripts, the package metadata, the venv. A rebuilt library
# needs no new extension (it loads the library by its soname, and the interface is the
# header), hence the order-only $(LIB).
EDITABLE := $(BUILD)/editable.stamp
venv: $(EDITABLE)

$(EDITABLE): $(VENV)/.stamp include/polyccd.h bindings/python/build_ffi.py \
             bindings/python/gen_cdef.py bindings/python/pyproject.toml bindings/python/setup.py | $(LIB)
	cd bindings/python && ../../$(VPY) build_ffi.py
	$(VENV)/bin/pip install -q --no-build-isolation --no-deps -e bindings/python
	@touch $@

# `make install PREFIX=/abs/path` (default /usr/local; DESTDIR for staging): the header,
# the library (real file, soname symlink, link symlink), polyccd.pc and the CMake package
# (packaging/README.md). `make uninstall` with the same variables removes exactly those.
PREFIX     ?= /usr/local
LIBDIR     ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
DESTDIR    ?=
# The installed pkg-config and CMake files name the library and header directories
# relative to their own directory (${pcfiledir}, CMAKE_CURRENT_LIST_DIR), so an installed
# tree still works after it is moved or copied elsewhere as a whole.
rel_to = $(shell realpath -m --relative-to=$(1) $(2))
INSTALL_SUBST := sed -e 's|@PC_LIBDIR@|$(call rel_to,$(LIBDIR)/pkgconfig,$(LIBDIR))|g' \
  -e 's|@PC_INCLUDEDIR@|$(call rel_to,$(LIBDIR)/pkgconfig,$(INCLUDEDIR))|g' \
  -e 's|@CMAKE_LIBDIR@|$(call rel_to,$(LIBDIR)/cmake/polyccd,$(LIBDIR))|g' \
  -e 's|@CMAKE_INCLUDEDIR@|$(call rel_to,$(LIBDIR)/cmake/polyccd,$(INCLUDEDIR))|g' \
  -e 's|@VERSION@|$(VERSION)|g' \
  -e 's|@SOVERSION@|$(PCCD_SOVERSION)|g' -e 's|@LIBS@|$(PCCD_LIBS)|g'
INSTALLED := $(INCLUDEDIR)/polyccd.h $(LIBDIR)/libpolyccd.so.$(VERSION) $(LIBDIR)/$(SONAME) \
  $(LIBDIR)/libpolyccd.so $(LIBDIR)/pkgconfig/polyccd.pc \
  $(LIBDIR)/cmake/polyccd/polyccdConfig.cmake $(LIBDIR)/cmake/polyccd/polyccdConfigVersion.cmake

install-dirs-absolute:
	@case "$(PREFIX)$(LIBDIR)$(INCLUDEDIR)" in /*) ;; *) echo "PREFIX must be an absolute path"; exit 1;; esac
	@for d in "$(LIBDIR)" "$(INCLUDEDIR)"; do case "$$d" in /*) ;; *) echo "$$d: not absolute"; exit 1;; esac; done

install: install-dirs-absolute
	@$(MAKE) --no-print-directory $(PAR) lib
	install -d $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(LIBDIR)/cmake/polyccd
	install -m 644 include/polyccd.h $(DESTDIR)$(INCLUDEDIR)/polyccd.h
	install -m 755 $(LIB_REAL) $(DESTDIR)$(LIBDIR)/libpolyccd.so.$(VERSION)
	ln -sf libpolyccd.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libpolyccd.so
	$(INSTALL_SUBST) packaging/polyccd.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/polyccd.pc
	$(INSTALL_SUBST) packaging/polyccdConfig.cmake.in > $(DESTDIR)$(LIBDIR)/cmake/polyccd/polyccdConfig.cmake
	$(INSTALL_SUBST) packaging/polyccdConfigVersion.cmake.in \
	  > $(DESTDIR)$(LIBDIR)/cmake/polyccd/polyccdConfigVersion.cmake
	@echo "installed libpolyccd $(VERSION) into $(DESTDIR)$(PREFIX)"

uninstall: install-dirs-absolute
	rm -f $(addprefix $(DESTDIR),$(INSTALLED))
	-rmdir $(DESTDIR)$(LIBDIR)/cmake/polyccd 2>/dev/null

# A C test program: one source file, linked against the shared library, which it finds
# beside itself (rpath $ORIGIN). -MMD -MP write build/test_X.d, the headers it includes.
$(C_TESTS): $(BUILD)/%: tests/c/%.c $(LIB)
	$(CC) -std=c99 -Wall -Wextra -Werror -g -Iinclude $(SAN) -MMD -MP -MF $@.d -MT $@ \
	  -o $@ $< -L$(BUILD) -lpolyccd -Wl,-rpath,'$$ORIGIN' -lm

# An internal C++ test: one source file, linked with the library's objects (the objects
# it does not use are harmless); its lib/ headers are tracked by -MMD. poly_probe is no
# test but a probe of lib/poly that tests/test_hermite.py runs; it is built the same way.
$(CPP_TESTS) $(BUILD)/poly_probe: $(BUILD)/%: tests/cpp/%.cpp $(OBJS)
	$(CXX) $(CXXFLAGS) -MMD -MP -MF $@.d -MT $@ -o $@ $< $(OBJS) $(LDLIBS)

-include $(DEPS) $(addsuffix .d,$(C_TESTS) $(CPP_TESTS) $(BUILD)/poly_probe)

check-header:
	@mkdir -p $(BUILD)
	@echo '#include "polyccd.h"' > $(BUILD)/hdr.c
	$(CC) -std=c99 -pedantic -Werror -Wall -Wextra -Iinclude -c $(BUILD)/hdr.c -o $(BUILD)/hdr.o
	@echo "header compiles with -std=c99 -pedantic -Werror"

check-symbols: $(LIB)
	@bad=$$(nm -D --defined-only $(LIB) | awk '$$2 ~ /[TDBRW]/ {print $$3}' | grep -v '^pccd_' || true); \
	if [ -n "$$bad" ]; then echo "exported symbols without pccd_ prefix:"; echo "$$bad"; exit 1; fi; \
	echo "nm -D: only pccd_ symbols exported ($$(nm -D --defined-only $(LIB) | grep -c ' T pccd_') functions)"

# Every test program: the internal C++ tests first (the layers below the API), then the
# C API tests; the first failure stops the run.
test-c: $(CPP_TESTS) $(C_TESTS) check-header check-symbols
	@set -e; for t in $(CPP_TESTS) $(C_TESTS); do echo "== $$t"; $$t; done

# pytest in $(PYTEST_WORKERS) worker processes (pytest-xdist). Tests write only under
# their tmp_path and take ports from the OS (port 0); --dist loadfile keeps a file's
# tests, and so its module-scoped fixtures, on one worker: tests/test_install.py, the
# only file that builds in the tree (make install, pip wheel, the sdist), runs alone.
PYTEST_WORKERS ?= 2
test-py: lib venv $(BUILD)/poly_probe
	POLYCCD_QUERY_DIR=$${POLYCCD_QUERY_DIR:-../shared/data/ccd-queries} $(VPY) -m pytest -q \
	  -n $(PYTEST_WORKERS) --dist loadfile tests

# Builds and runs every test (C, C++ and Python) with what is installed: no apt-get.
# Everything is built first, in parallel; then the C and C++ tests run, then the C++
# OMPL validators' test (tests/ompl/ompl.mk: it says "skipped" without OMPL's headers), then pytest,
# whose summary line ("N passed ...") ends the output.
check:
	@$(MAKE) --no-print-directory $(PAR) lib venv $(CPP_TESTS) $(C_TESTS) $(BUILD)/poly_probe
	@$(MAKE) --no-print-directory test-c
	@$(MAKE) --no-print-directory test-ompl
	@$(MAKE) --no-print-directory test-py

test: deps
	@$(MAKE) --no-print-directory check

# Memory checks: the C tests and the corpus under valgrind (see tests/c/run_valgrind.sh).
valgrind: deps
	@$(MAKE) --no-print-directory $(PAR) $(C_TESTS)
	bash tests/c/run_valgrind.sh $(notdir $(C_TESTS))

# ASan + UBSan build of the library and the C tests (tests/c/run_sanitizers.sh).
sanitize: deps
	+bash tests/c/run_sanitizers.sh

# ThreadSanitizer build of the library and the concurrency test (tests/c/run_tsan.sh).
tsan: deps
	+bash tests/c/run_tsan.sh

include tests/bench/bench.mk
include tests/fuzz/fuzz.mk
include tests/ompl/ompl.mk

bench: all $(BUILD)/bench_linear $(BUILD)/bench_min_distance
	$(BUILD)/bench_linear $(BENCH_LINEAR_ARGS)
	$(BUILD)/bench_min_distance $(BENCH_MD_ARGS)
	$(VENV)/bin/pip install -q -r tests/bench/requirements.txt
	$(VPY) tests/bench/bench_queries.py
	$(VPY) tests/bench/bench_bodies.py
	$(VPY) tests/bench/bench_bvh.py
	$(VPY) tests/bench/bench_online.py
	$(VPY) tests/bench/bench_distributed.py
	$(VPY) tests/bench/bench_robot.py
	$(VPY) tests/bench/bench_plainmp.py --n 200
	$(VPY) tests/bench/bench_threads.py
	$(VPY) tests/bench/bench_ipc_loop.py

# `make docs`: the reference in build/docs/html (docs/: the Markdown pages, the Python
# API from the package's docstrings, the C API from include/polyccd.h's comments);
# warnings are errors, as in tests/test_docs.py.
docs: all
	$(VENV)/bin/sphinx-build -W --keep-going -q -b html docs $(BUILD)/docs/html
	@echo "docs: $(abspath $(BUILD))/docs/html/index.html"

# `make wheel`: the pip wheel of bindings/python (built against this machine's GMP and
# libstdc++), repaired by auditwheel into a manylinux wheel in build/dist/: GMP is copied
# into polyccd.libs/ and linked there, so the wheel needs no libgmp on the target machine
# (glibc and libstdc++ at least as new as this machine's, the tag says which).
wheel: all
	rm -rf $(BUILD)/dist
	$(VENV)/bin/pip wheel -q --no-deps --no-build-isolation -w $(BUILD)/dist/linux ./bindings/python
	PATH="$(abspath $(VENV))/bin:$$PATH" $(VENV)/bin/auditwheel repair -w $(BUILD)/dist $(BUILD)/dist/linux/polyccd-*.whl
	PATH="$(abspath $(VENV))/bin:$$PATH" $(VENV)/bin/auditwheel show $(BUILD)/dist/polyccd-*manylinux*.whl
	@echo "wheel: $$(ls $(abspath $(BUILD))/dist/polyccd-*manylinux*.whl)"

# The main job: polyccd demo, then OMPL planning the Panda with exact edge checks
# (examples/ompl_panda.py, a few seconds; its packages come with tests/requirements.txt).
demo: all
	$(VENV)/bin/polyccd demo
	@echo
	$(VPY) examples/ompl_panda.py --seed 3

# lib/libpolyccd.so: where builds before the move to build/ left the library.
clean:
	rm -rf $(BUILD) build-asan build-fuzz build-tsan bindings/python/build lib/libpolyccd.so bindings/python/polyccd/_pccd*.so bindings/python/polyccd/_pccd.c
