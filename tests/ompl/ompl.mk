# The C++ OMPL validators (bindings/ompl/polyccd_ompl.hpp): their test program
# (tests/ompl/test_ompl_validator.cpp) and the planning benchmark's library
# (tests/bench/bench_planning_ompl.cpp), built only where OMPL's headers are installed
# (Debian libompl-dev: /usr/include/ompl-*; the CI machine may not have them). Included
# by the top Makefile: `make check` (and so `make test`) runs `make test-ompl`, which
# without the headers prints "test-ompl: skipped (...)" and succeeds, as it does when the
# robot packages (example-robot-data, yourdfpy) are missing from the venv.

OMPL_INC      := $(firstword $(wildcard /usr/include/ompl-*))
OMPL_SCENE    := $(BUILD)/ompl/panda_scene.txt
OMPL_CXXFLAGS := -std=c++17 -O2 -g -Wall -Wextra -Iinclude -Ibindings/ompl \
                 -isystem $(OMPL_INC) -isystem /usr/include/eigen3
OMPL_LIBS     := -L$(BUILD) -lpolyccd -lompl -pthread -Wl,-rpath,'$$ORIGIN'
OMPL_SKIP     := skipped (no OMPL headers: /usr/include/ompl-* is missing; apt-get install libompl-dev)

BENCH_PLANNING_ARGS ?= --queries 10 --runs 3 --slot

.PHONY: test-ompl bench-planning-ompl

# `make bench` runs the planning benchmark too (tests/bench/bench_planning_cpp.py: the
# C++ validators against plainmp and polyccd.ompl; plainmp when PLAINMP_SITE or the venv
# has it); `make bench-planning-ompl` alone, arguments in BENCH_PLANNING_ARGS.
bench: bench-planning-ompl

ifeq ($(OMPL_INC),)
test-ompl:
	@echo "test-ompl: $(OMPL_SKIP)"
bench-planning-ompl:
	@echo "bench-planning-ompl: $(OMPL_SKIP)"
else
$(BUILD)/bench/libbench_planning_ompl.so: tests/bench/bench_planning_ompl.cpp $(LIB)
	@mkdir -p $(dir $@)
	$(CXX) $(OMPL_CXXFLAGS) -DNDEBUG -fPIC -shared -MMD -MP -MF $@.d -MT $@ -o $@ $< \
	  -L$(BUILD) -lpolyccd -lompl -Wl,-rpath,$(abspath $(BUILD))

-include $(BUILD)/bench/libbench_planning_ompl.so.d

bench-planning-ompl: $(BUILD)/bench/libbench_planning_ompl.so all
	$(VPY) tests/bench/bench_planning_cpp.py $(BENCH_PLANNING_ARGS)

$(BUILD)/test_ompl_validator: tests/ompl/test_ompl_validator.cpp $(LIB)
	$(CXX) $(OMPL_CXXFLAGS) -MMD -MP -MF $@.d -MT $@ -o $@ $< $(OMPL_LIBS)

-include $(BUILD)/test_ompl_validator.d

# The scene file (the Panda, the example's plates and query) is written again on every
# run by the venv's polyccd (tests/ompl/scene_file.py: exit 3 = the robot packages are
# missing, skipped).
test-ompl: $(BUILD)/test_ompl_validator venv
	@mkdir -p $(BUILD)/ompl
	@rc=0; $(VPY) tests/ompl/scene_file.py $(OMPL_SCENE) || rc=$$?; \
	if [ $$rc = 3 ]; then echo "test-ompl: skipped (no robot packages in the venv)"; \
	elif [ $$rc != 0 ]; then exit $$rc; \
	else echo "== $(BUILD)/test_ompl_validator $(OMPL_SCENE)"; $(BUILD)/test_ompl_validator $(OMPL_SCENE); fi
endif
