"""The words on a scene picture (render_scene, _render.py): the title naming the touching
bodies, a legend of colour swatches, atom labels that do not overlap, and sparse tick
labels. Only for looking at: nothing here decides anything."""
import numpy as np

LEGEND_MAX = 8     # bodies named in the legend; the others are counted in one entry
LABELS_MAX = 6     # labelled balls in the zoom panel; the others are counted in its title
TICKS = 4          # tick labels per axis at most (more collide in the corners)
LABEL_PT = 8       # font size of the labels, in points


def touching_names(placed, features):
    """The names of the bodies with a touching feature, in body order."""
    indices = sorted({b for b, _, _ in features})
    return [placed[b].name for b in indices]


def touching_line(placed, features):
    """'touching (red): A and B' naming the bodies in contact ('' without contacts)."""
    names = touching_names(placed, features)
    if not names:
        return "no contact drawn"
    if len(names) > 4:
        names = names[:3] + [f"{len(names) - 3} more bodies"]
    shown = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    return f"touching (red): {shown}"


def add_legend(fig, placed, features, colors):
    """A legend of colour swatches at the bottom of the figure: the touching bodies
    first, then the others, at most LEGEND_MAX, the rest counted in a last entry."""
    from matplotlib.patches import Patch
    touching = {b for b, _, _ in features}
    order = sorted(placed, key=lambda p: (p.index not in touching, p.index))
    shown = order[:LEGEND_MAX] if len(order) <= LEGEND_MAX else order[:LEGEND_MAX - 1]
    handles = [Patch(facecolor=colors[p.index % len(colors)], edgecolor="black", linewidth=0.5,
                     label=p.name) for p in shown]
    if len(shown) < len(order):
        handles.append(Patch(facecolor="none", edgecolor="none",
                             label=f"... and {len(order) - len(shown)} more bodies"))
    if features:
        handles.append(Patch(facecolor="#e8001c", edgecolor="black", linewidth=0.5,
                             label="touching features"))
    fig.legend(handles=handles, loc="lower center", ncol=min(len(handles), 5), fontsize=9,
               frameon=False, handlelength=1.2, columnspacing=1.5)


def tidy_ticks(ax):
    """At most TICKS tick labels per axis, in a small font, so that the labels of two axes
    meeting in a corner of the 3D box do not run into each other."""
    from matplotlib.ticker import MaxNLocator
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(nbins=TICKS - 1, prune="both"))
    ax.tick_params(labelsize=8, pad=1)


def _round_robin(candidates):
    """The candidates (body, ...) taken in turn from each body, each body's in order, so
    that both sides of a contact get labels before a third ball of one side does."""
    by_body = {}
    for c in candidates:
        by_body.setdefault(c[0], []).append(c)
    queues = list(by_body.values())
    out = []
    while any(queues):
        for q in queues:
            if q:
                out.append(q.pop(0))
    return out


def place_labels(ax, fig, candidates):
    """Writes the labels (body, x, y, z, text) that fit without overlapping one another on
    the screen, at most LABELS_MAX, taken in turn from each body; returns how many were
    left out. Call after the axes' limits and view are set."""
    from mpl_toolkits.mplot3d import proj3d
    width_px = LABEL_PT * fig.dpi / 72
    taken, skipped = [], 0
    for _, x, y, z, text in _round_robin(candidates):
        if len(taken) >= LABELS_MAX:
            skipped += 1
            continue
        u, v, _ = proj3d.proj_transform(x, y, z, ax.get_proj())
        px, py = ax.transData.transform((u, v))
        box = np.array([px, py - width_px * 0.7, px + 0.62 * width_px * (len(text) + 1),
                        py + width_px * 0.7])
        if any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in taken):
            skipped += 1
            continue
        taken.append(box)
        ax.text(x, y, z, f" {text}", fontsize=LABEL_PT, zorder=8,
                bbox=dict(boxstyle="round,pad=0.15", facecolor="white", alpha=0.75,
                          edgecolor="none"))
    return skipped
