"""Hand-constructed corpus cases for tests/tools/make_corpus.py.

Each entry: (file name, kind, points, radii, source, want). `want` is the answer derived
by reasoning (stated in the source text): a first contact time, None for no contact, or
(IRR, minimal polynomial coefficients ascending, approximate value) for an irrational
time. make_corpus.py stops if the oracle disagrees with it.
"""
from fractions import Fraction as F

from oracle_gen import pmul

IRR = "irrational"
E30 = F(1, 10 ** 30)
C = "constructed: "


class Literal(str):
    """Written as a bare JSON number (exact decimal per formats.md)."""


def P(x, y, z):
    """A trajectory; each coordinate a constant or a list of coefficients (ascending)."""
    return [list(c) if isinstance(c, (list, tuple)) else [c] for c in (x, y, z)]


def scaled(pts, k, shift=(0, 0, 0)):
    return [[[c * k + (s if i == 0 else 0) for i, c in enumerate(axis)]
             for axis, s in zip(p, shift)] for p in pts]


TRI = [P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)]          # static right triangle in z = 0
SEG = [P(-1, 0, 0), P(1, 0, 0)]                     # static segment on the x axis
SQ2 = (IRR, [-1, 0, 2], 0.7071067811865476)          # 1/sqrt(2)
SQ3 = (IRR, [-1, 0, 3], 0.5773502691896258)          # 1/sqrt(3)
SQ6 = (IRR, [-1, 0, 6], 0.4082482904638630)          # 1/sqrt(6)
G13 = pmul(pmul([F(-1, 3), 1], [F(-1, 3), 1]), pmul([1, 1], pmul([1, 1], [1, 1])))
TWO_TOUCH = pmul(pmul([F(-1, 4), 1], [F(-1, 4), 1]), [F(3, 4), -1])
Q4 = [F(1, 4), 0, -1, 0, 1]                          # (t^2 - 1/2)^2
Q9 = [F(1, 9), 0, F(-2, 3), 0, 1]                    # (t^2 - 1/3)^2

VF = "vertex-face"
EE = "edge-edge"
VE = "vertex-edge"
VV = "vertex-vertex"
SS = "sphere-sphere"

CASES = [
    # ------------------------------------------------------------ vertex-face
    ("vf-falls-through-interior", VF, [P(F(1, 5), F(1, 5), [1, -2])] + TRI, None,
     C + "vertex falls along z (z = 1 - 2t) through a static triangle: z = 0 at t = 1/2", F(1, 2)),
    ("vf-irrational-first-contact", VF, [P(F(1, 5), F(1, 5), [1, 0, -2])] + TRI, None,
     C + "z = 1 - 2t^2 reaches the face at t = 1/sqrt(2)", SQ2),
    ("vf-grazing-double-root", VF, [P(F(1, 5), F(1, 5), [F(1, 4), -1, 1])] + TRI, None,
     C + "z = (t - 1/2)^2: vertex grazes the face, double root at t = 1/2", F(1, 2)),
    ("vf-grazing-near-miss-1e-30", VF, [P(F(1, 5), F(1, 5), [F(1, 4) + E30, -1, 1])] + TRI, None,
     C + "z = (t - 1/2)^2 + 1e-30 never reaches 0: near miss", None),
    ("vf-grazing-irrational-double-root", VF, [P(F(1, 5), F(1, 5), Q4)] + TRI, None,
     C + "z = (t^2 - 1/2)^2 touches only at t = 1/sqrt(2) (double root)", SQ2),
    ("vf-coplanar-slide-enters-through-edge", VF, [P([2, -3], F(1, 5), 0)] + TRI, None,
     C + "vertex slides in the face plane for all t, crosses x + y = 1 at x = 4/5, t = 2/5", F(2, 5)),
    ("vf-coplanar-slide-misses", VF, [P([2, -3], 2, 0)] + TRI, None,
     C + "vertex slides in the face plane along y = 2, outside the triangle", None),
    ("vf-coplanar-slide-near-miss-1e-30", VF, [P([-1, 3], -E30, 0)] + TRI, None,
     C + "vertex slides in the plane along y = -1e-30, just outside the edge y = 0", None),
    ("vf-coplanar-slide-along-edge-line", VF, [P([-1, 3], 0, 0)] + TRI, None,
     C + "vertex slides along the line of edge f0 f1, reaches f0 at t = 1/3", F(1, 3)),
    ("vf-contact-at-t0-on-vertex", VF, [P([1, 1], 0, [0, 1])] + TRI, None,
     C + "vertex starts exactly on face vertex f1 and leaves: contact at t = 0", F(0)),
    ("vf-contact-at-t1", VF, [P(F(1, 4), F(1, 4), [1, -1])] + TRI, None,
     C + "z = 1 - t reaches the face exactly at t = 1", F(1)),
    ("vf-through-hypotenuse", VF, [P(F(1, 2), F(1, 2), [1, -2])] + TRI, None,
     C + "vertex passes exactly through the edge x + y = 1 at t = 1/2", F(1, 2)),
    ("vf-through-vertex", VF, [P(1, 0, [1, -2])] + TRI, None,
     C + "vertex passes exactly through face vertex f1 at t = 1/2", F(1, 2)),
    ("vf-misses-vertex-by-1e-30", VF, [P(1 + E30, 0, [1, -2])] + TRI, None,
     C + "vertex crosses the plane at x = 1 + 1e-30, beside face vertex f1", None),
    ("vf-collinear-triangle-hit", VF, [P(F(3, 2), [1, -2], 0), P(0, 0, 0), P(1, 0, 0), P(2, 0, 0)],
     None, C + "degenerate (collinear) triangle = segment [0, 2] on x; vertex crosses it at t = 1/2",
     F(1, 2)),
    ("vf-collinear-triangle-miss", VF, [P(F(5, 2), [1, -2], 0), P(0, 0, 0), P(2, 0, 0), P(1, 0, 0)],
     None, C + "collinear triangle = segment [0, 2]; vertex crosses its line at x = 5/2", None),
    ("vf-point-triangle-hit", VF, [P([1, -2], 0, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0)], None,
     C + "all three face vertices coincide at the origin; vertex passes it at t = 1/2", F(1, 2)),
    ("vf-point-triangle-near-miss-1e-30", VF, [P([1, -2], E30, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0)],
     None, C + "coincident face vertices at the origin; vertex passes 1e-30 beside it", None),
    ("vf-two-coincident-vertices", VF, [P([1, -2], 1, 0), P(0, 0, 0), P(0, 0, 0), P(0, 2, 0)], None,
     C + "f0 == f1: the face is the segment x = 0, y in [0, 2]; vertex crosses it at t = 1/2",
     F(1, 2)),
    ("vf-triangle-flat-at-contact-instant", VF,
     [P(1, [F(-1, 2), 1], [F(1, 2), -1]), P(0, 0, 0), P(2, 0, 0), P(1, [1, -2], 0)], None,
     C + "apex f2 = (1, 1 - 2t, 0) makes the triangle collinear exactly at t = 1/2, when the "
     "vertex (1, t - 1/2, 1/2 - t) reaches the plane, at (1, 0, 0) on the segment", F(1, 2)),
    ("vf-face-falls-onto-static-vertex", VF,
     [P(F(1, 4), F(1, 4), 0), P(0, 0, [1, -4]), P(1, 0, [1, -4]), P(0, 1, [1, -4])], None,
     C + "the face moves down z = 1 - 4t onto a static vertex: t = 1/4", F(1, 4)),
    ("vf-degree5-rational-root", VF, [P(F(1, 5), F(1, 5), [F(1, 32), 0, 0, 0, 0, -1])] + TRI, None,
     C + "z = 1/32 - t^5 (degree 5): contact at t = 1/2", F(1, 2)),
    ("vf-degree6-irrational", VF, [P(F(1, 5), F(1, 5), [F(1, 2), 0, 0, 0, 0, 0, -1])] + TRI, None,
     C + "z = 1/2 - t^6 (degree 6): contact at t = 2^(-1/6)",
     (IRR, [-1, 0, 0, 0, 0, 0, 2], 0.8908987181403393)),
    ("vf-degree5-grazing", VF, [P(F(1, 5), F(1, 5), G13)] + TRI, None,
     C + "z = (t - 1/3)^2 (t + 1)^3 (degree 5) grazes at t = 1/3", F(1, 3)),
    ("vf-vertex-is-face-vertex", VF,
     [P(0, 1, [0, 1]), P([0, 1], 0, 0), P(1, [0, 0, 1], 0), P(0, 1, [0, 1])], None,
     C + "the vertex trajectory equals face vertex f2 for all t: contact at t = 0", F(0)),
    ("vf-plane-offset-1e-30", VF,
     [P([-1, 3], F(1, 5), 0), P(0, 0, E30), P(1, 0, E30), P(0, 1, E30)], None,
     C + "vertex slides in z = 0 across the triangle's projection; the face is at z = 1e-30", None),
    ("vf-huge-coordinates-1e30", VF, scaled([P(F(1, 5), F(1, 5), [1, -2])] + TRI, 10 ** 30), None,
     C + "vf-falls-through-interior with every coordinate times 1e30: t = 1/2", F(1, 2)),
    ("vf-tiny-coordinates-1e-30", VF, scaled([P(F(1, 5), F(1, 5), [1, -2])] + TRI, E30), None,
     C + "vf-falls-through-interior with every coordinate times 1e-30: t = 1/2", F(1, 2)),
    ("vf-json-number-literals", VF,
     [P(Literal("0.1"), Literal("0.4"), [Literal("0.3"), Literal("-0.6")]),
      P(0, 0, 0), P(Literal("0.5"), 0, 0), P(0, Literal("0.5"), 0)], None,
     C + "JSON number literals are exact decimals: 0.1 + 0.4 == 0.5 exactly, so the vertex "
     "crosses the hypotenuse x + y = 0.5 at t = 1/2 (in binary floats it would miss)", F(1, 2)),
    ("vf-static-inside", VF, [P(F(1, 4), F(1, 4), 0)] + TRI, None,
     C + "static vertex inside a static face: contact at t = 0", F(0)),
    ("vf-both-moving-irrational", VF,
     [P(F(1, 5), F(1, 5), [F(1, 3), 0, -1]), P(0, 0, [0, 0, 1]), P(1, 0, [0, 0, 1]),
      P(0, 1, [0, 0, 1])], None,
     C + "face at z = t^2, vertex at z = 1/3 - t^2: meet at t = 1/sqrt(6)", SQ6),
    ("vf-dip-1e-60-close-roots", VF, [P(F(1, 5), F(1, 5), [F(1, 4) - E30 * E30, -1, 1])] + TRI, None,
     C + "z = (t - 1/2)^2 - 1e-60 dips below the face between t = 1/2 -+ 1e-30: first "
     "contact 1/2 - 1e-30 (two roots 2e-30 apart)", F(1, 2) - E30),
    ("vf-dip-2e-60-close-irrational-roots", VF,
     [P(F(1, 5), F(1, 5), [F(1, 4) - 2 * E30 * E30, -1, 1])] + TRI, None,
     C + "z = (t - 1/2)^2 - 2e-60: first contact 1/2 - sqrt(2) 1e-30 (irrational, the two "
     "roots 2.8e-30 apart)", (IRR, None, (F(1, 2) - F(1415, 1000) * E30, F(1, 2) - F(1414, 1000) * E30))),
    ("vf-through-face-vertex-irrational", VF, [P(1, 0, [1, 0, -2])] + TRI, None,
     C + "vertex passes exactly through face vertex f1 at t = 1/sqrt(2)", SQ2),
    ("vf-triangle-flat-at-irrational-instant", VF,
     [P(1, 0, [F(-1, 2), 0, 1]), P(0, 0, 0), P(2, 0, 0), P(1, [-1, 0, 2], 0)], None,
     C + "apex (1, 2t^2 - 1, 0) flattens the triangle exactly when the vertex (1, 0, t^2 - 1/2) "
     "reaches its plane, at t = 1/sqrt(2)", SQ2),
    ("vf-degree10-irrational", VF, [P(F(1, 5), F(1, 5), [F(1, 3)] + [0] * 9 + [-1])] + TRI, None,
     C + "z = 1/3 - t^10 (degree 10): t = 3^(-1/10)",
     (IRR, [-1] + [0] * 9 + [3], 0.8959584598407622)),
    ("vf-isolated-touch-before-crossing", VF, [P(F(1, 5), F(1, 5), TWO_TOUCH)] + TRI, None,
     C + "z = (t - 1/4)^2 (3/4 - t): grazes at t = 1/4, crosses at t = 3/4; first is 1/4",
     F(1, 4)),
    # ------------------------------------------------------------ edge-edge
    ("ee-perpendicular-crossing", EE, SEG + [P(0, -1, [1, -2]), P(0, 1, [1, -2])], None,
     C + "edge along y descends z = 1 - 2t across the static x-axis edge: t = 1/2", F(1, 2)),
    ("ee-irrational-crossing", EE, SEG + [P(0, -1, [1, 0, -3]), P(0, 1, [1, 0, -3])], None,
     C + "z = 1 - 3t^2: the edges cross at t = 1/sqrt(3)", SQ3),
    ("ee-parallel-never", EE, SEG + [P(-1, 1, [0, 1]), P(1, 1, [0, 1])], None,
     C + "parallel edges on distinct lines for all t", None),
    ("ee-parallel-become-collinear-overlap", EE, SEG + [P(0, [1, -2], 0), P(2, [1, -2], 0)], None,
     C + "parallel for all t, collinear at t = 1/2 with overlap [0, 1]", F(1, 2)),
    ("ee-parallel-become-collinear-disjoint", EE, SEG + [P(2, [1, -2], 0), P(3, [1, -2], 0)], None,
     C + "parallel, collinear at t = 1/2 but x in [2, 3] vs [-1, 1]: no contact", None),
    ("ee-parallel-become-collinear-touch-endpoints", EE, SEG + [P(1, [1, -2], 0), P(3, [1, -2], 0)],
     None, C + "parallel, collinear at t = 1/2, touching at the shared endpoint x = 1", F(1, 2)),
    ("ee-collinear-sliding-endpoints-meet", EE,
     [P(0, 0, 0), P(1, 0, 0), P([3, -3], 0, 0), P([4, -3], 0, 0)], None,
     C + "collinear for all t, edge B slides onto A: endpoints meet at t = 2/3", F(2, 3)),
    ("ee-collinear-overlapping-from-start", EE,
     [P(0, 0, 0), P(2, 0, 0), P([1, 1], 0, 0), P([3, 1], 0, 0)], None,
     C + "collinear, overlapping at t = 0", F(0)),
    ("ee-collinear-gap-closes-to-1e-30", EE,
     [P(0, 0, 0), P(1, 0, 0), P([2 + E30, -1], 0, 0), P(3, 0, 0)], None,
     C + "collinear; the gap 1 - t + 1e-30 never closes on [0, 1]", None),
    ("ee-shared-endpoint", EE, [P(0, 0, 0), P([1, 1], 0, 0), P(0, 0, 0), P(0, [1, 5], 0)], None,
     C + "the edges share an endpoint for all t", F(0)),
    ("ee-endpoints-meet-at-t1", EE, [P(0, 0, 0), P(1, 0, 0), P(1, 0, [1, -1]), P(1, 1, [1, -1])],
     None, C + "endpoint b0 = (1, 0, 1 - t) reaches endpoint a1 at t = 1", F(1)),
    ("ee-grazing-double-root", EE,
     SEG + [P(0, -1, [F(1, 9), F(-2, 3), 1]), P(0, 1, [F(1, 9), F(-2, 3), 1])], None,
     C + "edge at height z = (t - 1/3)^2 above a crossing edge: grazes at t = 1/3", F(1, 3)),
    ("ee-grazing-near-miss-1e-30", EE,
     SEG + [P(0, -1, [F(1, 9) + E30, F(-2, 3), 1]), P(0, 1, [F(1, 9) + E30, F(-2, 3), 1])], None,
     C + "z = (t - 1/3)^2 + 1e-30: never touches", None),
    ("ee-grazing-irrational-double-root", EE, SEG + [P(0, -1, Q9), P(0, 1, Q9)], None,
     C + "z = (t^2 - 1/3)^2: touches only at t = 1/sqrt(3)", SQ3),
    ("ee-skew-lines-cross-outside", EE, SEG + [P(0, 1, [1, -2]), P(0, 2, [1, -2])], None,
     C + "the lines cross at t = 1/2 at y = 0, outside edge B (y in [1, 2])", None),
    ("ee-zero-length-a-hits-b", EE, [P(F(1, 2), 0, [1, -4])] * 2 + SEG, None,
     C + "edge A has zero length (a point) and falls onto B at t = 1/4", F(1, 4)),
    ("ee-both-zero-length-irrational", EE, [P([-1, 0, 3], 0, 0)] * 2 + [P(0, 0, 0)] * 2, None,
     C + "both edges are points; they meet where 3t^2 = 1", SQ3),
    ("ee-zero-length-near-miss-1e-30", EE, [P(1 + E30, 0, [1, -2])] * 2 + SEG, None,
     C + "zero-length edge crosses z = 0 at x = 1 + 1e-30, beside B's endpoint", None),
    ("ee-coplanar-for-all-t-sweep", EE,
     [P(0, 0, 0), P(1, 0, 0), P([2, -2], 1, 0), P([2, -2], -1, 0)], None,
     C + "all four points in z = 0 for all t; B sweeps to x = 1 at t = 1/2", F(1, 2)),
    ("ee-parallel-only-at-contact", EE,
     [P(0, 0, 0), P(1, 0, 0), P(F(1, 2), [F(-1, 2), 1], [F(-1, 2), 1]),
      P(F(3, 2), [-1, 2], [F(-1, 2), 1])], None,
     C + "B is at z = t - 1/2 and becomes parallel to A, overlapping it, exactly at t = 1/2",
     F(1, 2)),
    ("ee-degree4-crossing", EE, SEG + [P(0, -1, [F(1, 16), 0, 0, 0, -1]), P(0, 1, [F(1, 16), 0, 0, 0, -1])],
     None, C + "z = 1/16 - t^4: crossing at t = 1/2", F(1, 2)),
    ("ee-huge-translation-1e40", EE,
     scaled(SEG + [P(0, -1, [1, -2]), P(0, 1, [1, -2])], 1, (10 ** 40, -2 * 10 ** 40, 3 * 10 ** 40)),
     None, C + "ee-perpendicular-crossing translated by (1e40, -2e40, 3e40): t = 1/2", F(1, 2)),
    ("ee-t-junction", EE, SEG + [P(F(1, 2), [1, -2], 0), P(F(1, 2), [2, -2], 0)], None,
     C + "coplanar; endpoint b0 = (1/2, 1 - 2t, 0) reaches A's interior at t = 1/2", F(1, 2)),
    ("ee-dip-1e-60-close-roots", EE,
     SEG + [P(0, -1, [F(1, 4) - E30 * E30, -1, 1]), P(0, 1, [F(1, 4) - E30 * E30, -1, 1])], None,
     C + "B at z = (t - 1/2)^2 - 1e-60 crosses A twice, 2e-30 apart: first at 1/2 - 1e-30",
     F(1, 2) - E30),
    ("ee-endpoints-meet-irrational", EE, SEG + [P(1, 0, [1, 0, -2]), P(1, 1, [1, 0, -2])], None,
     C + "endpoint b0 = (1, 0, 1 - 2t^2) meets endpoint a1 at t = 1/sqrt(2)", SQ2),
    # ------------------------------------------------------------ vertex-edge
    ("ve-through-interior", VE, [P(F(1, 3), [1, -3], 0)] + SEG, None,
     C + "vertex crosses the edge interior at t = 1/3", F(1, 3)),
    ("ve-through-endpoint", VE, [P(1, [2, -3], 0)] + SEG, None,
     C + "vertex passes exactly through endpoint e1 at t = 2/3", F(2, 3)),
    ("ve-misses-endpoint-1e-30", VE, [P(1 + E30, [2, -3], 0)] + SEG, None,
     C + "vertex passes 1e-30 beyond endpoint e1", None),
    ("ve-collinear-sliding", VE, [P([3, -4], 0, 0)] + SEG, None,
     C + "vertex slides along the edge's line, reaches e1 at t = 1/2", F(1, 2)),
    ("ve-collinear-stops-1e-30-short", VE, [P([3 + E30, -2], 0, 0)] + SEG, None,
     C + "collinear approach stopping at x = 1 + 1e-30 at t = 1", None),
    ("ve-zero-length-edge-hit", VE, [P([1, -1], 0, 0), P(F(1, 2), 0, 0), P(F(1, 2), 0, 0)], None,
     C + "zero-length edge at x = 1/2; the vertex reaches it at t = 1/2", F(1, 2)),
    ("ve-zero-length-edge-near-miss", VE, [P([1, -1], E30, 0), P(F(1, 2), 0, 0), P(F(1, 2), 0, 0)],
     None, C + "zero-length edge; the vertex passes 1e-30 beside it", None),
    ("ve-grazing-at-t1-double-root", VE, [P(0, [1, -2, 1], 0)] + SEG, None,
     C + "y = (1 - t)^2: the vertex reaches the edge only at t = 1 (double root)", F(1)),
    ("ve-irrational", VE, [P(0, [1, 0, -2], 0)] + SEG, None,
     C + "y = 1 - 2t^2: contact at t = 1/sqrt(2)", SQ2),
    ("ve-vertex-is-endpoint", VE, [P([0, 1], [0, 0, 1], 1), P(-1, 0, 0), P([0, 1], [0, 0, 1], 1)],
     None, C + "the vertex equals endpoint e1 for all t", F(0)),
    ("ve-edge-shrinks-onto-vertex-at-t1", VE, [P(0, [1, -1], 0), P([-1, 1], 0, 0), P([1, -1], 0, 0)],
     None, C + "the edge shrinks to the point 0 exactly when the vertex arrives, t = 1", F(1)),
    ("ve-degree5", VE, [P(F(1, 2), [F(1, 32), 0, 0, 0, 0, -1], 0)] + SEG, None,
     C + "y = 1/32 - t^5: contact at t = 1/2", F(1, 2)),
    ("ve-both-moving-irrational", VE, [P(0, [F(1, 3), 0, -1], 0), P(-1, [0, 0, 1], 0), P(1, [0, 0, 1], 0)],
     None, C + "edge at y = t^2, vertex at y = 1/3 - t^2: t = 1/sqrt(6)", SQ6),
    # ------------------------------------------------------------ vertex-vertex
    ("vv-meet-at-third", VV, [P([1, -3], 2, 0), P(0, 2, 0)], None,
     C + "x = 1 - 3t reaches the static point at t = 1/3", F(1, 3)),
    ("vv-near-miss-1e-30", VV, [P([1, -3], 2, 0), P(0, 2, E30)], None,
     C + "the static point is 1e-30 off the path", None),
    ("vv-meet-irrational", VV, [P([1, 0, -2], 0, 0), P(0, 0, 0)], None,
     C + "x = 1 - 2t^2: meet at t = 1/sqrt(2)", SQ2),
    ("vv-coincident-for-all-t", VV, [P([1, 2], 3, [0, 0, 7])] * 2, None,
     C + "identical trajectories", F(0)),
    ("vv-coordinates-vanish-apart", VV, [P([1, -2], [1, -3], 0), P(0, 0, 0)], None,
     C + "x vanishes at t = 1/2, y at t = 1/3: never both", None),
    ("vv-meet-double-root", VV,
     [P([0, 1], [0, 0, 1], 1), P([F(1, 4), 0, 1], [F(1, 4), -1, 2], [F(5, 4), -1, 1])], None,
     C + "b = a + (t - 1/2)^2 (1, 1, 1): meet only at t = 1/2", F(1, 2)),
    ("vv-meet-at-t1", VV, [P([1, -1], 0, 0), P(0, 0, 0)], None, C + "meet at t = 1", F(1)),
    ("vv-degree6", VV, [P([F(1, 64), 0, 0, 0, 0, 0, -1], 0, 0), P(0, 0, 0)], None,
     C + "x = 1/64 - t^6: meet at t = 1/2", F(1, 2)),
    ("vv-degree12", VV, [P([F(1, 4096)] + [0] * 11 + [-1], 0, 0), P(0, 0, 0)], None,
     C + "x = 1/4096 - t^12 (degree 12): meet at t = 1/2", F(1, 2)),
    ("vv-tiny-1e-30", VV, [P([E30, -3 * E30], 0, 0), P(0, 0, 0)], None,
     C + "x = 1e-30 (1 - 3t): meet at t = 1/3", F(1, 3)),
    ("vv-huge-offset-1e30", VV, [P([10 ** 30 + 1, -3], 5 * 10 ** 30, 0), P(10 ** 30, 5 * 10 ** 30, 0)],
     None, C + "both points near (1e30, 5e30, 0); x difference 1 - 3t: t = 1/3", F(1, 3)),
    # ------------------------------------------------------------ sphere-sphere
    ("ss-approach", SS, [P(0, 0, 0), P([10, -10], 0, 0)], [1, 1],
     C + "|d| = 10 - 10t <= 2 from t = 4/5", F(4, 5)),
    ("ss-touching-at-t0", SS, [P(0, 0, 0), P([3, 1], 4, 0)], [2, 3],
     C + "|d| = |(3 + t, 4)| = 5 = ra + rb at t = 0, then apart", F(0)),
    ("ss-touching-at-t1", SS, [P(0, 0, 0), P([5, -1], 0, 0)], [2, 2], C + "|d| = 5 - t = 4 at t = 1", F(1)),
    ("ss-grazing-tangent", SS, [P(0, 0, 0), P(2, [F(1, 4), -1, 1], 0)], [1, 1],
     C + "|d|^2 = 4 + (t - 1/2)^4: the balls touch only at t = 1/2", F(1, 2)),
    ("ss-grazing-near-miss-1e-30", SS, [P(0, 0, 0), P(2 + E30, [F(1, 4), -1, 1], 0)], [1, 1],
     C + "|d| >= 2 + 1e-30 > ra + rb", None),
    ("ss-irrational", SS, [P(0, 0, 0), P([3, 0, -2], 0, 0)], [1, 1], C + "|d| = 3 - 2t^2 = 2 at 1/sqrt(2)", SQ2),
    ("ss-same-centre", SS, [P([1, 2], [0, 0, 3], 4)] * 2, [1, 2], C + "identical centre trajectories", F(0)),
    ("ss-overlapping-from-start", SS, [P(0, 0, 0), P(1, 0, [0, 5])], [1, 1],
     C + "|d| = 1 < 2 at t = 0", F(0)),
    ("ss-tiny-radii-meet", SS, [P(0, 0, 0), P([1, -2], 0, 0)], [E30, E30],
     C + "radii 1e-30: |1 - 2t| <= 2e-30 from t = 1/2 - 1e-30", F(1, 2) - E30),
    ("ss-tiny-radii-miss", SS, [P(0, 0, 0), P([1, -2], 3 * E30, 0)], [E30, E30],
     C + "radii 1e-30, centres pass at distance 3e-30 > 2e-30", None),
    ("ss-pythagorean-3d", SS, [P(0, 0, 0), P([4, -2], [6, -3], [12, -6])], [F(7, 2), F(7, 2)],
     C + "d = (2, 3, 6)(2 - t), |d| = 7 (2 - t) = 7 at t = 1", F(1)),
    ("ss-pythagorean-touching-all-t", SS, [P([0, 1], [0, 0, 1], [0, 0, 0, 1]),
                                           P([2, 1], [3, 0, 1], [6, 0, 0, 1])], [3, 4],
     C + "cb = ca + (2, 3, 6): |d| = 7 = ra + rb for all t", F(0)),
    ("ss-separating", SS, [P(0, 0, 0), P([3, 1], 0, 0)], [1, 1], C + "moving apart from |d| = 3", None),
    ("ss-grazing-irrational", SS, [P(0, 0, 0), P(2, Q4, 0)], [1, 1],
     C + "|d|^2 = 4 + (t^2 - 1/2)^4: touch only at t = 1/sqrt(2)", SQ2),
    ("ss-degree4-approach", SS, [P(0, 0, 0), P([F(33, 16), 0, 0, 0, -1], 0, 0)], [1, 1],
     C + "|d| = 33/16 - t^4 = 2 at t = 1/2", F(1, 2)),
    ("ss-radii-fraction-strings", SS, [P(0, 0, 0), P([5, -2], 0, 0)], ["7/3", "2/3"],
     C + "radii 7/3 + 2/3 = 3; |d| = 5 - 2t = 3 at t = 1", F(1)),
    ("ss-json-number-literals", SS, [P(0, 0, 0), P([Literal("0.6"), Literal("-0.6")], 0, 0)],
     [Literal("0.1"), Literal("0.2")],
     C + "JSON literals: 0.1 + 0.2 == 0.3 exactly; |d| = 0.6 - 0.6t = 0.3 at t = 1/2", F(1, 2)),
]
