"""The words on the demo's pictures (polyccd.apps._annotate): a legend of colour swatches
named by body (no hex codes), a title naming the touching bodies, labels that do not
overlap on the screen, few tick labels. The pictures themselves are looked at by a
person (docs/cli.md, `polyccd demo`); these check the rules that keep them readable."""
import re
from types import SimpleNamespace

import numpy as np
import pytest

pytest.importorskip("matplotlib")
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from polyccd.apps import _annotate  # noqa: E402
from polyccd.apps._draw_geometry import BODY_COLORS  # noqa: E402


def _placed(*names):
    return [SimpleNamespace(index=i, name=n) for i, n in enumerate(names)]


def test_title_names_the_touching_bodies():
    placed = _placed("panda_link0", "panda_hand", "plate")
    assert _annotate.touching_line(placed, [(2, "triangle", 0), (1, "vertex", 3)]) \
        == "touching (red): panda_hand and plate"
    assert _annotate.touching_line(placed, []) == "no contact drawn"
    many = _placed(*[f"b{i}" for i in range(6)])
    assert _annotate.touching_line(many, [(i, "vertex", 0) for i in range(6)]) \
        == "touching (red): b0, b1, b2 and 3 more bodies"


def test_legend_is_swatches_touching_bodies_first():
    fig = Figure()
    placed = _placed(*[f"link{i}" for i in range(12)], "plate")
    _annotate.add_legend(fig, placed, [(12, "triangle", 0), (5, "edge", 1)], BODY_COLORS)
    (legend,) = fig.legends
    texts = [t.get_text() for t in legend.get_texts()]
    assert texts[:2] == ["link5", "plate"], texts
    assert len(texts) == _annotate.LEGEND_MAX + 1 and texts[-2] == "... and 6 more bodies"
    assert texts[-1] == "touching features"
    assert not any(re.search(r"#[0-9a-fA-F]{6}", t) for t in texts), texts
    patches = legend.get_patches()
    assert all(isinstance(p, Patch) for p in patches)
    colour = patches[1].get_facecolor()[:3]      # plate: body 12
    assert np.allclose(colour, [int(BODY_COLORS[12 % 6][k:k + 2], 16) / 255 for k in (1, 3, 5)])


def test_labels_do_not_overlap_and_alternate_bodies():
    fig = Figure(figsize=(8, 8), dpi=100)
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    ax.set_xlim(0, 10), ax.set_ylim(0, 10), ax.set_zlim(0, 10)
    # Five labels of body 0 at one point, two of body 1 far away, one of body 0 far away.
    candidates = ([(0, 5, 5, 5, f"A:ASP{i} OD1") for i in range(5)]
                  + [(1, 0, 0, 9, "017-200 O18"), (1, 9, 9, 1, "017-200 C30"), (0, 9, 0, 1, "A:GLY48 O")])
    skipped = _annotate.place_labels(ax, fig, candidates)
    shown = [t.get_text().strip() for t in ax.texts]
    assert shown[:2] == ["A:ASP0 OD1", "017-200 O18"], shown     # both bodies first
    assert set(shown) == {"A:ASP0 OD1", "017-200 O18", "017-200 C30", "A:GLY48 O"}, shown
    assert skipped == 4 and len(shown) + skipped == len(candidates)
    # On the rendered figure, no two label boxes overlap.
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    renderer = FigureCanvasAgg(fig).get_renderer()
    boxes = [t.get_window_extent(renderer) for t in ax.texts]
    assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


def test_at_most_a_few_tick_labels_per_axis():
    fig = Figure()
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    ax.set_xlim(-0.75, 0.75), ax.set_ylim(0, 1000), ax.set_zlim(0.38, 0.52)
    _annotate.tidy_ticks(ax)
    for axis, (lo, hi) in ((ax.xaxis, (-0.75, 0.75)), (ax.yaxis, (0, 1000)), (ax.zaxis, (0.38, 0.52))):
        ticks = [t for t in axis.get_major_locator().tick_values(lo, hi) if lo <= t <= hi]
        assert 2 <= len(ticks) <= _annotate.TICKS, ticks
