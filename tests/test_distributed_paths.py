"""The CLI against a separately started Dask cluster whose worker runs in another
directory (issue 24: relative paths failed there, "0 passed, 226 failed"): relative file
arguments give the serial run's output, byte for byte. The scheduler and the worker are
separate processes on 127.0.0.1, the worker started in a temporary directory."""
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytest.importorskip("distributed")

ROOT = Path(__file__).resolve().parents[1]
QUERY_DIR = Path(os.environ.get("POLYCCD_QUERY_DIR", ROOT / ".." / "shared" / "data" /
                                "ccd-queries")).resolve()


@pytest.fixture(scope="module")
def address(tmp_path_factory):
    here = tmp_path_factory.mktemp("cluster")
    file = here / "scheduler.json"
    procs = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host",
                               "127.0.0.1", "--port", "0", "--dashboard-address", "127.0.0.1:0",
                               "--scheduler-file", str(file)], cwd=here,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        deadline = time.monotonic() + 60
        while not file.exists() and time.monotonic() < deadline:
            time.sleep(0.2)
        assert file.exists(), "the scheduler did not start"
        addr = json.loads(file.read_text())["address"]
        elsewhere = tmp_path_factory.mktemp("worker_cwd")
        procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", addr,
                                       "--nworkers", "1", "--nthreads", "1", "--host", "127.0.0.1",
                                       "--no-dashboard"], cwd=elsewhere,
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        yield addr
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()


def run(*args):
    return subprocess.run([sys.executable, "-m", "polyccd", *map(str, args), "--quiet"],
                          capture_output=True, text=True, cwd=ROOT, timeout=600)


def test_relative_paths_on_an_external_cluster(address):
    cases = ["corpus/vertex-edge", "examples/cli"]
    serial = run("corpus", *cases)
    remote = run("corpus", *cases, "--scheduler", address, "--workers", "1")
    assert serial.returncode == 0 and "0 failed" in serial.stdout, serial.stdout
    assert (remote.returncode, remote.stdout) == (serial.returncode, serial.stdout)
    files = ["examples/cli/box_meets_wall.json", "corpus/vertex-face/vf-collinear-triangle-hit.json",
             "no/such/file.json"]
    serial = run("check", *files)
    remote = run("check", *files, "--scheduler", address, "--workers", "1")
    assert "no/such/file.json" in serial.stdout + serial.stderr
    assert (remote.returncode, remote.stdout, remote.stderr) == (serial.returncode, serial.stdout,
                                                                  serial.stderr)


def test_relative_csv_paths_on_an_external_cluster(address):
    csv = sorted(QUERY_DIR.glob("*/vertex-face/*.csv"))
    if not csv:
        pytest.skip(f"no query CSV under {QUERY_DIR}")
    rel = os.path.relpath(csv[0], ROOT)
    serial = run("queries", rel, "--json")
    remote = run("queries", rel, "--json", "--scheduler", address, "--workers", "1")
    strip = lambda out: [{k: v for k, v in json.loads(l).items() if k != "seconds_per_query"}
                         for l in out.splitlines()]
    assert serial.returncode == 0
    assert (remote.returncode, strip(remote.stdout)) == (serial.returncode, strip(serial.stdout))
    assert strip(remote.stdout)[0]["file"] == rel
