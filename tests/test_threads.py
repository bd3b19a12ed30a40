"""Many Python threads solving at once on shared objects give the serial answers (issue
15, item 4; the C side and ThreadSanitizer: tests/c/test_threads.c, `make tsan`).

The bindings release the GIL inside every C call (cffi), so the threads below really
run the library at once. Shared between them: the Mesh / Spheres shapes, the Motions,
the Bodies, one Index and the primitive queries' inputs; every call builds its own
result. The jobs run first one after the other (the expected answers), then on THREADS
threads, each in its own order, ROUNDS times; every answer must equal the serial one.
A second set of shapes, never solved before the threads start, is used in the threaded
run, so the structures a body builds on first use are built while the threads race.
"""
import random
import threading
from fractions import Fraction as F

import polyccd as P

THREADS, ROUNDS, SEED = 6, 1, 20261124


def grid(rng, scale=4):
    return F(rng.randint(-scale, scale), scale)


def world(seed):
    """The same shapes, motions, bodies and queries for the same seed."""
    rng = random.Random(seed)
    cube = P.Mesh([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)],
                  [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                   [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    balls = P.Spheres([[0, 0, 0], [1, 0, 0], [0, 1, 0]], ["1/2", "1/4", "3/8"])
    tet = P.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                  [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    motions = [P.Motion.linear([3, "1/2", "1/2"], [-1, "1/2", "1/2"]),
               P.Motion.screw([0, 0, 1], ["1/2", "1/2", 0], 0, 1, -1),
               P.Motion.axis_rotation([1, 1, 0], [0, 0, "1/2"], -1, 1)]
    queries = [P.Body(shape, m, name=f"q{k}")
               for k, (shape, m) in enumerate([(balls, motions[0]), (tet, motions[1]),
                                               (balls, motions[2]), (cube, motions[0])])]
    stored = P.Body(cube, name="cube")
    prims, hits, misses = [], 0, 0
    while hits + misses < 12:  # random queries near each other: 6 that touch, 6 that do not
        kind = ["vertex-face", "edge-edge", "vertex-edge", "sphere-sphere"][len(prims) % 4]
        n = {"vertex-face": 4, "edge-edge": 4, "vertex-edge": 3, "sphere-sphere": 2}[kind]
        points = [[[grid(rng, 2) for _ in range(rng.randint(1, 3))] for _ in range(3)]
                  for _ in range(n)]
        radii = ["1/2", "3/4"] if kind == "sphere-sphere" else None
        hit = P.solve(kind, points, radii, want_time=False).collides
        if (hits if hit else misses) < 6:
            prims.append((kind, points, radii))
            hits, misses = hits + hit, misses + (not hit)
    return stored, queries, prims


def jobs(stored, queries, prims, index):
    """Every job as a function returning its answer (comparable values)."""
    out = []
    for kind, points, radii in prims:
        out.append(lambda kind=kind, points=points, radii=radii:
                   P.solve(kind, points, radii, time_tolerance="1e-9"))
    for q in queries:
        out.append(lambda q=q: P.check([stored, q], time_tolerance="1e-9", threads=2))
        out.append(lambda q=q: P.check([stored, q], time_tolerance="1e-9", broad_phase="range"))
        out.append(lambda q=q: index.query(q, time_tolerance="1e-9"))
    out.append(lambda: P.check([stored] + queries, time_tolerance="1e-9", all_contacts=True))
    out.append(lambda: tuple(index.query_many(queries, time_tolerance="1e-9", threads=2)))
    return out


def test_threads_share_objects_and_answer_as_serial():
    stored, queries, prims = world(SEED)
    serial = [job() for job in jobs(stored, queries, prims, P.Index(stored))]
    assert sum(1 for r in serial if getattr(r, "collides", True)) >= len(serial) // 4
    fresh_stored, fresh_queries, fresh_prims = world(SEED)  # never solved before
    shared = jobs(fresh_stored, fresh_queries, fresh_prims, P.Index(fresh_stored))
    bad, errors = [], []
    start = threading.Barrier(THREADS)

    def work(t):
        try:
            start.wait()
            for r in range(ROUNDS):
                for i in range(len(shared)):
                    k = (7 * t + 3 * r + i) % len(shared)
                    got = shared[k]()
                    if got != serial[k]:
                        bad.append((t, k))
        except Exception as e:  # reported below, with the thread
            errors.append((t, repr(e)))

    threads = [threading.Thread(target=work, args=(t,)) for t in range(THREADS)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not errors, errors
    assert not bad, f"(thread, job) answers differing from the serial run: {bad[:10]}"


def test_each_thread_sees_its_own_error():
    """The C library's last error is per thread: each thread's exception names its own
    bad value, whatever the other threads failed on meanwhile."""
    seen, start = {}, threading.Barrier(THREADS)

    def work(t):
        start.wait()
        messages = []
        for _ in range(50):
            try:
                P.solve("vertex-vertex", [[[f"bad{t}"], [0], [0]], [[0], [0], [0]]])
            except P.InputError as e:
                messages.append(str(e))
        seen[t] = messages

    threads = [threading.Thread(target=work, args=(t,)) for t in range(THREADS)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for t in range(THREADS):
        assert len(seen[t]) == 50
        assert all(f'"bad{t}" is not a number' in m for m in seen[t]), seen[t][:3]
