"""Time per query of polyccd.check on the benchmark scenes of bench_bodies.py with each
broad phase (boxes, range; brute optional), one thread, after one warm-up query.

    .venv/bin/python tests/bench/broad_phases.py [--sizes mesh-1k,mol-1k] [--repeat 3] [--swing]

--swing: the mesh scenes' sphere swings on a pendulum instead of its screw: the rotation
about the x axis through (0, 0, 4) with tau from 1/4 to 0, then lowered by 1/4, so that
it ends where the screw ends (the same hit / near / touch plates apply, contact or not
near t = 1/2 and t = 1). A rotation about a fixed axis: the range phase uses its exact
linearization there (lib/range/LINEARIZATION.md).
"""
from fractions import Fraction
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bodies_cases as bb  # noqa: E402  (the scenes of bench_bodies.py)
import bodies_methods as bm  # noqa: E402
import polyccd  # noqa: E402


def swing_motion():
    return (polyccd.Motion.axis_rotation([1, 0, 0], [0, 0, 4], Fraction(1, 4), 0)
            .compose([1, 0, 0, 0], [0, 0, Fraction(-1, 4)], side="world").validate())


def bodies_of(label, variant, cache, swing=False):
    if label not in cache:
        if label.startswith("mol"):
            case = bb.mol_case(label)
            cache[label] = (case, bm.polyccd_build_mol(polyccd, case))
        else:
            case = bb.mesh_case(label, bb.MESH_SIZES[label])
            cache[label] = (case, bm.polyccd_build_mesh(polyccd, case))
    case, built = cache[label]
    if label.startswith("mol"):
        off, L = case["offset_exact"], case["variants"][variant]["L"]
        m = polyccd.Motion.linear(list(off), [off[0] - L, off[1], off[2]]).validate()
        return [polyccd.Body(built["shape"], None, name="A"), polyccd.Body(built["shape"], m, name="B")]
    return [polyccd.Body(built["sphere"], swing_motion() if swing else built["motion"], name="sphere"),
            polyccd.Body(built["plates"][variant], None, name="plate")]


def main():
    ap = argparse.ArgumentParser(allow_abbrev=False, description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="mesh-1k,mesh-5k,mol-1k,mol-5k")
    ap.add_argument("--phases", default="boxes,range")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--swing", action="store_true", help="mesh scenes: a pendulum swing instead of the screw")
    args = ap.parse_args()
    cache = {}
    print(f"{'scene':10} {'variant':7} " + " ".join(f"{p + ' ms':>10}" for p in args.phases.split(","))
          + "  answers agree")
    for label in args.sizes.split(","):
        for variant in bb.VARIANTS:
            bodies = bodies_of(label, variant, cache, args.swing)
            times, answers = [], []
            for phase in args.phases.split(","):
                r = polyccd.check(bodies, broad_phase=phase)
                t0 = time.perf_counter()
                for _ in range(args.repeat):
                    r = polyccd.check(bodies, broad_phase=phase)
                times.append((time.perf_counter() - t0) / args.repeat * 1e3)
                ct = r.first_contact
                answers.append((r.collides, ct and (ct.lo, ct.hi)))
            print(f"{label:10} {variant:7} " + " ".join(f"{t:10.2f}" for t in times)
                  + f"  {all(a == answers[0] for a in answers)}")


if __name__ == "__main__":
    main()
