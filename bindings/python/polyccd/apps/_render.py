"""Pictures of scenes: render_scene draws bodies at a time t with their touching features
highlighted, into a PNG (matplotlib, Agg backend: no display needed).

Drawing is floating point and only for looking at: the pose of each body at t is taken
exactly from its Motion (Motion.position of the body origin and of the three unit
points gives R(r(t)) and o(t) exactly), then rounded to float once, and every vertex or
ball centre is moved in float with numpy. The geometry comes from the shapes' float
arrays (polyccd.apps' LoadedMesh.vertices / .triangles, LoadedSpheres.centers /
.radii); other shapes need them passed in `geometry`.
"""
from fractions import Fraction
from pathlib import Path

import numpy as np

from .. import InputError
from ..extras import need
from ._annotate import add_legend, place_labels, tidy_ticks, touching_line
from ._files import replace_file
from ._draw_geometry import (BODY_COLORS, HIGHLIGHT, _arrays, _clip_segments, _clip_to_box,
                             _contacts, _decimate, _edges_of, _float_pose, _parts, _shade, _time)


# ------------------------------------------------------------------------- drawing ---

class _Placed:
    """One body at time t: world float arrays of its geometry and of its features."""

    def __init__(self, index, shape, motion, name, geometry, t):
        self.index, self.name, self.motion = index, name, motion
        self.kind, a, b = _arrays(shape, geometry, index)
        lo, hi = a.min(axis=0), a.max(axis=0)
        self.body_center = (lo + hi) / 2  # in body coordinates
        R, o = _float_pose(motion, t)
        if self.kind == "mesh":
            self.vertices, self.triangles = a @ R.T + o, b
            self.center = (self.vertices.min(axis=0) + self.vertices.max(axis=0)) / 2
        else:
            self.centers, self.radii = a @ R.T + o, b
            self.center = self.centers.mean(axis=0)
        self._edges = None

    def trajectory(self, samples=41):
        """The world path of the body's box centre over [0, 1] (None when stationary)."""
        if self.motion is None:
            return None
        points = []
        for t in np.linspace(0, 1, samples):
            R, o = _float_pose(self.motion, Fraction(float(t)))
            points.append(R @ self.body_center + o)
        points = np.array(points)
        return points if np.ptp(points, axis=0).max() > 0 else None

    def edges(self):
        if self._edges is None:
            self._edges = _edges_of(self.triangles)
        return self._edges

    def feature_points(self, kind, k):
        """The world points of one feature (for the zoom box and the markers)."""
        if kind == "sphere":
            return self.centers[[k]]
        if kind == "vertex":
            return self.vertices[[k]]
        if kind == "edge":
            return self.vertices[self.edges()[k]]
        return self.vertices[self.triangles[k]]

    def lo_hi(self):
        if self.kind == "mesh":
            return self.vertices.min(axis=0), self.vertices.max(axis=0)
        return ((self.centers - self.radii[:, None]).min(axis=0),
                (self.centers + self.radii[:, None]).max(axis=0))


def _samples(body, kind, k):
    """Points spread over one feature (corners, and a barycentric grid on a triangle or
    edge), for locating where features meet."""
    pts = body.feature_points(kind, k)
    if kind == "sphere":
        return pts, body.radii[k]
    if len(pts) == 1:
        return pts, 0.0
    s = np.linspace(0, 1, 12)
    if len(pts) == 2:
        return pts[0] + s[:, None] * (pts[1] - pts[0]), 0.0
    u, v = np.meshgrid(s, s)
    inside = u + v <= 1
    u, v = u[inside], v[inside]
    return pts[0] + u[:, None] * (pts[1] - pts[0]) + v[:, None] * (pts[2] - pts[0]), 0.0


def _contact_point(placed, features):
    """About where the touching features meet: the middle of the closest pair of sample
    points of features of different bodies (ball surfaces, not centres), else the mean
    of the features' points."""
    groups = {}
    for b, kind, k in features:
        pts, r = _samples(placed[b], kind, k)
        groups.setdefault(b, []).append((pts, r))
    if len(groups) < 2:
        return np.concatenate([p for g in groups.values() for p, _ in g]).mean(axis=0)
    best, where = np.inf, None
    items = sorted(groups.items())
    for i, (_, ga) in enumerate(items):
        for _, gb in items[i + 1:]:
            for pa, ra in ga:
                for pb, rb in gb:
                    d = np.linalg.norm(pa[:, None] - pb[None], axis=2)
                    m = np.unravel_index(d.argmin(), d.shape)
                    if d[m] - ra - rb < best:
                        best = d[m] - ra - rb
                        a, bb = pa[m[0]], pb[m[1]]
                        # the point between the ball surfaces (ra / (ra + rb) of the way)
                        w = ra / (ra + rb) if ra + rb > 0 else 0.5
                        where = a + (bb - a) * (w if ra + rb > 0 else 0.5)
    return where


def _view(placed, features):
    """(elev, azim): look across the line between the first two bodies' centres (the
    contact, when known, is then seen from the side)."""
    if len(placed) < 2:
        return 20.0, -60.0
    d = placed[1].center - placed[0].center
    if np.linalg.norm(d[:2]) < 1e-12 * (1 + np.linalg.norm(d)):
        return 10.0, -60.0
    azim = np.degrees(np.arctan2(d[1], d[0])) - 90.0
    return 28.0, float(azim)


def _set_box(ax, center, half):
    ax.set_xlim(center[0] - half, center[0] + half)
    ax.set_ylim(center[1] - half, center[1] + half)
    ax.set_zlim(center[2] - half, center[2] + half)
    ax.set_box_aspect((1, 1, 1))


def _points_per_unit(ax, fig, half):
    """Approximate marker scale: points per data unit in an axes showing 2*half."""
    bbox = ax.get_position()
    width_pt = min(bbox.width * fig.get_figwidth(), bbox.height * fig.get_figheight()) * 72
    return width_pt / (2 * half) * 0.75  # the 3D box is drawn smaller than the axes


def _draw(ax, fig, placed, features, center, half, *, max_triangles, labels, zoomed,
          paths=None):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
    import matplotlib.colors as mcolors

    ax.computed_zorder = False  # highlights drawn last, on top of the bodies
    lo, hi = center - half, center + half
    polys, colors = [], []
    ppu = _points_per_unit(ax, fig, half)
    for body in placed:
        rgb = np.array(mcolors.to_rgb(BODY_COLORS[body.index % len(BODY_COLORS)]))
        if body.kind == "mesh":
            v, tri = body.vertices, body.triangles
            if zoomed:  # 3D axes do not clip: cut the surface to the box ourselves
                p = _clip_to_box(v, tri, lo, hi, max_triangles)
            else:
                v, tri = _decimate(v, tri, max_triangles)
                p = v[tri]
            if len(p):
                polys.append(p)
                colors.append(_shade(rgb, np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])))
        else:
            c, r = body.centers, body.radii
            if zoomed:
                inside = np.all((c >= lo - r[:, None]) & (c <= hi + r[:, None]), axis=1)
                c, r = c[inside], r[inside]
            if len(c):
                ax.scatter(c[:, 0], c[:, 1], c[:, 2], s=(r * ppu) ** 2 * np.pi,
                           color=rgb, alpha=(0.35 if len(body.radii) > 200 else 0.75)
                           if zoomed else 0.8, edgecolors="none",
                           depthshade=True, zorder=1)
    if polys:
        faces = np.concatenate(colors)
        # In the zoom the pieces are big on screen: edges in the face colour close the
        # anti-aliasing seams between them.
        poly = Poly3DCollection(np.concatenate(polys), facecolors=faces,
                                edgecolors=faces if zoomed else "none",
                                linewidths=0.4 if zoomed else 0, zorder=1)
        ax.add_collection3d(poly)

    # The touching features, always drawn in full and on top.
    red_polys, red_lines, red_points, balls, label_at = [], [], [], [], []
    for b, kind, k in features:
        body = placed[b]
        pts = body.feature_points(kind, k)
        if kind == "triangle":
            red_polys.append(pts)
            red_lines.extend([[pts[0], pts[1]], [pts[1], pts[2]], [pts[2], pts[0]]])
        elif kind == "edge":
            red_lines.append(pts)
        elif kind == "vertex":
            red_points.append(pts[0])
        else:
            balls.append((b, k, pts[0], body.radii[k]))
    if zoomed:  # features drawn in full would run out of the zoom box
        if red_polys:
            red_polys = list(_clip_to_box(np.array(red_polys), None, lo, hi, 20000))
        if red_lines:
            red_lines = list(_clip_segments(np.array(red_lines), lo, hi))
    if red_polys:
        ax.add_collection3d(Poly3DCollection(red_polys, facecolors=HIGHLIGHT, alpha=0.85,
                                             edgecolors="none", zorder=5))
    if red_lines:
        ax.add_collection3d(Line3DCollection(red_lines, colors=HIGHLIGHT,
                                             linewidths=3.5 if zoomed else 2.0, zorder=6))
    if red_points:
        p = np.array(red_points)
        ax.scatter(p[:, 0], p[:, 1], p[:, 2], s=60 if zoomed else 30, c=HIGHLIGHT,
                   edgecolors="black", linewidths=1.0, depthshade=False, zorder=7)
    for b, k, c, r in balls:
        if zoomed:  # true balls in data units, so tangency shows as tangency
            u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 32), np.linspace(0, np.pi, 16))
            ax.plot_surface(c[0] + r * np.cos(u) * np.sin(v), c[1] + r * np.sin(u) * np.sin(v),
                            c[2] + r * np.cos(v), color=HIGHLIGHT, alpha=0.9, linewidth=0,
                            shade=True, zorder=7)
        else:
            ax.scatter([c[0]], [c[1]], [c[2]], s=(r * ppu) ** 2 * np.pi, c=HIGHLIGHT,
                       edgecolors="black", linewidths=1.2, alpha=0.95, depthshade=False,
                       zorder=7)
        if zoomed and labels is not None and labels.get(b) is not None:
            label_at.append((b, c[0], c[1], c[2] + r * 1.1, labels[b](k)))
    for body, path in zip(placed, paths or ()):
        if path is not None:  # where the body's centre goes over [0, 1]
            color = np.array(mcolors.to_rgb(BODY_COLORS[body.index % len(BODY_COLORS)])) * 0.6
            ax.plot(path[:, 0], path[:, 1], path[:, 2], "--", color=color, linewidth=1.5,
                    zorder=4)
            ax.scatter(*path[0], marker="o", s=25, color=color, depthshade=False, zorder=4)
            ax.scatter(*path[-1], marker="s", s=30, color=color, depthshade=False, zorder=4)
    if not zoomed and features:  # small features stay visible in the full view
        marks = np.array([placed[b].feature_points(kind, k).mean(axis=0)
                          for b, kind, k in features])
        ax.scatter(marks[:, 0], marks[:, 1], marks[:, 2], s=260, facecolors="none",
                   edgecolors=HIGHLIGHT, linewidths=2.0, depthshade=False, zorder=9)
    _set_box(ax, center, half)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    tidy_ticks(ax)
    # Labels that would overlap are left out (the first features' first): their count.
    return place_labels(ax, fig, label_at) if label_at else 0


def _label_functions(labels):
    """{body index: k -> text} from AtomInfo-like objects (with .label) or callables."""
    out = {}
    for i, value in (labels or {}).items():
        if value is None:
            continue
        out[i] = value.label if hasattr(value, "label") else value
    return out


def render_scene(bodies, t, contacts, path, title=None, *, geometry=None, labels=None,
                 size=(1600, 800), dpi=100, zoom=True, max_triangles=20000, view=None,
                 zoom_half=None, trajectories=True):
    """Writes a PNG of the bodies at time t with the touching features highlighted;
    returns the path.

    bodies: polyccd.Body objects (or (shape, motion[, name]) tuples) whose shapes carry
    float geometry (polyccd.data loaders), or with geometry={index: {...}}.
    t: a number, str or ContactTime (its exact value, else its enclosure's middle).
    contacts: a SceneResult, PairResults, or (body index, (kind, k)) items, kind in
    "vertex", "edge" (k indexes Mesh.edges), "triangle", "sphere"; None: nothing.
    Touching triangles are red (outlined), edges thick red lines, vertices red points,
    balls red with a black rim; all drawn on top of the bodies. With zoom (and contacts),
    a second panel shows the region of the contacts (labels: {body index: AtomInfo or
    k -> text} names the touching balls there). Meshes above max_triangles are shown
    decimated (vertex clustering); features are always drawn from the full geometry.
    trajectories: the path of each moving body's centre over [0, 1] is drawn dashed
    (a dot at t = 0, a square at t = 1) in the full view."""
    need("polyccd.apps.to_png", "interop", "matplotlib")
    from matplotlib.figure import Figure
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    placed = [_Placed(i, *_parts(b, i), geometry, t) for i, b in enumerate(bodies)]
    if not placed:
        raise InputError("bodies: nothing to draw")
    features = _contacts(contacts, len(placed))
    label_fns = _label_functions(labels)

    paths = [b.trajectory() for b in placed] if trajectories else None
    lows, highs = zip(*(b.lo_hi() for b in placed))
    lo, hi = np.min(lows, axis=0), np.max(highs, axis=0)
    for track in paths or ():
        if track is not None:
            lo, hi = np.minimum(lo, track.min(axis=0)), np.maximum(hi, track.max(axis=0))
    center, half = (lo + hi) / 2, (hi - lo).max() / 2 * 1.02
    panels = 2 if zoom and features else 1
    width, height = size
    fig = Figure(figsize=(width / dpi, height / dpi), dpi=dpi)
    FigureCanvasAgg(fig)
    elev, azim = view if view is not None else _view(placed, features)

    ax = fig.add_subplot(1, panels, 1, projection="3d")
    ax.view_init(elev=elev, azim=azim)
    _draw(ax, fig, placed, features, center, half, max_triangles=max_triangles,
          labels=label_fns, zoomed=False, paths=paths)
    ax.set_title("scene", fontsize=10)
    if panels == 2:
        c = _contact_point(placed, features)
        balls = [placed[b].radii[k] for b, kind, k in features if kind == "sphere"]
        zh = zoom_half if zoom_half is not None else max(half * 0.15, 3.5 * max(balls, default=0))
        zx = fig.add_subplot(1, 2, 2, projection="3d")
        zx.view_init(elev=elev, azim=azim)
        hidden = _draw(zx, fig, placed, features, c, zh, max_triangles=max_triangles,
                       labels=label_fns, zoomed=True)
        zx.set_title("contact region (zoom)" + (f"; {hidden} more touching balls not labelled"
                                                if hidden else ""), fontsize=10)
    t_exact = _time(t)
    head = title or "polyccd scene"
    # The title names the bodies in contact; the legend shows every colour (a robot has a
    # dozen or more meshes: the touching ones first, the rest counted).
    fig.suptitle("\n".join([head, f"{touching_line(placed, features)}   (drawn at t = "
                                   f"{float(t_exact):.12g}, {len(features)} features in red)"]),
                 fontsize=11)
    add_legend(fig, placed, features, BODY_COLORS)
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.07, top=0.9, wspace=0.02)
    fmt = Path(path).suffix[1:].lower() or "png"  # a temporary file, renamed (_files.py)
    return replace_file(path, lambda f: fig.savefig(f, dpi=dpi, format=fmt))
