"""polyccd.apps.distributed: batches of polyccd work mapped over a dask.distributed cluster. In short::

    import polyccd.apps.distributed as pd
    with pd.cluster(workers=2) as client:            # an embedded LocalCluster
        for r in pd.index_map(body, queries, client=client):
            ...                                        # SceneResults, in query order

Every map splits its items into chunks, submits one task per chunk and yields the
answers in the order of the items as they stream back (a tqdm bar on stderr when both
stdout and stderr are terminals, see _progress), each equal to the serial
call's answer: the workers run the same library calls on the same exact inputs.

Shipping: the C handles cannot be pickled, so bodies, motions and Index objects travel
as their exact inputs (Mesh / Spheres / Motion / Body pickle that way, see
docs/python.md) and are rebuilt on arrival. A body shared by every task (the Index's
stored body) is scattered to every worker once per client, kept for later calls
(client.scatter(broadcast=True), _broadcast_body), and each worker process builds its
Index from it once, lazily on its first task, then keeps it for every later call with
a body of the same exact inputs (_cached_index, by _body_token). Files (CSV query
sets, scene and query files, corpus cases) travel as paths: the workers must see the
same files (a shared file system).

A worker that dies mid-run loses nothing: the results not yet received are computed
again by the scheduler on the remaining or restarted workers (every worker of an
embedded cluster has a nanny that restarts it), and the broadcast body has a copy on
every worker. Needs dask.distributed (`pip install "polyccd[dask]"` adds it to an installed
polyccd); `import polyccd` never imports this module.
"""
import collections
import dataclasses
import functools
import hashlib
import os
import pickle
import threading
from contextlib import contextmanager

from .. import Body, Index, InputError, InternalError
from ._chunks import Sizer, timed_chunk
from ._progress import bar

try:
    import dask.config as _dask_config
    import distributed as _distributed
except ImportError as _e:  # pragma: no cover - depends on the install
    raise ImportError("polyccd.apps.distributed needs dask.distributed: pip install "
                      "'polyccd[dask]' (adds the dask extra's packages to this installed "
                      "polyccd) or 'dask[distributed]'") from _e

__all__ = ["cluster", "map_chunks", "index_map", "check_map", "corpus_map", "queries_map"]


LOOPBACK = "127.0.0.1"  # the embedded cluster's only interface (cluster())

# Dask settings of the embedded cluster, which cut the fixed cost of a task (issue 35;
# tests/bench/bench_distributed.py, docs/distributed.md): CPU time of all the cluster's
# processes per one-item task doing nothing, 1 worker, 300 tasks, 2-core machine at
# load 9: 3.2-3.8 ms with dask's defaults, 1.2-2.4 ms with these.
#  - worker-saturation inf: the scheduler sends every ready task to the workers at once
#    instead of queuing it until a worker's thread is free (one round trip per task);
#    the tasks of a map are even chunks, and work stealing still moves queued ones.
#  - no statistical profiler (a thread sampling every task's stack every 10 ms) and no
#    GIL-contention sampling (every 1 ms, with gilknocker) on the workers: data for the
#    dashboard, which the embedded cluster does not show unless asked.
#  - fewer wake-ups of every event loop while the workers compute: the loop-health tick
#    (20 ms: it only logs a blocked loop), the system monitor (500 ms: psutil counters
#    for the dashboard) and the worker's memory monitor (100 ms: spilling and pausing,
#    which a second still catches before a batch grows far). CPU of an idle 2-worker
#    cluster per second of wall time (2-core machine, load 3.5; docs/distributed.md):
#    processes 50-74 ms -> 10-16 ms, threads 24 ms -> 4 ms. That time is taken from
#    the workers' cores while they compute.
EMBEDDED_CONFIG = {"distributed.scheduler.worker-saturation": float("inf"),
                   "distributed.worker.profile.enabled": False,
                   "distributed.admin.system-monitor.gil.enabled": False,
                   "distributed.admin.tick.interval": "1s",
                   "distributed.admin.system-monitor.interval": "2s",
                   "distributed.worker.memory.monitor-interval": "1s"}


K_RETRIES = 3  # map_chunks: times a chunk cancelled by a lost shared copy is sent again


@contextmanager
def cluster(client=None, *, scheduler=None, workers=None, threads_per_worker=1, dashboard=False,
            processes=True):
    """A dask.distributed Client for the maps, closed on exit when made here.

    client: used as it is (not closed). scheduler: the address of a running scheduler
    ("tcp://host:8786"); workers then means: wait until that many workers are
    connected. Neither: an embedded LocalCluster of `workers` workers (default
    os.cpu_count()) with threads_per_worker threads each: worker processes, each with a
    nanny, or with processes=False worker threads in this process (no pickling, no
    copies, no processes beside this one: the choice for work inside the library,
    which releases the GIL, docs/distributed.md). Processes listen on 127.0.0.1 only
    (dask's dashboard and endpoints take no authentication: issue 23 found the
    dashboard on 0.0.0.0); threads talk in memory (inproc://) and listen on nothing
    but the HTTP server, on 127.0.0.1. No dashboard unless dashboard=True (then on
    127.0.0.1, a free port); without one the cluster runs with EMBEDDED_CONFIG (a
    lower cost per task)."""
    if client is not None:
        yield client
        return
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 1):
        raise InputError(f"workers: expected an integer >= 1, got {workers!r}")
    if not isinstance(processes, bool):
        raise InputError(f"processes: expected True or False, got {processes!r}")
    if scheduler is not None:
        with _distributed.Client(scheduler) as c:
            if workers:
                c.wait_for_workers(workers)
            yield c
        return
    n = workers or os.cpu_count() or 1
    # The scheduler and the workers read these settings when they are made (the
    # threads here, in LocalCluster()); each nanny hands its worker (the first, and one
    # restarted after a crash) the config it was given.
    quiet = {} if dashboard else EMBEDDED_CONFIG
    # processes: tcp:// on loopback, a nanny per worker (config: see above); threads:
    # inproc:// (no address to bind), Worker objects that take no config argument.
    where = {"host": LOOPBACK, "config": quiet} if processes else {}
    with _dask_config.set(quiet):
        local = _distributed.LocalCluster(n_workers=n, threads_per_worker=threads_per_worker,
                                          processes=processes,
                                          # the scheduler's HTTP server (health, and the
                                          # dashboard when asked) on loopback, a free port
                                          dashboard_address=f"{LOOPBACK}:0",
                                          scheduler_kwargs={"dashboard": bool(dashboard)},
                                          worker_dashboard_address=None,
                                          silence_logs=40, **where)
    with local, _distributed.Client(local) as c:
        yield c


def _client(client):
    if client is None:
        try:
            return _distributed.get_client()
        except ValueError:
            raise InputError("client: no dask.distributed Client given and none is active "
                             "(use `with polyccd.apps.distributed.cluster() as client:`)") from None
    return client


def _fixed_size(chunk_size):
    """chunk_size as given (an integer >= 1), or None: sized by measured cost."""
    if chunk_size is not None and (isinstance(chunk_size, bool) or not isinstance(chunk_size, int)
                                   or chunk_size < 1):
        raise InputError(f"chunk_size: expected an integer >= 1, got {chunk_size!r}")
    return chunk_size


def map_chunks(fn, items, *shared, client=None, chunk_size=None, progress=None,
               desc="polyccd", unit="it", rescatter=None):
    """Yields ``fn(chunk, *shared)`` item by item, in the order of items: items are cut into
    chunks (lists), fn returns one answer per item of its chunk. chunk_size: items per
    chunk, or None: sized by the cost per item measured on the workers (_chunks.Sizer:
    small probes first, then chunks of about 0.1 s of work). shared: objects every task
    needs, scattered once to every worker (fn gets them as they were); a Future is
    passed as it is. fn must be importable by the workers (a module-level function).
    A chunk cancelled because a worker that held the only copy of a shared object died
    (dask's memory manager keeps fewer copies than a broadcast made) is sent again with
    the shared objects scattered again: rescatter() gives the Futures given in shared
    anew (index_map: its body), the other objects are scattered from shared; at most
    K_RETRIES times a chunk, then an InternalError."""
    client = _client(client)
    items = list(items)
    workers = len(client.scheduler_info().get("workers", {}))
    sizer = Sizer(len(items), workers, _fixed_size(chunk_size))
    # One future per object (a list or dict given to scatter would be split up); a
    # future given in shared (index_map's body, kept across calls) is passed as it is.
    def place(fresh=None):
        return [(fresh.pop(0) if fresh else s) if isinstance(s, _distributed.Future)
                else client.scatter([s], broadcast=True, hash=False)[0] for s in shared]

    scattered = place()
    retries = {}  # chunk -> times sent again
    task = functools.partial(timed_chunk, fn)
    bounds, live = [], {}  # chunk k's (start, end); future key -> (k, future)
    running = _distributed.as_completed(loop=client.loop, with_results=True)

    def submit(count):
        new = []
        while len(new) < count and (b := sizer.take()) is not None:
            new.append(b)
        if new:  # one client.map: one message for the whole wave
            futures = client.map(task, [items[a:b] for a, b in new],
                                 *[[s] * len(new) for s in scattered], pure=False)
            for f, b in zip(futures, new):
                live[f.key] = (len(bounds), f)
                bounds.append(b)
                running.add(f)

    done, next_chunk = {}, 0
    progress_bar = bar(len(items), desc, unit, progress)
    try:
        submit(sizer.in_flight())
        for batch in running.batches():  # what finished since the last: one round trip
            for future, result in batch:
                k, _ = live.pop(future.key)
                a, b = bounds[k]
                if isinstance(result, BaseException):  # cancelled: a shared copy was lost
                    retries[k] = retries.get(k, 0) + 1
                    if retries[k] > K_RETRIES:
                        raise InternalError(f"{fn.__name__}: chunk {k} (items {a}..{b - 1}) was "
                                            f"cancelled {retries[k]} times: {result!r}")
                    if any(f.status != "finished" for f in scattered):  # once per loss
                        scattered = place(list(rescatter()) if rescatter else None)
                    again = client.submit(task, items[a:b], *scattered, pure=False)
                    live[again.key] = (k, again)
                    running.add(again)
                    continue
                answers, seconds = result
                if len(answers) != b - a:
                    raise InputError(f"{fn.__name__}: {len(answers)} answers for a chunk of "
                                     f"{b - a}")
                sizer.record(b - a, seconds)
                done[k] = answers
                progress_bar.update(len(answers))
            submit(len(batch))  # as many as finished: the workers keep their queue
            while next_chunk in done:
                yield from done.pop(next_chunk)
                next_chunk += 1
    finally:  # stopped early (an error, a consumer that stops): drop the rest
        progress_bar.close()
        pending = [f for _, f in live.values() if not f.done()]
        if pending and client.status == "running":
            client.cancel(pending)
        del live, running, scattered  # released by the scheduler when no future refers to them


# ------------------------------------------------------------------- on-line index ---

_INDEXES = {}  # per worker process: token -> Index (a few, the latest)
_INDEX_LOCK = threading.Lock()
_BUILDS = collections.Counter()  # token -> Index objects built in this process (tests read it)
_SCATTERED = {}  # the caller's side: (client id, token) -> broadcast body (a few, the latest)
_SCATTER_LOCK = threading.Lock()


def _body_token(body):
    """The name of a body's exact inputs: the SHA-256 of its pickle (shape, motion and
    name as their exact inputs, docs/python.md). Equal inputs give the same token in
    every call, so the workers' Index of the body (_cached_index) and its broadcast
    copy (_broadcast_body) serve every later index_map of it; different inputs never
    share one."""
    return hashlib.sha256(pickle.dumps(body, protocol=5)).hexdigest()


def _broadcast_body(client, token, body):
    """The future of body scattered to every worker of client, made on the first
    index_map of this body and kept for the next ones (while its data is held: a
    future whose copies were all lost is made again)."""
    key = (client.id, token)
    with _SCATTER_LOCK:
        future = _SCATTERED.get(key)
        if future is None or future.status != "finished":
            while len(_SCATTERED) >= 4:
                _SCATTERED.pop(next(iter(_SCATTERED)))
            future = _SCATTERED[key] = client.scatter([body], broadcast=True, hash=False)[0]
        return future


def _kept_going(place, fn, *args):
    """fn(*args), or the error of this one item (returned, not raised, so that the other
    items of its chunk and of the batch still get their answers): an InputError (or
    LimitError) with `place` in front, anything else as an InternalError naming it."""
    try:
        return fn(*args)
    except InputError as e:
        return type(e)(f"{place}: {e}" if place else str(e))
    except Exception as e:  # a bug: reported for this item, the batch goes on
        return InternalError(f"{place + ': ' if place else ''}{type(e).__name__}: {e}")


def _cached_index(token, body):
    """The Index of body for this token, built once per process (the first task of a
    worker builds it; the others of any thread of that worker reuse it)."""
    with _INDEX_LOCK:
        ix = _INDEXES.get(token)
        if ix is None:
            while len(_INDEXES) >= 4:
                _INDEXES.pop(next(iter(_INDEXES)))
            ix = _INDEXES[token] = Index(body)
            _BUILDS[token] += 1
        return ix


def _index_chunk(chunk, body, token, options):
    """Index.query_many of the chunk of (k, query) (one C call; equal to Index.query of
    each). When it fails, each query is checked on its own, so a bad query gives its
    own error, named by its place in the whole batch (queries[k]), and the others their
    answers."""
    ix = _cached_index(token, body)
    try:
        return ix.query_many([q for _, q in chunk], **options)
    except InputError:
        return [_kept_going(f"queries[{k}]", lambda q=q: ix.query(q, **options)) for k, q in chunk]


def index_map(index, queries, *, client=None, chunk_size=None, progress=None, **options):
    """Yields ``index.query(q, **options)`` for every query Body, in order, computed on the
    cluster (identical SceneResults, with their bodies attached again here).

    index: a polyccd.Index or the Body to index (each worker builds its own Index once,
    and keeps it for later calls with a body of the same exact inputs: the body is sent
    to the workers once per client, not once per call).
    queries: Body objects, or (shape, motion) / (shape, motion, name) tuples (the
    "(body, motion) pairs" of a batch). options: the keywords of Index.query. A query
    that fails yields its InputError (returned, not raised) naming it "queries[k]: ..."
    by its place in `queries`; the other queries get their answers."""
    body = index.body if isinstance(index, Index) else index
    if not isinstance(body, Body):
        raise InputError(f"index: expected a polyccd.Index or polyccd.Body, got {type(index).__name__}")
    queries = [q if isinstance(q, Body) else Body(*q) for q in queries]
    client = _client(client)
    token = _body_token(body)
    shared = _broadcast_body(client, token, body)
    answers = map_chunks(_index_chunk, list(enumerate(queries)), shared, token, options,
                         client=client, chunk_size=chunk_size, progress=progress,
                         desc="index queries", unit="query",
                         rescatter=lambda: [_broadcast_body(client, token, body)])
    for q, r in zip(queries, answers):
        if not isinstance(r, Exception):
            object.__setattr__(r, "bodies", (body, q))
        yield r


# ---------------------------------------------------------------------------- files ---

def _files(paths):
    """(shown, absolute) for each path: a worker of a separately started cluster runs in
    its own directory, so it opens the absolute path; messages and reports show the path
    as the caller gave it (the serial run's output)."""
    return [(str(p), os.path.abspath(p)) for p in paths]


def _as_given(text, shown, real):
    return text.replace(real, shown)


def _check_chunk(files, threads, limits=None):
    from ._corpus import read_case, solve_case, solve_scene_case
    def solve(real):
        what, case = read_case(real)
        return (solve_scene_case(case, limits=limits, threads=threads) if what == "scene"
                else solve_case(case, limits))
    out = [_kept_going("", solve, real) for _, real in files]
    return [type(r)(_as_given(str(r), shown, real)) if isinstance(r, Exception) else r
            for r, (shown, real) in zip(out, files)]


def check_map(paths, *, threads=1, client=None, chunk_size=1, progress=None, limits=None):
    """Yields, for each scene or query file, what `polyccd check FILE` computes: the
    SceneResult or Result, or the InputError of a bad file (returned, not raised; an
    InternalError for a bug met on one file: the other files still get their answers).
    limits: a polyccd.Limits without a Cancel (each worker applies it to each file)."""
    return map_chunks(_check_chunk, _files(paths), threads, limits, client=client,
                      chunk_size=chunk_size, progress=progress, desc="check", unit="file")


def _corpus_chunk(files):
    from ._corpus import check_case
    out = [_kept_going(shown, check_case, real) for shown, real in files]
    return [type(r)(_as_given(str(r), shown, real)) if isinstance(r, Exception)
            else [_as_given(reason, shown, real) for reason in r]
            for r, (shown, real) in zip(out, files)]


def corpus_map(paths, *, client=None, chunk_size=None, progress=None):
    """Yields check_case(path) (the reasons a corpus case fails; empty: it passes) for
    every case file, in order; an error met on one case is yielded as "PATH: ..." in
    its place (returned, not raised)."""
    return map_chunks(_corpus_chunk, _files(paths), client=client,
                      chunk_size=chunk_size, progress=progress, desc="corpus", unit="case")


def _queries_chunk(files, kind):
    from ._queries import run_file
    out = [_kept_going(shown, run_file, real, kind) for shown, real in files]
    return [type(r)(_as_given(str(r), shown, real)) if isinstance(r, Exception)
            else dataclasses.replace(r, file=shown) for r, (shown, real) in zip(out, files)]


def queries_map(paths, kind=None, *, client=None, chunk_size=1, progress=None):
    """Yields run_file(path, kind) (a FileReport: counts against the truth column, the
    time per query measured on the worker) for every CSV file, in order, or the
    InputError of a bad file (returned, not raised)."""
    return map_chunks(_queries_chunk, _files(paths), kind, client=client,
                      chunk_size=chunk_size, progress=progress, desc="queries", unit="file")
