"""`polyccd demo`: a few degenerate queries whose exact answers are obvious by
construction, printed next to polyccd's answers, then the shared benchmark summary."""
import os
from fractions import Fraction
from pathlib import Path

from ..texts import ratio_text
from .. import solve

# A static triangle in the plane z = 0 (used by the vertex-face cases).
TRIANGLE = [[[0], [0], [0]], [[1], [0], [0]], [[0], [1], [0]]]
HALF = Fraction(1, 2)


def _exactly(t):
    return lambda r: r.collides and r.first_contact.exact == t


def _inverse_sqrt2(r):
    # t* = 1/sqrt(2) is irrational: no exact value, and lo^2 <= 1/2 <= hi^2.
    c = r.first_contact
    return r.collides and c.exact is None and 0 <= c.lo and c.lo ** 2 <= HALF <= c.hi ** 2


CASES = [
    ("vertex grazing a face: a double root at t = 1/2",
     "v(t) = (1/4, 1/4, (2t-1)^2) touches the triangle (0,0,0) (1,0,0) (0,1,0) at t = 1/2 "
     "and leaves it",
     "contact at exactly t = 1/2 (vertex-face)", _exactly(HALF),
     ("vertex-face", [[["1/4"], ["1/4"], [1, -4, 4]]] + TRIANGLE, None)),
    ("near miss by 1e-30",
     "the same vertex lifted by 10^-30: v(t) = (1/4, 1/4, (2t-1)^2 + 1e-30)",
     "no contact (the distance never drops below 1e-30)", lambda r: not r.collides,
     ("vertex-face", [[["1/4"], ["1/4"], ["1.000000000000000000000000000001", -4, 4]]]
      + TRIANGLE, None)),
    ("edge-edge contact at the irrational time t = 1/sqrt(2)",
     "edge (-1,0,0)-(1,0,0) is static; edge (0,-1,z)-(0,1,z) falls along z(t) = 1 - 2t^2",
     "contact at t = 1/sqrt(2) = 0.70710678118654752..., not rational (edge-edge)",
     _inverse_sqrt2,
     ("edge-edge", [[[-1], [0], [0]], [[1], [0], [0]],
                    [[0], [-1], [1, 0, -2]], [[0], [1], [1, 0, -2]]], None)),
    ("contact exactly at t = 1",
     "v(t) = (1/4, 1/4, 1 - t) reaches the triangle in the plane z = 0 at the last instant",
     "contact at exactly t = 1 (vertex-face)", _exactly(Fraction(1)),
     ("vertex-face", [[["1/4"], ["1/4"], [1, -1]]] + TRIANGLE, None)),
    ("coplanar sliding edges",
     "in the plane z = 0, edge (0,0,0)-(1,0,0) is static; edge (x,-1,0)-(x,1,0) slides "
     "along x(t) = 2 - 3t/2 and meets the end point (1,0,0) at t = 2/3",
     "contact at exactly t = 2/3 (vertex-edge: point 1 inside edge 2-3)",
     _exactly(Fraction(2, 3)),
     ("edge-edge", [[[0], [0], [0]], [[1], [0], [0]],
                    [[2, "-3/2"], [-1], [0]], [[2, "-3/2"], [1], [0]]], None)),
    ("two balls meeting",
     "balls of radius 1/2 centred at (0,0,0) and (3 - 4t, 0, 0) touch when the centres "
     "are 1 apart",
     "contact at exactly t = 1/2 (sphere-sphere)", _exactly(HALF),
     ("sphere-sphere", [[[0], [0], [0]], [[3, -4], [0], [0]]], ["1/2", "1/2"])),
]


def _answer(r):
    if not r.collides:
        return "no contact"
    c = r.first_contact
    if c.exact is not None:
        when = f"contact at exactly t = {ratio_text(c.exact.numerator, c.exact.denominator)}"
    else:
        when = (f"contact at t in [{float(c.lo):.17g}, {float(c.hi):.17g}] "
                f"(width {float(c.hi - c.lo):.2g}, not exact)")
    features = ", ".join(f"{f.kind} {list(f.points)}" for f in r.features)
    return f"{when}; features: {features or 'none'}; decided by stage {r.stage}"


def run_cases(out):
    """Prints every case; True when every answer is the expected one."""
    all_ok = True
    for number, (title, setup, expected, is_right, (kind, points, radii)) in enumerate(CASES, 1):
        r = solve(kind, points, radii)
        ok = is_right(r)
        all_ok &= ok
        out(f"{number}. {title}\n   {setup}\n   expected: {expected}\n"
            f"   polyccd:  {_answer(r)}\n   {'OK' if ok else 'MISMATCH'}\n")
    return all_ok


def query_dir():
    """The shared benchmark query folder, or None when it is not there: $POLYCCD_QUERY_DIR
    (absolute, or relative to the working directory or the checkout), else
    ../shared/data/ccd-queries beside the checkout this package runs from (an installed
    package has no checkout: then only the variable finds it)."""
    env = os.environ.get("POLYCCD_QUERY_DIR")
    repo = Path(__file__).resolve().parents[4]  # bindings/python/polyccd/apps -> the repo
    candidates = [Path(env), repo / env] if env else [repo / "../shared/data/ccd-queries"]
    for d in candidates:
        if d.is_dir():
            return d.resolve()
    return None
