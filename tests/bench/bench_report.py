"""What the benchmarks print about themselves: the machine (CPU model, loaded libraries,
package versions), aligned tables, time and number formats, and the scaling exponent
fitted to (size, time) points. Shared by bench_bodies.py, bench_bvh.py, bench_online.py."""
import datetime
import os
import platform
from pathlib import Path

import numpy as np

# ---------------------------------------------------------------------------------------
# Reporting


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def loaded_libraries(names):
    """[(path, mtime)] of the shared objects this process mapped whose name contains one of
    names (from /proc/self/maps: the files actually in use, even if rebuilt since)."""
    seen = []
    try:
        with open("/proc/self/maps") as f:
            for line in f:
                path = line.split(None, 5)[-1].strip() if len(line.split(None, 5)) == 6 else ""
                if any(n in Path(path).name for n in names) and path not in [p for p, _ in seen]:
                    deleted = path.endswith(" (deleted)")
                    try:
                        mtime = ("file replaced since" if deleted else datetime.datetime.fromtimestamp(
                            os.stat(path).st_mtime, datetime.timezone.utc).isoformat(timespec="seconds"))
                    except OSError:
                        mtime = "?"
                    seen.append((path, mtime))
    except OSError:
        pass
    return seen


def pkg_version(name):
    try:
        from importlib.metadata import version

        return version(name)
    except Exception:
        return "not installed"


def print_table(headers, rows):
    widths = [max(len(str(h)), *(len(str(r[i])) for r in rows)) for i, h in enumerate(headers)]
    line = "  ".join(f"{h:>{w}}" for h, w in zip(headers, widths))
    print(line)
    print("-" * len(line))
    for r in rows:
        print("  ".join(f"{str(c):>{w}}" for c, w in zip(r, widths)))


def fmt_ms(ns):
    if ns is None:
        return "n/a"
    ms = ns / 1e6
    return f"{ms:.3f}" if ms < 10 else f"{ms:.1f}"


def fmt_time(ans):
    if ans is None or ans.error is not None or not ans.collides:
        return "-"
    if ans.exact is not None:
        return str(ans.exact)
    return f"{ans.time:.6g}" if ans.time is not None else "?"


def fit_exponent(points):
    """Least-squares slope of log(time) against log(primitives)."""
    pts = [(n, t) for n, t in points if t and t > 0]
    if len(pts) < 2 or len({n for n, _ in pts}) < 2:
        return None
    x = np.log([n for n, _ in pts])
    y = np.log([t for _, t in pts])
    return float(np.polyfit(x, y, 1)[0])


def fstr(q):
    return None if q is None else str(q)
