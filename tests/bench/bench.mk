# bench_linear: polyccd's C API against Tight Inclusion's C++ in one process
# (tests/bench/bench_linear.cpp). Included by the top Makefile; `make bench-linear` runs it
# alone, `make bench` runs it before the Python benchmarks. Arguments: BENCH_LINEAR_ARGS,
# e.g. make bench-linear BENCH_LINEAR_ARGS="--workloads public --repeat 5 --json b.json".

# The directory holding libpolyccd.so (the only place the bench names it).
PCCD_LIBDIR ?= $(BUILD)
# Tight Inclusion's source (../shared/peers/tight-inclusion/README.md) and Eigen.
TI_DIR      ?= ../shared/peers/tight-inclusion
EIGEN_DIR   ?= /usr/include/eigen3
BENCH_LINEAR_ARGS ?=

BENCH_DIR   := $(BUILD)/bench
# As the peer README builds Tight Inclusion; the bench's own files get the same flags.
BENCH_OPT   := -O3 -march=native -std=c++17 -DNDEBUG
TI_OBJS     := $(patsubst %,$(BENCH_DIR)/ti_%.o,avx ccd interval interval_root_finder)
BENCH_LINEAR_OBJS := $(patsubst %,$(BENCH_DIR)/%.o,bench_linear bench_linear_input \
                       bench_linear_report bench_linear_tail bench_linear_batch)
# The batch hook (bench_linear_batch.cpp) is compiled in once polyccd.h declares the call.
BENCH_BATCH_DEF := $(shell grep -q 'pccd_solve_linear_batch_d' include/polyccd.h && echo -DPCCD_HAVE_LINEAR_BATCH)

.PHONY: bench-linear

$(BENCH_DIR)/ti_%.o: $(TI_DIR)/tight_inclusion/%.cpp | deps
	@mkdir -p $(dir $@)
	$(CXX) $(BENCH_OPT) -I$(TI_DIR) -I$(EIGEN_DIR) -MMD -MP -c $< -o $@

# Our files: warnings on, Tight Inclusion and Eigen as system headers (their warnings
# are not ours); polyccd only through its public header.
$(BENCH_DIR)/%.o: tests/bench/%.cpp | deps
	@mkdir -p $(dir $@)
	$(CXX) $(BENCH_OPT) -Wall -Wextra -Iinclude -isystem $(TI_DIR) -isystem $(EIGEN_DIR) \
	  $(BENCH_BATCH_DEF) -MMD -MP -c $< -o $@

$(BUILD)/bench_linear: $(BENCH_LINEAR_OBJS) $(TI_OBJS) $(PCCD_LIBDIR)/libpolyccd.so
	$(CXX) -o $@ $(BENCH_LINEAR_OBJS) $(TI_OBJS) -L$(PCCD_LIBDIR) -lpolyccd -lgmpxx -lgmp \
	  -Wl,-rpath,$(abspath $(PCCD_LIBDIR)) -pthread

bench-linear: $(BUILD)/bench_linear
	$(BUILD)/bench_linear $(BENCH_LINEAR_ARGS)

# bench_min_distance: pccd_config.min_distance against Tight Inclusion's ms on the public
# set (tests/bench/bench_min_distance.cpp); `make bench` runs it after bench_linear.
BENCH_MD_OBJS := $(patsubst %,$(BENCH_DIR)/%.o,bench_min_distance bench_linear_input)
.PHONY: bench-min-distance
$(BUILD)/bench_min_distance: $(BENCH_MD_OBJS) $(TI_OBJS) $(PCCD_LIBDIR)/libpolyccd.so
	$(CXX) -o $@ $(BENCH_MD_OBJS) $(TI_OBJS) -L$(PCCD_LIBDIR) -lpolyccd -lgmp \
	  -Wl,-rpath,$(abspath $(PCCD_LIBDIR)) -pthread

bench-min-distance: $(BUILD)/bench_min_distance
	$(BUILD)/bench_min_distance $(BENCH_MD_ARGS)

-include $(BENCH_LINEAR_OBJS:.o=.d) $(BENCH_MD_OBJS:.o=.d) $(TI_OBJS:.o=.d)

# bench_adversarial: the broad phases where boxes cannot help, and auto's choice
# (tests/bench/bench_adversarial.py); `make bench` runs it and prints its exponents
# table, `make bench-adversarial` alone. Arguments: BENCH_ADV_ARGS, e.g.
# make bench-adversarial BENCH_ADV_ARGS="--sizes 1k,2k --families slivers".
BENCH_ADV_ARGS ?=
.PHONY: bench-adversarial
bench-adversarial: all
	$(VPY) tests/bench/bench_adversarial.py $(BENCH_ADV_ARGS)
bench: bench-adversarial

# The planning benchmark of the C++ OMPL validators (tests/bench/bench_planning_cpp.py)
# is added to `make bench` by tests/ompl/ompl.mk, only where OMPL's headers are installed.
