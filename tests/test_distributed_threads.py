"""polyccd.apps.distributed on an embedded cluster of worker threads
(cluster(processes=False), issue 35): the maps give the serial answers, in order, with
the work run by two worker threads at once (polyccd releases the GIL in its C calls);
the cluster talks in memory (inproc://) and binds no network address but its HTTP
server on 127.0.0.1; the settings that cut the cost of a task reach its scheduler and
workers, as they reach those of the process cluster (tests/test_distributed.py)."""
import threading
import time

import numpy as np
import pytest

import polyccd
from polyccd import Index

pytest.importorskip("distributed")
import polyccd.apps.distributed as pd  # noqa: E402
from polyccd.apps._corpus import check_case, files_under  # noqa: E402
from test_distributed import CORPUS, PLATE, query_bodies  # noqa: E402


@pytest.fixture(scope="module")
def client():
    with pd.cluster(workers=2, processes=False) as c:
        c.wait_for_workers(2)
        yield c


def steps(n, seed):
    """n random vertex-face steps (the benchmark's kind of batch)."""
    rng = np.random.default_rng(seed)
    t0 = rng.uniform(-1, 1, (n, 4, 3))
    return t0, t0 + rng.uniform(-1, 1, (n, 4, 3)) * 10 ** rng.uniform(-3, 0, (n, 1, 1))


SEEN = []  # (worker thread, start, end) of every call of solve_slices in this process


def solve_slices(chunk, t0, t1):
    """Per (a, b): which queries of the slice collide, and the bounds of their times."""
    out = []
    for a, b in chunk:
        start = time.perf_counter()
        r = polyccd.solve_linear_many("vertex-face", t0[a:b], t1[a:b])
        SEEN.append((threading.get_ident(), start, time.perf_counter()))
        hit = r.collides
        out.append((hit.tolist(), r.lo[hit].tolist(), r.hi[hit].tolist()))
    return out


def test_slices_equal_serial_on_two_threads_at_once(client):
    t0, t1 = steps(40_000, 3)
    slices = [(a, a + 2_000) for a in range(0, 40_000, 2_000)]
    serial = solve_slices(slices, t0, t1)
    SEEN.clear()
    got = list(pd.map_chunks(solve_slices, slices, t0, t1, client=client, chunk_size=1,
                             progress=False))
    assert got == serial and any(any(c) for c, _, _ in got)
    assert len({thread for thread, _, _ in SEEN}) == 2  # both worker threads took tasks
    assert threading.get_ident() not in {thread for thread, _, _ in SEEN}


def test_the_gil_is_released_in_the_call(client):
    """While one thread is inside solve_linear_many, another runs Python: the longest
    pause of a thread counting in a loop is far below the call's length (a call that
    held the GIL would stop it for all of it). The switch interval (5 ms) bounds the
    pauses that Python's own parts of the call can cause."""
    t0, t1 = steps(300_000, 4)
    stop, gaps = [], []

    def count():
        last = time.perf_counter()
        while not stop:
            now = time.perf_counter()
            gaps.append(now - last)
            last = now
    th = threading.Thread(target=count)
    th.start()
    start = time.perf_counter()
    polyccd.solve_linear_many("vertex-face", t0, t1)
    call = time.perf_counter() - start
    stop.append(True)
    th.join()
    assert call > 0.04, call  # long enough to tell (about 0.1 s here)
    assert max(gaps) < call / 2, (max(gaps), call)


def test_index_and_corpus_maps_equal_serial(client):
    queries = query_bodies(2_000)
    assert list(pd.index_map(PLATE, queries, client=client)) == Index(PLATE).query_many(queries)
    files = files_under([CORPUS / "vertex-face"], "*.json")
    assert list(pd.corpus_map(files, client=client)) == [check_case(p) for p in files]


def test_it_binds_only_its_http_server_on_loopback(client):
    info = client.scheduler_info()
    assert client.scheduler.address.startswith("inproc://")
    assert info["workers"] and all(w.startswith("inproc://") for w in info["workers"])
    socks = client.run_on_scheduler(lambda dask_scheduler: [
        s.getsockname()[0] for s in dask_scheduler.http_server._sockets.values()])
    assert socks and set(socks) == {"127.0.0.1"}


def intervals(server):
    """ms between the wake-ups that EMBEDDED_CONFIG slows down (None: not running)."""
    pcs = server.periodic_callbacks
    return {k: pcs[k].callback_time if k in pcs else None
            for k in ("tick", "monitor", "memory_monitor", "profile")}


def test_the_settings_reach_the_scheduler_and_the_workers(client):
    got = client.run(lambda dask_worker: intervals(dask_worker))
    assert list(got.values()) == [{"tick": 1000, "monitor": 2000, "memory_monitor": 1000,
                                   "profile": None}] * 2
    on_scheduler = client.run_on_scheduler(
        lambda dask_scheduler: (intervals(dask_scheduler), dask_scheduler.WORKER_SATURATION))
    assert on_scheduler == ({"tick": 1000, "monitor": 2000, "memory_monitor": None,
                             "profile": None}, float("inf"))


def test_processes_must_be_a_bool():
    with pytest.raises(polyccd.InputError, match="processes: expected True or False, got 'no'"):
        with pd.cluster(workers=1, processes="no"):
            pass
