"""Limits that hold inside long exact computations (issue 23, item 1).

Each case is one the audit of issue 23 reproduced: before the work steps counted by cost
(util/work_budget.h, work_cost) these calls ran for minutes before their first check of
the limits. The timing bounds are the issue's (a limit of 1 s ends the call within 2 s,
a cancellation or Ctrl-C within 0.5 s), with the margins stated at each; the cases are
seeded, so the same inputs run every time. tests/cpp/test_work_cost.cpp makes one
polynomial product long on purpose and checks the limit holding inside it.
"""
import json
import random
import subprocess
import sys
import threading
import time
from fractions import Fraction as F

import pytest

import polyccd as P

BUILD = r"""
import random
from fractions import Fraction as F
import polyccd as P


def edge_edge_48(seed=48):
    # Edge a along x at z = 0, edge b along y falling from z = 1 to z = -1 (they cross
    # near t = 1/2), every coordinate of degree 48: its coefficients up from t^1 are
    # fractions of two 30-digit numbers (/ 1000: small perturbations of that motion)
    rng = random.Random(seed)
    def r30():
        return F(rng.randrange(10 ** 29, 10 ** 30) * rng.choice([-1, 1]),
                 rng.randrange(10 ** 29, 10 ** 30) * 1000)
    base = [[-1, 0, 0], [1, 0, 0], [0, -1, 1], [0, 1, 1]]
    points = [[[c] + [r30() for _ in range(48)] for c in p] for p in base]
    for p in points[2:]:
        p[2][1] += -2  # z = 1 - 2t
    return points


def rotation_64(seed=64):
    # a degree-64 rotation whose coefficients are fractions of two 1,200-digit numbers
    # (2,400 digits, 7,970 bits: inside the default input limit of 16,384 bits)
    rng = random.Random(seed)
    big = lambda: rng.randrange(10 ** 1199, 10 ** 1200)
    return P.Motion(rotation=[[F(big(), big()) for _ in range(65)] for _ in range(4)])


def two_balls(motion):
    return [P.Body(P.Spheres([[0, 0, 0]], [1]), name="still"),
            P.Body(P.Spheres([[3, 0, 0]], [1]), motion, name="turning")]
"""
exec(BUILD)


def ends_within(call, seconds, **limits):
    """Runs call(limits) and returns its seconds; it must raise LimitError."""
    start = time.perf_counter()
    with pytest.raises(P.LimitError) as e:
        call(P.Limits(**limits))
    took = time.perf_counter() - start
    assert took < seconds, (took, str(e.value))
    return e.value


def test_degree_48_edge_edge_ends_within_the_limit():
    points = edge_edge_48()
    e = ends_within(lambda lim: P.solve("edge-edge", points, limits=lim), 2.0, max_seconds=1)
    assert "config.max_seconds: the time limit of 1 s was reached" in str(e)
    # A work limit ends it after the same count every time (the count is the input's).
    messages = {str(ends_within(lambda lim: P.solve("edge-edge", points, limits=lim), 30,
                                max_work=2000)).split(" and ")[0] for _ in range(2)}
    assert messages == {"config.max_work: the limit of 2000 work steps was reached (after 2000 work steps"}


def test_long_rotation_scene_index_and_position_end_within_the_limit():
    motion = rotation_64()
    bodies = two_balls(motion)
    ends_within(lambda lim: P.check(bodies, limits=lim), 2.0, max_seconds=1)
    ends_within(lambda lim: P.check(bodies, threads=2, all_contacts=True, limits=lim), 2.0,
                max_seconds=1)
    # Index construction and Motion.position take limits too (they took none: 11.5 s and
    # more than 300 s on the audit's inputs). A fresh motion: the scene above may have
    # kept the first one's derivation.
    ends_within(lambda lim: P.Index(P.Body(bodies[1].shape, rotation_64()), limits=lim),
                2.0, max_seconds=1)
    t = F(1, 2 ** 63000 + 1)  # a time of 63,000 bits: beyond the default input limit
    with pytest.raises(P.LimitError, match=r"^t: a number of 6300\d bits .* exceeds config.max_number_bits"):
        motion.position([1, 2, 3], t, limits=P.Limits())
    # The evaluation at such a time is integer products and, per coordinate, one gcd of
    # 10 million bits (5-6 s, not divisible): under a time limit that gcd is predicted
    # from the product of the same numbers and refused when it would pass the deadline
    # (poly/lowest_terms.h), so every limit holds (it ended 1.3 s late at 1.5 s).
    for seconds in (0.5, 1, 1.5):
        ends_within(lambda lim: motion.position([1, 2, 3], t, limits=lim), seconds + 1.0,
                    max_seconds=seconds, max_number_bits=None)
    # Composition (pccd_motion_compose_cfg): products of two such rotations.
    ends_within(lambda lim: motion.then(rotation_64(seed=65), limits=lim), 2.0, max_seconds=1)
    # Validation: the primitive parts of the components (lcms of 65 denominators of
    # 4,000 bits) are counted by cost, then coprimality is proved modulo a prime.
    ends_within(lambda lim: motion.validate(limits=lim), 30, max_work=1)
    assert motion.validate(limits=P.Limits(max_seconds=60)) is motion
    assert P.Motion.linear([0, 0, 0], [2, 4, 6]).position([1, 1, 1], F(1, 2), limits=P.Limits(max_work=10)) \
        == (2, 3, 4)


def test_cancel_ends_a_long_exact_step_at_once():
    bodies = two_balls(rotation_64())
    cancel = P.Cancel()
    timer = threading.Timer(0.5, cancel.set)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(P.LimitError, match="config.cancel: the call was cancelled"):
        P.check(bodies, limits=P.Limits(cancel=cancel))
    after_set = time.perf_counter() - start - 0.5
    timer.join()
    assert after_set < 0.5, after_set


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_ctrl_c_ends_a_long_exact_step_at_once():
    from test_limits import interrupt_child
    # 0.5 s: inside the motion's preparation by now
    status, line, reacted = interrupt_child(BUILD + "bodies = two_balls(rotation_64())",
                                            "P.check(bodies)", 0.5)
    assert (status, line) == (3, "interrupted")
    assert reacted < 0.5, reacted


def test_command_line_time_limit_covers_reading_the_file(tmp_path):
    """--max-seconds covers reading the file and building its bodies (a 38 MB scene read
    for 63 s under --max-seconds 5): here 300,000 vertices (11 MB) and 0.2 s."""
    n = 300000
    rng = random.Random(3)
    verts = [[rng.randrange(-10 ** 6, 10 ** 6) / 10 ** 6 for _ in range(3)] for _ in range(n)]
    doc = {"format": "polyccd/1", "bodies": [
        {"name": "m", "mesh": {"vertices": verts, "triangles": [[k, k + 1, k + 2] for k in range(n - 2)]}},
        {"name": "b", "spheres": {"centers": [[5, 5, 5]], "radii": [0.1]}}]}
    path = tmp_path / "big.json"
    path.write_text(json.dumps(doc))
    done = subprocess.run([sys.executable, "-m", "polyccd", "check", "--max-seconds", "0.2", str(path)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert done.stderr.startswith(f"polyccd: {path}: config.max_seconds: the time limit of 0.2 s "
                                  "was reached while reading the file (after ")


def test_position_in_integers_is_the_exact_position():
    """Motion.position evaluates in integers and reduces once (lib/motion/rigid_motion.cpp):
    the same point as the formula x = R(r(t)) p + o(t) in Fractions, R(q) = Rn(q) / |q|^2,
    on motions of long random coefficients, and as the composition of two positions for
    a composed motion (its offset b is not zero)."""
    rng = random.Random(23)

    def num(bits):
        return F(rng.randrange(-2 ** bits, 2 ** bits), rng.randrange(1, 2 ** bits))

    def value(c, t):
        return sum(x * t ** i for i, x in enumerate(c))

    def oracle(rot, tr, p, t):
        w, x, y, z = (value(c, t) for c in rot)
        n = w * w + x * x + y * y + z * z
        R = [[w*w + x*x - y*y - z*z, 2 * (x*y - w*z), 2 * (x*z + w*y)],
             [2 * (x*y + w*z), w*w - x*x + y*y - z*z, 2 * (y*z - w*x)],
             [2 * (x*z - w*y), 2 * (y*z + w*x), w*w - x*x - y*y + z*z]]
        return tuple(sum(R[i][j] * p[j] for j in range(3)) / n + value(tr[i], t) for i in range(3))

    for case in range(6):
        bits = (8, 200, 2000)[case % 3]
        rot = [[num(bits) for _ in range(rng.randrange(1, 5))] for _ in range(4)]
        tr = [[num(bits) for _ in range(rng.randrange(0, 5))] for _ in range(3)]
        m = P.Motion(translation=tr, rotation=rot)
        for _ in range(3):
            p, t = [num(bits) for _ in range(3)], F(rng.randrange(0, 2 ** 40), 2 ** 40 - 1)
            if all(value(c, t) == 0 for c in rot):
                continue
            assert m.position(p, t, limits=P.Limits(max_seconds=60)) == oracle(rot, tr, p, t)
        outer = P.Motion(translation=[[num(bits)] for _ in range(3)],
                         rotation=[[num(bits), num(bits)] for _ in range(4)])
        both = m.then(outer)
        p, t = [num(bits) for _ in range(3)], F(rng.randrange(1, 1000), 1000)
        assert both.position(p, t) == outer.position(m.position(p, t), t)


def grid_mesh(n):
    """An n x n grid of unit squares (2 n^2 triangles) on a wavy sheet, as numpy arrays."""
    import numpy as np
    xs, ys = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
    V = np.stack([xs.ravel(), ys.ravel(), np.sin(xs.ravel()) / 10], axis=1)
    i, j = (a.ravel() for a in np.meshgrid(np.arange(n), np.arange(n), indexing="ij"))
    a = i * (n + 1) + j
    F3 = np.concatenate([np.stack([a, a + n + 1, a + 1], 1), np.stack([a + n + 1, a + n + 2, a + 1], 1)])
    return P.Mesh(V, F3)


def test_index_construction_of_a_large_mesh_takes_its_limits():
    # Building an index's hierarchy and range trees over 80,000 triangles scans them
    # about 17 times per structure and took seconds for a million triangles with no
    # check of the limits (a 120 s limit ended 115 s late). Each tree node and each 256
    # lifted primitives are now work steps: a work limit far below the build's count
    # ends it, deterministically; the same build without limits succeeds.
    body = P.Body(grid_mesh(200), motion=P.Motion.linear((0, 0, 0), (1, 0, 0)))
    with pytest.raises(P.LimitError, match=r"config.max_work: the limit of 2000 work steps"):
        P.Index(body, limits=P.Limits(max_work=2000))
    with pytest.raises(P.LimitError, match=r"config.max_seconds"):
        P.Index(P.Body(grid_mesh(200), motion=P.Motion.linear((0, 0, 0), (1, 0, 0))),
                limits=P.Limits(max_seconds=0.01))
    P.Index(body, limits=P.Limits())  # the default limits: built
