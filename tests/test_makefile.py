"""The Makefile's own promises (README, "The two commands of a checkout"): it builds in
parallel unless told otherwise, and no target redoes the editable install of the dev venv
unless that install's inputs changed. `make -n` only prints, so these leave the tree as
it is."""
import os
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _make_n(*args, **extra_env):
    """What `make -n ARGS` would run, with no make jobserver or flags of a make running
    this test (extra_env: variables set for it)."""
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    env.update(extra_env)
    out = subprocess.run(["make", "-n", "--no-print-directory", "-C", str(ROOT), *args],
                         capture_output=True, text=True, env=env, timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    return out.stdout


def _build_command(out):
    """The sub-make command that builds everything for `check` (the sub-make's own
    messages, "make[1]: 'build/poly_probe' is up to date.", are not it)."""
    (line,) = [ln for ln in out.splitlines() if ln.startswith("make ") and "poly_probe" in ln]
    return line


def test_builds_in_parallel_unless_told():
    jobs = f"-j{len(os.sched_getaffinity(0))}"    # the CPUs this process may use, as nproc
    assert jobs in _build_command(_make_n("check")).split()
    # An OpenMP setting (dask's nanny sets OMP_NUM_THREADS=1 in the test process) is not a
    # CPU count: nproc alone would take it.
    assert jobs in _build_command(_make_n("check", OMP_NUM_THREADS="1", OMP_THREAD_LIMIT="1")).split()
    line = _build_command(_make_n("-j3", "check"))
    assert not re.search(r"(^|\s)-j\d", line), line       # the command line's -j3 governs


def test_pytest_runs_in_two_workers():
    out = _make_n("test-py").replace("\\\n", " ")      # one command over two lines
    (line,) = [ln for ln in out.splitlines() if "-m pytest" in ln]
    assert "-n 2" in line.split("pytest", 1)[1] and "--dist loadfile" in line, line


@pytest.mark.skipif(not (ROOT / "build" / "editable.stamp").exists(),
                    reason="no editable install made by this Makefile yet (make venv)")
def test_editable_install_is_not_redone_when_nothing_changed():
    """After `make` (as under `make test`), test-py and check run no pip install and no
    build_ffi.py: the stamp build/editable.stamp is newer than their inputs."""
    for target in ("venv", "test-py", "all"):
        out = _make_n(target)
        assert "pip install" not in out and "build_ffi.py" not in out, (target, out)
