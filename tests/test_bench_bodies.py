"""Smoke test of tests/bench/bench_bodies.py: its --quick mode (a 1280-triangle icosphere on
a screw against a plate, and two 1000-atom molecules, each as hit / near miss by 1.0e-6 /
exact touch) runs, and every polyccd answer (threads=1 and threads=2) equals the exact
truth the benchmark derives from the geometry alone. FCL runs too when python-fcl is
installed; its answers are reported by the benchmark, never judged here."""
import json
import subprocess
import sys
from pathlib import Path

import polyccd

BENCH = Path(__file__).resolve().parent / "bench" / "bench_bodies.py"
CASES = {(s, v) for s in ("mesh-1k", "mol-1k") for v in ("hit", "near", "touch")}
T_STAR = {"hit": "1/2", "near": None, "touch": "1"}


def test_bench_bodies_quick(tmp_path):
    assert hasattr(polyccd, "check") and hasattr(polyccd, "Body"), \
        "polyccd.check / polyccd.Body missing (docs/python.md, Scenes)"
    out = tmp_path / "bodies.json"
    args = [sys.executable, str(BENCH), "--quick", "--repeat", "1", "--json", str(out)]
    try:
        import fcl  # noqa: F401
    except ImportError:
        args.append("--no-fcl")
    proc = subprocess.run(args, capture_output=True, text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    data = json.loads(out.read_text())
    assert data["polyccd"] == polyccd.__version__, data.get("polyccd_note")
    records = data["records"]
    assert {(r["size"], r["variant"]) for r in records} == CASES
    for r in records:
        where = f"{r['size']}/{r['variant']}"
        # the benchmark's exact truth is what the construction promises
        assert r["truth"] == (r["variant"] != "near"), where
        assert r["t_star"] == T_STAR[r["variant"]], where
        for m in ("polyccd-t1", "polyccd-t2"):
            e = r["methods"][m]
            assert e is not None and e["error"] is None, (where, m, e)
            assert e["collides"] == r["truth"], (where, m, e)
            if r["truth"]:  # a rational first contact is reported exactly
                assert e["exact"] == r["t_star"], (where, m, e)
            else:
                assert e["exact"] is None and e["lo"] is None, (where, m, e)
            assert e["verdict"] == "OK", (where, m, e)
