# Fuzzing (tests/fuzz/README.md). Included by the top Makefile. `make fuzz` installs clang
# and atheris when missing, builds the library's sources with clang and
# -fsanitize=fuzzer-no-link,address,undefined into $(FUZZ_BUILD) (beside build/, which
# it does not touch), links each libFuzzer harness tests/fuzz/fuzz_*.c against them,
# writes the seed corpora from corpus/ and the shared query set, then runs every
# harness (C and Python) for FUZZ_SECONDS seconds and prints its executions.
# Arguments: FUZZ_SECONDS (default 10 per harness), FUZZ_ARGS (extra libFuzzer flags),
# FUZZ_ONLY (a subset of harness names).

FUZZ_CC      ?= clang
FUZZ_CXX     ?= clang++
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 10
FUZZ_ARGS    ?=
FUZZ_ONLY    ?=
# The system packages `make fuzz` needs beyond .ci/apt-packages.txt (make test does not).
FUZZ_APT_PKGS := clang
# UBSan reports are fatal (-fno-sanitize-recover): libFuzzer then keeps the input.
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=undefined \
                -fno-omit-frame-pointer
FUZZ_CXXFLAGS := -O1 -g -std=c++17 -ffp-contract=off -frounding-math -pthread \
                 -Iinclude -Ilib -DPCCD_BUILDING -Wno-unused-command-line-argument \
                 -fsanitize=fuzzer-no-link $(FUZZ_SAN)

FUZZ_OBJS    := $(patsubst lib/%.cpp,$(FUZZ_BUILD)/lib/%.o,$(SRCS))
FUZZ_C       := $(sort $(wildcard tests/fuzz/fuzz_*.c))
FUZZ_PY      := $(sort $(wildcard tests/fuzz/fuzz_*.py))
FUZZ_TARGETS := $(patsubst tests/fuzz/%.c,$(FUZZ_BUILD)/%,$(FUZZ_C))

.PHONY: fuzz fuzz-deps fuzz-build fuzz-run

fuzz-deps: deps
	@missing=""; for p in $(FUZZ_APT_PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then echo "installing:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "missing system packages:$$missing (run as root or install them)"; exit 1; fi; fi

$(FUZZ_BUILD)/lib/%.o: lib/%.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(FUZZ_CXXFLAGS) -MMD -MP -c $< -o $@

# A harness: C99 against the public header only (compiled by clang), linked by clang++
# (the C++ sanitizer runtimes) with the sanitized objects.
$(FUZZ_BUILD)/%.ho: tests/fuzz/%.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) -std=c99 -O1 -g -Wall -Wextra -Werror -Iinclude -fsanitize=fuzzer $(FUZZ_SAN) \
	  -MMD -MP -MF $@.d -MT $@ -c $< -o $@

$(FUZZ_TARGETS): $(FUZZ_BUILD)/%: $(FUZZ_BUILD)/%.ho $(FUZZ_OBJS)
	$(FUZZ_CXX) -fsanitize=fuzzer $(FUZZ_SAN) -o $@ $< $(FUZZ_OBJS) -lgmpxx -lgmp -lm -pthread

-include $(FUZZ_OBJS:.o=.d) $(addsuffix .ho.d,$(FUZZ_TARGETS))

fuzz-build: $(FUZZ_TARGETS)

fuzz: fuzz-deps
	@$(MAKE) --no-print-directory $(PAR) fuzz-build lib venv
	@$(MAKE) --no-print-directory fuzz-run

fuzz-run:
	$(VENV)/bin/pip install -q -r tests/fuzz/requirements.txt
	$(VPY) tests/fuzz/run_fuzz.py --build $(FUZZ_BUILD) --seconds $(FUZZ_SECONDS) \
	  --python $(VPY) $(if $(FUZZ_ONLY),--only $(FUZZ_ONLY)) $(if $(FUZZ_ARGS),--args "$(FUZZ_ARGS)")
