"""Work limits, the input limit and Ctrl-C from Python (issue 15; polyccd.Limits, polyccd.Cancel).

The library checks the limits (tests/c/test_limits.c covers the C side); these tests
check what Python users get: LimitError with the library's message, answers equal to
the unlimited ones, a cancellation from another thread, no GIL held during a long
check, and Ctrl-C (a real SIGINT to a child process) ending a long check at once.
"""
import os
import signal
import subprocess
import sys
import threading
import time
from fractions import Fraction as F

import pytest

import polyccd as P

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rows(n, x0=0):
    """n balls at x = x0 + k / 2 of radius n / 4 + 1: each reaches a whole parallel row."""
    return P.Spheres([[x0 + F(k, 2), 0, 0] for k in range(n)], [F(n, 4) + 1] * n)


def rows_scene(n):
    """Two rows of n balls, one sliding through the other: n^2 touching ball pairs with
    all_contacts (tests/c/test_limits.c builds the same)."""
    return [P.Body(rows(n), name="a"),
            P.Body(rows(n, F(1, 4)), P.Motion.linear([0, n, 0], [0, -n, 0]), name="b")]


def test_bad_limits_name_the_field():
    for kw, word in [({"max_seconds": -1}, "limits.max_seconds"),
                     ({"max_seconds": float("nan")}, "limits.max_seconds"),
                     ({"max_work": 0}, "limits.max_work"),
                     ({"max_work": 1.5}, "limits.max_work"),
                     ({"max_number_bits": True}, "limits.max_number_bits"),
                     ({"cancel": 1}, "limits.cancel")]:
        with pytest.raises(P.InputError, match=word):
            P.Limits(**kw)
    with pytest.raises(P.InputError, match="limits: expected a polyccd.Limits"):
        P.check(rows_scene(2), limits={"max_work": 3})


def test_input_limit_is_checked_up_front_and_can_be_raised():
    # Ball a (radius 1e-5000, 16,611 bits as a fraction) at the origin, ball b of radius 1
    # from x = 3 to x = 0: the first contact is when 3 - 3t = 1 + 1e-5000.
    ra = F(1, 10 ** 5000)
    points = [[[0], [0], [0]], [[3, -3], [0], [0]]]
    with pytest.raises(P.LimitError, match=r"^radii\[0\]: a number of 16611 bits .* exceeds "
                                           r"config.max_number_bits = 16384"):
        P.solve("sphere-sphere", points, [ra, 1])
    r = P.solve("sphere-sphere", points, [ra, 1], limits=P.Limits(max_number_bits=None))
    assert r.collides and r.first_contact.exact == (2 - ra) / 3
    r2 = P.solve("sphere-sphere", points, [ra, 1], limits=P.Limits(max_number_bits=16611))
    assert r2 == r
    # Scenes name the body and the motion.
    big = P.Motion.linear([ra, 0, 0], [0, 0, 0])
    with pytest.raises(P.LimitError, match=r"bodies\[1\]\.motion\.translation\[0\]\[0\]"):
        P.check([P.Body(rows(1)), P.Body(rows(1), big)])


def test_work_limit_ends_a_scene_and_never_changes_an_answer():
    bodies = rows_scene(6)
    free = P.check(bodies, all_contacts=True)
    with pytest.raises(P.LimitError, match=r"config.max_work: the limit of 5 work steps was reached "
                                           r"\(after 5 work steps"):
        P.check(bodies, all_contacts=True, limits=P.Limits(max_work=5))
    assert P.check(bodies, all_contacts=True, limits=P.Limits(max_work=10 ** 9)) == free
    # The count is the scene's: the smallest sufficient limit is the same for 1..3 threads.
    def solves(w, threads):
        try:
            P.check(bodies, all_contacts=True, threads=threads, limits=P.Limits(max_work=w))
            return True
        except P.LimitError:
            return False
    lo, hi = 1, 2
    while not solves(hi, 1):
        lo, hi = hi, hi * 2
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if solves(mid, 1) else (mid, hi)
    assert hi > 10
    for threads in (2, 3):
        assert solves(hi, threads) and not solves(lo, threads)


def test_batches_and_index_queries_take_limits():
    import numpy as np
    t0 = np.zeros((3, 2, 3))
    t1 = np.zeros((3, 2, 3))
    t0[:, 0, 0] = 1
    cancel = P.Cancel()
    cancel.set()
    assert cancel.is_set
    with pytest.raises(P.LimitError, match="config.cancel: the call was cancelled"):
        P.solve_linear_many("vertex-vertex", t0, t1, limits=P.Limits(cancel=cancel))
    cancel.reset()
    assert not cancel.is_set
    got = P.solve_linear_many("vertex-vertex", t0, t1, limits=P.Limits(cancel=cancel))
    assert got.collides.all()
    a, b = rows_scene(3)
    ix = P.Index(a)
    with pytest.raises(P.LimitError, match="config.max_work"):
        ix.query(b, all_contacts=True, limits=P.Limits(max_work=2))
    with pytest.raises(P.LimitError, match="config.max_work"):
        ix.query_many([b, b], all_contacts=True, limits=P.Limits(max_work=2))
    assert ix.query(b, limits=P.Limits(max_work=10 ** 6)) == ix.query(b)


def test_cancel_from_another_thread_and_max_seconds():
    bodies = rows_scene(700)  # 490,000 touching pairs with all contacts: seconds of work
    cancel = P.Cancel()
    timer = threading.Timer(0.05, cancel.set)
    timer.start()
    with pytest.raises(P.LimitError, match=r"config.cancel: the call was cancelled \(after \d+ work steps"):
        P.check(bodies, all_contacts=True, limits=P.Limits(cancel=cancel))
    timer.join()
    with pytest.raises(P.LimitError, match=r"config.max_seconds: the time limit of 0.05 s was reached"):
        P.check(bodies, all_contacts=True, threads=2, limits=P.Limits(max_seconds=0.05))


def test_a_long_check_does_not_hold_the_gil():
    """While one thread runs a long check, this thread keeps running Python code: it
    counts to a large number before the check ends (with the GIL held through the
    call, the count would stay at its first few iterations)."""
    bodies = rows_scene(700)
    done = threading.Event()
    errors = []

    def work():
        try:
            P.check(bodies, all_contacts=True, limits=P.Limits(max_seconds=1.0))
        except P.LimitError as e:
            errors.append(str(e))
        finally:
            done.set()

    th = threading.Thread(target=work)
    th.start()
    time.sleep(0.05)
    count = 0
    while not done.is_set():
        count += 1
    th.join()
    assert errors and "config.max_seconds" in errors[0]  # the check ran its whole second
    assert count > 100000


CHILD = r"""
import signal, sys, time
from fractions import Fraction as F
import polyccd as P
# As in an interactive Python: a child of a background job (CI) inherits SIGINT ignored,
# and Python then installs no handler of its own (polyccd leaves an ignored SIGINT alone).
signal.signal(signal.SIGINT, signal.default_int_handler)
SETUP
print("started", flush=True)
try:
    CALL
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(3)
print("finished", flush=True)
"""


def interrupt_child(setup, call, wait):
    """Runs `setup` then `call` in a child Python, sends it SIGINT `wait` seconds after
    the call started; returns (exit status, its next line of output, seconds from the
    signal to that line)."""
    script = CHILD.replace("SETUP", setup).replace("CALL", call)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(wait)
        sent = time.perf_counter()
        child.send_signal(signal.SIGINT)
        line = child.stdout.readline().strip()
        reacted = time.perf_counter() - sent
        child.communicate(timeout=30)
    finally:
        if child.poll() is None:
            child.kill()
    return child.returncode, line, reacted


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_ctrl_c_ends_a_long_check():
    setup = """
n = 2000  # 4,000,000 touching pairs with all contacts: minutes (rows above)
rows = lambda x0: P.Spheres([[x0 + F(k, 2), 0, 0] for k in range(n)], [F(n, 4) + 1] * n)
bodies = [P.Body(rows(0)), P.Body(rows(F(1, 4)), P.Motion.linear([0, n, 0], [0, -n, 0]))]
"""
    # 1 s: inside the check by now (building the bodies took less)
    status, line, _ = interrupt_child(setup, "P.check(bodies, all_contacts=True)", 1.0)
    assert (status, line) == (3, "interrupted")


def test_command_line_limits(run_cli):
    case = os.path.join(REPO, "corpus", "bodies", "spheres-mesh", "slow-rational-root-long-radius.json")
    done = run_cli("check", case)
    assert done.returncode == 0 and '"collides": true' in done.stdout
    small = run_cli("check", "--max-number-bits", 1000, case)
    assert small.returncode == 2
    assert "bodies[0].radii[0]: a number of 16004 bits" in small.stderr
    assert "config.max_number_bits = 1000" in small.stderr
    work = run_cli("check", "--max-work", 3, case)
    assert work.returncode == 2 and "config.max_work: the limit of 3 work steps" in work.stderr
    assert run_cli("check", "--max-work", 10 ** 9, case).stdout == done.stdout
    bad = run_cli("check", "--max-seconds", "-1", case)
    assert bad.returncode == 2 and "--max-seconds" in bad.stderr
