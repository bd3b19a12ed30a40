"""Whole simulator steps: polyccd.check_step against ipctk 1.6 (IPC Toolkit, Tight
Inclusion CCD behind each of its CPU broad phases) on the same MuJoCo cloth frames.

    .venv/bin/python tests/bench/bench_step.py --sizes 32,64,224@64 --repeat 3

Frames: tests/bench/step_frames.py (a MuJoCo flex cloth of 2 n^2 triangles with
self-collision falling onto a sphere above a floor; steps "falling", "impact", "draped";
V0, V1 the flex vertex positions at consecutive steps; the sphere and floor as static
obstacle meshes; "224@64": the 64 x 64 cloth's frames resampled onto a 224 x 224 grid,
100,352 triangles, since MuJoCo steps that model too slowly here). For each frame and min_distance, on 1 and 2 threads
(ipctk.set_num_threads; polyccd's threads=):
  - polyccd first: check_step (the exact first time, the pairs touching first, the step
    size); polyccd decide: check_step(first_contact=False);
  - ipctk <bp>: compute_collision_free_stepsize(mesh, V0, V1, min_distance, bp) with
    TightInclusionCCD at its defaults (tolerance 1e-6, conservative rescaling 0.8) for
    every CPU broad phase (HashGrid, SpatialHash, LBVH, SweepAndPrune), and
    is_step_collision_free for the best one (ipctk's decide).
Times are the minimum over --repeat calls, in ms, everything in one process (the ratios
are within one run). ipctk's CollisionMesh is built once per frame outside the timing;
polyccd's times include building its step from the arrays. Reported besides: the exact
first contact time (polyccd), each step size, candidate pairs (polyccd: pairs whose
swept boxes met and were solved; ipctk: Candidates.build with the same inflation), and
TI's false positives: ipctk reports a contact (step size < 1, or not collision free)
where the exact answer has none.

Then a rigid MuJoCo scene (tests/bench/tunnel_scene.py; --no-tunnel skips it): a fast
spinning box shot through a thin plate, which MuJoCo's discrete contacts let tunnel;
each step's poses become exact polyccd motions (Motion.between) checked by
polyccd.check: MuJoCo's contact count, the step polyccd reports, its first time and
pair, and polyccd's time per step (the minimum over --repeat runs of all steps).
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import step_frames  # noqa: E402

import polyccd  # noqa: E402


def best_time(fn, repeat):
    best, out = float("inf"), None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best * 1e3, out


def ipctk_setup(V0, V1, F, obstacles):
    import ipctk
    verts0, verts1, faces, off = [V0], [V1], [F], len(V0)
    for V, OF in obstacles:
        verts0.append(V)
        verts1.append(V)
        faces.append(OF + off)
        off += len(V)
    A0 = np.asfortranarray(np.vstack(verts0))
    A1 = np.asfortranarray(np.vstack(verts1))
    FF = np.asfortranarray(np.vstack(faces).astype(np.int32))
    E = np.asfortranarray(ipctk.edges(FF).astype(np.int32))
    return ipctk.CollisionMesh(A0, E, FF), A0, A1


def run_frame(name, V0, V1, F, obstacles, delta, threads, repeat):
    import ipctk
    row = {"frame": name, "triangles": int(len(F)), "vertices": int(len(V0)), "min_distance": delta}
    for th in threads:
        t, r = best_time(lambda: polyccd.check_step(V0, V1, F, obstacles=obstacles, min_distance=delta,
                                                    threads=th), repeat)
        row[f"polyccd_first_{th}t"] = t
        td, rd = best_time(lambda: polyccd.check_step(V0, V1, F, obstacles=obstacles, min_distance=delta,
                                                      threads=th, first_contact=False), repeat)
        row[f"polyccd_decide_{th}t"] = td
        assert rd.collides == r.collides
    row["exact_collides"] = r.collides
    row["exact_time"] = None if r.first_contact is None else float(r.first_contact.lo)
    row["polyccd_stepsize"] = r.stepsize
    row["polyccd_candidates"] = int(r.stats["candidates"])
    mesh, A0, A1 = ipctk_setup(V0, V1, F, obstacles)
    phases = {"HashGrid": ipctk.HashGrid, "SpatialHash": ipctk.SpatialHash, "LBVH": ipctk.LBVH,
              "SweepAndPrune": ipctk.SweepAndPrune}
    for th in threads:
        ipctk.set_num_threads(th)
        best = None
        for bp_name, bp in phases.items():
            t, s = best_time(lambda: ipctk.compute_collision_free_stepsize(
                mesh, A0, A1, delta, broad_phase=bp()), repeat)
            row[f"ipctk_{bp_name}_{th}t"] = t
            row["ipctk_stepsize"] = s
            if best is None or t < row[f"ipctk_{best}_{th}t"]:
                best = bp_name
        row[f"ipctk_best_{th}t"] = best
        t, free = best_time(lambda: ipctk.is_step_collision_free(mesh, A0, A1, delta,
                                                                 broad_phase=phases[best]()), repeat)
        row[f"ipctk_decide_{th}t"] = t
        row["ipctk_free"] = bool(free)
    c = ipctk.Candidates()
    c.build(mesh, A0, A1, delta, ipctk.HashGrid())
    row["ipctk_candidates"] = len(c)
    row["ti_false_positive"] = (not r.collides) and (row["ipctk_stepsize"] < 1.0 or not row["ipctk_free"])
    return row


def table(rows, threads):
    th = max(threads)
    head = ("| frame | triangles | delta | polyccd first / decide (ms, 1t; 2t) | ipctk best CPU (ms, 1t; 2t) "
            "| ipctk decide 2t | ratio first / decide to ipctk best, 2t | exact t* | polyccd step | ipctk step "
            "| candidates polyccd / ipctk | TI false pos |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in rows:
        best = r["ipctk_%s_%dt" % (r["ipctk_best_%dt" % th], th)]
        ipc = "; ".join("%.2f (%s)" % (r["ipctk_%s_%dt" % (r["ipctk_best_%dt" % t], t)], r["ipctk_best_%dt" % t])
                        for t in threads)
        first = "; ".join("%.2f / %.2f" % (r["polyccd_first_%dt" % t], r["polyccd_decide_%dt" % t])
                          for t in threads)
        t_star = "-" if r["exact_time"] is None else f"{r['exact_time']:.6g}"
        lines.append(
            f"| {r['frame']} | {r['triangles']} | {r['min_distance']:g} | {first} | {ipc} | "
            f"{r['ipctk_decide_%dt' % th]:.2f} | {r['polyccd_first_%dt' % th] / best:.2f}x / "
            f"{r['polyccd_decide_%dt' % th] / best:.2f}x | {t_star} | {r['polyccd_stepsize']:.6g} | "
            f"{r['ipctk_stepsize']:.6g} | {r['polyccd_candidates']} / {r['ipctk_candidates']} | "
            f"{'yes' if r['ti_false_positive'] else 'no'} |")
    return "\n".join(lines)


def tunnel(repeat):
    """The rigid tunnelling scene's table (tunnel_scene.py)."""
    import tunnel_scene
    poses, contacts = tunnel_scene.simulate()
    ms, steps = best_time(lambda: tunnel_scene.polyccd_steps(poses), repeat)
    hits = [(k, r) for k, r in steps if r.collides]
    lines = ["| scene | steps | MuJoCo contacts | polyccd steps with a contact | first: step, t*, pair "
             "| polyccd ms per step |", "|---|---|---|---|---|---|"]
    first = "-"
    if hits:
        k, r = hits[0]
        c = r.pairs[0].contacts[0]
        first = f"{k}, {float(r.first_contact.lo):.9f}, bullet {c.a[0]} {c.a[1]} / plate {c.b[0]} {c.b[1]}"
    lines.append(f"| bullet through a 1 cm plate, 30 m/s, 5 ms steps | {len(steps)} | {sum(contacts)} | "
                 f"{[k for k, _ in hits]} | {first} | {ms / len(steps):.3f} |")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", default="32,64,224@64",
                    help="cloth resolutions n (2 n^2 triangles), n@m: m resampled onto n")
    ap.add_argument("--phases", default=",".join(step_frames.PHASES))
    ap.add_argument("--min-distance", default="0,0.001", help="min_distance values")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", help="write the rows here")
    ap.add_argument("--no-tunnel", action="store_true", help="skip the rigid MuJoCo tunnelling scene")
    a = ap.parse_args(argv)
    threads = [int(x) for x in a.threads.split(",")]
    import ipctk
    # ipctk logs a warning line per pair already within min_distance at t = 0: off, so
    # that printing is not timed.
    ipctk.set_logger_level(ipctk.LoggerLevel.off)
    rows = []
    for size in a.sizes.split(","):
        # "n": MuJoCo's n x n cloth; "n@m": MuJoCo's m x m cloth resampled onto n x n
        n, _, m = size.partition("@")
        frames, F, obstacles = step_frames.load(int(m or n))
        label = f"cloth {n}" if not m else f"cloth {n} (from {m})"
        if m:
            frames, F = step_frames.upsampled(frames, int(m), int(n))
        for phase in a.phases.split(","):
            if phase not in frames:
                continue
            V0, V1 = frames[phase]
            for delta in (float(x) for x in a.min_distance.split(",")):
                row = run_frame(f"{label} {phase}", V0, V1, F, obstacles, delta, threads, a.repeat)
                rows.append(row)
                print(table([row], threads).splitlines()[-1], flush=True)
    print()
    print(table(rows, threads))
    if not a.no_tunnel:
        print()
        print(tunnel(a.repeat))
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
