"""Chunks sized by measured cost, for polyccd.apps.distributed.map_chunks (issue 35).

A task costs a fixed ~2 ms on an embedded cluster (scheduling, pickling, a round trip:
tests/bench/bench_distributed.py) on top of its work. Chunks that carry much more work
than that hide the cost; chunks that are too big leave workers idle at the end. The
cost of an item is not known in advance (an Index query, a corpus case: from
microseconds to seconds), so it is measured: the first chunks are small probes, each
timed on its worker (timed_chunk); every later chunk is sized from the cost per item
measured so far to carry about TARGET_SECONDS of work, and at most a share of the items
left that keeps every worker busy to the end. Only the cutting depends on the timings:
each answer is its item's, so the answers never do.
"""
import time

# Work per task: 50 times the ~2 ms a task costs, so the fixed cost stays near 2 %.
TARGET_SECONDS = 0.1
# The probes: 2 per worker, each at most 1/64 of a worker's share of the batch.
PROBE_SHARE = 64


def timed_chunk(fn, chunk, *shared):
    """(fn(chunk, *shared), the seconds it took), run on a worker."""
    start = time.perf_counter()
    answers = fn(chunk, *shared)
    return answers, time.perf_counter() - start


class Sizer:
    """Cuts items [0, n) into consecutive chunks for `workers` workers: take() gives the
    next (start, end) or None when none is left, record() reports a finished chunk."""

    def __init__(self, n, workers, fixed=None):
        self.n, self.workers, self.fixed = n, max(1, workers), fixed
        self.start = 0
        self.items = 0          # items of the finished chunks
        self.seconds = 0.0      # their time on the workers
        self.probe = max(1, n // (PROBE_SHARE * self.workers))

    def in_flight(self):
        """How many chunks to keep submitted: all at once for fixed sizes; else two per
        worker (one running, one waiting), so a new size can use the latest timings."""
        return self.n if self.fixed else 2 * self.workers

    def record(self, count, seconds):
        self.items += count
        self.seconds += seconds

    def size(self):
        left = self.n - self.start
        if self.fixed:
            return self.fixed
        if self.items == 0:
            return self.probe
        per_item = self.seconds / self.items
        wanted = left if per_item <= 0 else round(TARGET_SECONDS / per_item)
        # The end: every worker gets a share of what is left, in chunks of at least an
        # eighth of the target (shorter ones would be mostly fixed cost).
        tail = max(-(-left // (2 * self.workers)), wanted // 8)
        return max(1, min(wanted, tail))

    def take(self):
        if self.start >= self.n:
            return None
        end = min(self.n, self.start + self.size())
        chunk, self.start = (self.start, end), end
        return chunk
