"""Runs every fuzzer for a set time and prints its executions (`make fuzz`).

For each harness (the C ones in BUILD/, fuzz_readers.py under the venv's Python): first
the saved inputs of tests/fuzz/crashes/<harness>-* (every crash found so far, fixed:
they must run clean), then libFuzzer for --seconds, on BUILD/corpus/<harness> (kept
between runs) seeded from BUILD/seeds/<harness> (seeds.py, rewritten each run). A new
crash, leak or hang (a single input past -timeout) is written to BUILD/crashes/ and
fails the run. Prints one line per harness and the total:

    fuzz_query: 10 s, 2,310 executions (231/s), clean
"""
import argparse
import os
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# Longest input per harness (bytes): enough for the largest seed, small enough to stay
# within the harnesses' cost limits most of the time.
MAX_LEN = {"fuzz_query": 1024, "fuzz_motion": 1024, "fuzz_body": 2048, "fuzz_scene": 2048,
           "fuzz_numbers": 512, "fuzz_readers": 4096}
TIMEOUT_S = 10       # one input running longer is a hang (wall clock: --timeout for a niced
                     # run on a busy machine, where an input of 0.5 s without sanitizers
                     # took 6-10 s under ASan at nice 19)
RSS_LIMIT_MB = 3072  # a process using more is a failure (ASan allocator caches included: fuzz_query
                     # passed 2 GB after 99,572 executions with a live heap of 31 MB)


def harnesses(build):
    c = sorted(p.stem for p in (ROOT / "tests" / "fuzz").glob("fuzz_*.c"))
    py = sorted(p.stem for p in (ROOT / "tests" / "fuzz").glob("fuzz_*.py"))
    return [(h, [str(build / h)]) for h in c] + [(h, None) for h in py]


def command(name, c_cmd, python):
    if c_cmd is not None:
        return list(c_cmd)
    return [python, str(ROOT / "tests" / "fuzz" / f"{name}.py")]


def flags(name, timeout=TIMEOUT_S):
    return [f"-max_len={MAX_LEN.get(name, 4096)}", f"-timeout={timeout}",
            f"-rss_limit_mb={RSS_LIMIT_MB}"]


def replay(name, cmd):
    """Runs the saved crash inputs of this harness; False when one fails again."""
    saved = sorted((ROOT / "tests" / "fuzz" / "crashes").glob(f"{name}-*"))
    if not saved:
        return True
    r = subprocess.run(cmd + flags(name) + [str(p) for p in saved], capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stderr[-3000:], file=sys.stderr)
        print(f"{name}: a saved crash input fails again (tests/fuzz/crashes/)")
        return False
    print(f"{name}: {len(saved)} saved crash inputs run clean")
    return True


def run(name, cmd, seconds, build, extra, timeout=TIMEOUT_S):
    corpus, seeds, crashes = build / "corpus" / name, build / "seeds" / name, build / "crashes"
    for d in (corpus, seeds, crashes):
        d.mkdir(parents=True, exist_ok=True)
    args = cmd + flags(name, timeout) + [f"-max_total_time={seconds}", "-print_final_stats=1",
                                f"-artifact_prefix={crashes}/{name}-"] + extra
    args += [str(corpus), str(seeds)]
    start = time.monotonic()
    log = build / f"{name}.log"  # written as libFuzzer goes: a long run can be watched
    with open(log, "w") as out:
        r = subprocess.run(args, stdout=out, stderr=subprocess.STDOUT, env=dict(os.environ))
    took = max(1, round(time.monotonic() - start))  # a crash ends the run early
    text = log.read_text(errors="replace")
    m = re.search(r"stat::number_of_executed_units:\s*(\d+)", text)
    if m is None:  # killed before the final stats: count the last status line
        lines = re.findall(r"^#(\d+)\s", text, re.M)
        execs = int(lines[-1]) if lines else 0
    else:
        execs = int(m.group(1))
    clean = r.returncode == 0
    what = "clean" if clean else f"FAILED (exit {r.returncode}; see {log} and {crashes}/)"
    print(f"{name}: {took} s, {execs:,} executions ({execs // took:,}/s), {what}", flush=True)
    return execs, clean


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n")[0])
    ap.add_argument("--build", type=Path, default=ROOT / "build-fuzz")
    ap.add_argument("--seconds", default="10",
                    help="seconds per harness: N, or name=N,name=N (others: 10)")
    ap.add_argument("--python", default=sys.executable, help="the Python with polyccd and atheris")
    ap.add_argument("--only", default="", help="comma-separated harness names")
    ap.add_argument("--args", default="", help="extra libFuzzer flags")
    ap.add_argument("--timeout", type=int, default=TIMEOUT_S,
                    help=f"seconds (wall clock) after which one input is a hang (default {TIMEOUT_S})")
    args = ap.parse_args(argv)
    build = args.build if args.build.is_absolute() else ROOT / args.build
    per = {}
    if "=" in args.seconds:
        for item in args.seconds.split(","):
            k, v = item.split("=")
            per[k.strip()] = int(v)
        default = 10
    else:
        default = int(args.seconds)
    subprocess.run([sys.executable, str(ROOT / "tests" / "fuzz" / "seeds.py"), str(build / "seeds")],
                   check=True)
    only = [s for s in args.only.split(",") if s]
    total, ok = 0, True
    for name, c_cmd in harnesses(build):
        if only and name not in only:
            continue
        cmd = command(name, c_cmd, args.python)
        ok = replay(name, cmd) and ok
        execs, clean = run(name, cmd, per.get(name, default), build, shlex.split(args.args),
                           args.timeout)
        total += execs
        ok = ok and clean
    print(f"fuzz: {total:,} executions in total, {'clean' if ok else 'FAILED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
