"""polyccd.apps._chunks.Sizer, the cutting of map_chunks' batches by measured cost
(issue 35), driven here by simulated workers with a known cost per item: the chunks
cover every item once, in order; after the probes each carries about TARGET_SECONDS
of work; the last ones shrink so that every worker has a share; fixed sizes stay
fixed. (The answers' order and equality on a real cluster: tests/test_distributed.py.)
"""
import pytest

from polyccd.apps._chunks import PROBE_SHARE, TARGET_SECONDS, Sizer


def simulate(n, workers, per_item, fixed=None):
    """The chunks a Sizer cuts while `workers` workers finish them in order of
    submission, each item costing per_item seconds."""
    sizer = Sizer(n, workers, fixed)
    queue, chunks = [], []
    for _ in range(sizer.in_flight()):
        c = sizer.take()
        if c is None:
            break
        queue.append(c)
    while queue:
        a, b = queue.pop(0)
        chunks.append((a, b))
        sizer.record(b - a, (b - a) * per_item)
        c = sizer.take()
        if c is not None:
            queue.append(c)
    return sorted(chunks)


def covers(chunks, n):
    return [x for a, b in chunks for x in range(a, b)] == list(range(n))


@pytest.mark.parametrize("n,workers,per_item", [
    (10_000, 2, 1e-4), (10_000, 2, 0.5), (229, 2, 5e-3), (1, 4, 1e-3), (37, 16, 1e-6),
    (200_000, 3, 2e-6)])
def test_every_item_once_in_order(n, workers, per_item):
    chunks = simulate(n, workers, per_item)
    assert covers(chunks, n) and all(b > a for a, b in chunks)


def test_cheap_items_are_sized_to_the_target():
    n, workers, per_item = 100_000, 2, 1e-5  # 1 s of work in all, 1e4 items per 0.1 s
    chunks = simulate(n, workers, per_item)
    probe = n // (PROBE_SHARE * workers)
    assert chunks[0] == (0, probe)
    sizes = [b - a for a, b in chunks]
    after_probes = sizes[2 * workers:]
    target = round(TARGET_SECONDS / per_item)
    assert max(after_probes) == target  # no chunk carries more than the target...
    assert sum(s for s in sizes if s == target) > n / 2  # ...and most items go so
    assert len(chunks) <= 25            # not one task per item, nor per probe


def test_the_tail_is_shared_among_the_workers():
    n, workers, per_item = 100_000, 2, 1e-5
    sizes = [b - a for a, b in simulate(n, workers, per_item)]
    target = round(TARGET_SECONDS / per_item)
    assert sizes[-1] < target and sizes[-2] < target  # the end is cut finer...
    assert min(sizes[2 * workers:-1]) >= target // 8  # ...but not into crumbs


def test_expensive_items_go_one_by_one():
    """An item of 0.5 s already exceeds the target: chunks of one (balance first)."""
    sizes = [b - a for a, b in simulate(300, 2, 0.5)]
    assert set(sizes[2 * 2:]) == {1}  # after the probes (300 // 128 = 2 items each)


def test_fixed_sizes_stay_fixed():
    chunks = simulate(103, 2, 1e-3, fixed=10)
    assert [b - a for a, b in chunks] == [10] * 10 + [3]
    assert Sizer(103, 2, 10).in_flight() == 103
