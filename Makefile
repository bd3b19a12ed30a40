# polyccd build. `make` = library + Python venv; `make test` = every test; `make bench`;
# `make demo`. Run as root on a fresh Debian machine, missing system packages are
# installed with apt-get (see deps).

CXX      ?= g++
CC       ?= gcc
PYTHON   ?= python3
BUILD    := build
LIB      := lib/libpolyccd.so
VENV     := .venv
VPY      := $(VENV)/bin/python
# -ffp-contract=off: no fused multiply-add may change a rounding the interval layer
# relies on (see lib/arith/interval.h; tests/c/test_api.c checks it is not fused).
CXXFLAGS ?= -O2 -g
CXXFLAGS += -std=c++17 -fPIC -fvisibility=hidden -fvisibility-inlines-hidden \
            -ffp-contract=off -frounding-math -Wall -Wextra -Wno-unused-parameter \
            -pthread -Iinclude -Ilib -DPCCD_BUILDING
LDLIBS   := -lgmpxx -lgmp -pthread
SAN      ?=

SRCS := $(sort $(wildcard lib/*/*.cpp))
OBJS := $(patsubst lib/%.cpp,$(BUILD)/%.o,$(SRCS))
DEPS := $(OBJS:.o=.d)

APT_PKGS := libgmp-dev libmpfr-dev libcgal-dev libcgal-demo libeigen3-dev g++ make python3-venv python3-dev valgrind

.PHONY: all deps lib venv test test-c test-py check-header check-symbols bench demo clean sanitize valgrind

all: lib venv

# Installs what is missing, only when run as root (CI, fresh machines).
deps:
	@missing=""; for p in $(APT_PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then echo "installing:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "missing system packages:$$missing (run as root or install them)"; exit 1; fi; fi

lib: $(LIB)

$(LIB): $(OBJS) lib/exports.map
	$(CXX) -shared -Wl,--version-script=lib/exports.map -o $@ $(OBJS) $(LDLIBS) $(SAN)

$(BUILD)/%.o: lib/%.cpp | deps
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(SAN) -MMD -MP -c $< -o $@

-include $(DEPS)

$(VENV)/.stamp: bindings/python/requirements.txt | deps
	$(PYTHON) -m venv $(VENV)
	$(VENV)/bin/pip install -q --upgrade pip
	$(VENV)/bin/pip install -q -r bindings/python/requirements.txt
	touch $@

venv: $(VENV)/.stamp $(LIB)
	cd bindings/python && ../../$(VPY) build_ffi.py
	$(VENV)/bin/pip install -q --no-build-isolation --no-deps -e bindings/python

# The C test program, linked against the shared library.
$(BUILD)/test_api: tests/c/test_api.c tests/c/exact_rational.h include/polyccd.h $(LIB)
	@mkdir -p $(BUILD)
	$(CC) -std=c99 -Wall -Wextra -Werror -Iinclude $(SAN) -o $@ tests/c/test_api.c \
	  -Llib -lpolyccd -Wl,-rpath,'$$ORIGIN/../lib' -lm

# Internal probe of lib/poly for tests/test_hermite.py (links the objects directly).
$(BUILD)/poly_probe: tests/cpp/poly_probe.cpp $(OBJS)
	$(CXX) $(CXXFLAGS) -o $@ tests/cpp/poly_probe.cpp $(OBJS) $(LDLIBS)

# The rigid-motion C test (pccd_motion_*), linked against the shared library.
$(BUILD)/test_motion: tests/c/test_motion.c include/polyccd.h $(LIB)
	@mkdir -p $(BUILD)
	$(CC) -std=c99 -Wall -Wextra -Werror -Iinclude $(SAN) -o $@ tests/c/test_motion.c \
	  -Llib -lpolyccd -Wl,-rpath,'$$ORIGIN/../lib' -lm

# The scene C test (pccd_scene_*, pccd_report_*), linked against the shared library.
$(BUILD)/test_scene: tests/c/test_scene.c tests/c/check.h tests/c/scene_fixtures.h include/polyccd.h $(LIB)
	@mkdir -p $(BUILD)
	$(CC) -std=c99 -Wall -Wextra -Werror -Iinclude $(SAN) -o $@ tests/c/test_scene.c \
	  -Llib -lpolyccd -Wl,-rpath,'$$ORIGIN/../lib' -lm

# The on-line index C test (pccd_index_*), linked against the shared library.
$(BUILD)/test_index: tests/c/test_index.c tests/c/check.h tests/c/scene_fixtures.h include/polyccd.h $(LIB)
	@mkdir -p $(BUILD)
	$(CC) -std=c99 -Wall -Wextra -Werror -Iinclude $(SAN) -o $@ tests/c/test_index.c \
	  -Llib -lpolyccd -Wl,-rpath,'$$ORIGIN/../lib' -lm

# The body C test (pccd_body_*), linked against the shared library.
$(BUILD)/test_body: tests/c/test_body.c tests/c/check.h include/polyccd.h $(LIB)
	@mkdir -p $(BUILD)
	$(CC) -std=c99 -Wall -Wextra -Werror -Iinclude $(SAN) -o $@ tests/c/test_body.c \
	  -Llib -lpolyccd -Wl,-rpath,'$$ORIGIN/../lib' -lm

# Internal test of the interval layer's ulp steps (links no library code: header only).
$(BUILD)/test_ulp: tests/cpp/test_ulp.cpp lib/arith/interval.h
	@mkdir -p $(BUILD)
	$(CXX) $(CXXFLAGS) -o $@ tests/cpp/test_ulp.cpp

# Internal test of the range tree's clause bounds against exact rationals.
$(BUILD)/test_halfspace_bounds: tests/cpp/test_halfspace_bounds.cpp lib/range/halfspaces.h lib/arith/interval.h
	@mkdir -p $(BUILD)
	$(CXX) $(CXXFLAGS) -o $@ tests/cpp/test_halfspace_bounds.cpp $(LDLIBS)

# Internal test of the fixed-axis rotation detection (links the objects directly).
$(BUILD)/test_axis_rotation: tests/cpp/test_axis_rotation.cpp $(OBJS)
	$(CXX) $(CXXFLAGS) -o $@ tests/cpp/test_axis_rotation.cpp $(OBJS) $(LDLIBS)

check-header:
	@echo '#include "polyccd.h"' > $(BUILD)/hdr.c
	$(CC) -std=c99 -pedantic -Werror -Wall -Wextra -Iinclude -c $(BUILD)/hdr.c -o $(BUILD)/hdr.o
	@echo "header compiles with -std=c99 -pedantic -Werror"

check-symbols: $(LIB)
	@bad=$$(nm -D --defined-only $(LIB) | awk '$$2 ~ /[TDBRW]/ {print $$3}' | grep -v '^pccd_' || true); \
	if [ -n "$$bad" ]; then echo "exported symbols without pccd_ prefix:"; echo "$$bad"; exit 1; fi; \
	echo "nm -D: only pccd_ symbols exported ($$(nm -D --defined-only $(LIB) | grep -c ' T pccd_') functions)"

test-c: $(BUILD)/test_api $(BUILD)/test_motion $(BUILD)/test_body $(BUILD)/test_scene $(BUILD)/test_index $(BUILD)/test_ulp $(BUILD)/test_halfspace_bounds $(BUILD)/test_axis_rotation check-header check-symbols
	$(BUILD)/test_ulp
	$(BUILD)/test_halfspace_bounds
	$(BUILD)/test_axis_rotation
	$(BUILD)/test_api
	$(BUILD)/test_motion
	$(BUILD)/test_body
	$(BUILD)/test_scene
	$(BUILD)/test_index

test-py: all $(BUILD)/poly_probe
	POLYCCD_QUERY_DIR=$${POLYCCD_QUERY_DIR:-../shared/data/ccd-queries} $(VPY) -m pytest -q tests

test: all test-c test-py

# Memory checks: the C test and the corpus under valgrind (see tests/c/run_valgrind.sh).
valgrind: $(BUILD)/test_api $(BUILD)/test_motion $(BUILD)/test_body $(BUILD)/test_scene $(BUILD)/test_index
	bash tests/c/run_valgrind.sh

# ASan + UBSan build of the library and the C test (tests/c/run_sanitizers.sh).
sanitize:
	bash tests/c/run_sanitizers.sh

include tests/bench/bench.mk

bench: all $(BUILD)/bench_linear
	$(BUILD)/bench_linear $(BENCH_LINEAR_ARGS)
	$(VENV)/bin/pip install -q -r tests/bench/requirements.txt
	$(VPY) tests/bench/bench_queries.py
	$(VPY) tests/bench/bench_bodies.py
	$(VPY) tests/bench/bench_online.py

demo: all
	$(VENV)/bin/polyccd demo

clean:
	rm -rf $(BUILD) build-asan $(LIB) bindings/python/polyccd/_pccd*.so bindings/python/polyccd/_pccd.c
