"""Paper: a matplotlib axes in sheet millimetres with the drawing primitives (lines of the
ISO 128-2 types, arrowheads, text as glyph paths, ISO 128-50 hatching)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from .conventions import (ARROW_DEG, ARROW_MM, HATCH_DEG, HATCH_FILL, HATCH_MM, INK, LINE_MM,
                          PNG_DPI, PT_PER_MM, SHEET_MM, TEXT_PT)


def _line_kw(kind: str, pattern: tuple[float, ...] | None = None) -> dict:
    width = LINE_MM[kind] * PT_PER_MM
    kw = {"color": INK, "linewidth": width, "capstyle": "butt"}
    if pattern:  # matplotlib scales dash lengths by the line width
        kw["linestyle"] = (0, tuple(p * PT_PER_MM / width for p in pattern))
    return kw


class Sheet:
    """One drawing sheet: Figure + axes whose data units are millimetres on paper."""

    def __init__(self):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        w, h = SHEET_MM
        self.fig = Figure(figsize=(w / 25.4, h / 25.4))
        self.canvas = FigureCanvasAgg(self.fig)
        self.ax = self.fig.add_axes((0, 0, 1, 1))
        self.ax.set_xlim(0, w)
        self.ax.set_ylim(0, h)
        self.ax.set_axis_off()
        self.texts: list = []

    def text_size(self, s: str, size: float = TEXT_PT, weight: str = "normal"
                  ) -> tuple[float, float]:
        """Width and height [mm] of ``s`` set horizontally."""
        from matplotlib.font_manager import FontProperties
        renderer = self.canvas.get_renderer()
        font = FontProperties(size=size, weight=weight)
        w, h, _ = renderer.get_text_width_height_descent(s, font, False)
        return w / self.fig.dpi * 25.4, h / self.fig.dpi * 25.4

    def lines(self, polylines, kind="visible", pattern=None) -> None:
        from matplotlib.collections import LineCollection
        if polylines:
            self.ax.add_collection(LineCollection(polylines, **_line_kw(kind, pattern)))

    def arrow(self, tip, towards) -> None:
        """Closed filled arrowhead with its tip at ``tip``, pointing away from ``towards``."""
        from matplotlib.patches import Polygon
        tip, back = np.asarray(tip, float), np.asarray(towards, float)
        d = (tip - back) / np.linalg.norm(tip - back)
        n = np.array([-d[1], d[0]]) * ARROW_MM * math.tan(math.radians(ARROW_DEG))
        base = tip - d * ARROW_MM
        self.ax.add_patch(Polygon([tip, base + n, base - n], closed=True, facecolor=INK,
                                  edgecolor="none"))

    def text(self, x, y, s, size=TEXT_PT, rotation=0.0, ha="center", va="center", **kw):
        t = self.ax.text(x, y, s, fontsize=size, rotation=rotation, ha=ha, va=va,
                         rotation_mode="anchor", color=INK, **kw)
        self.texts.append(t)
        return t

    def hatch(self, rings_paper: list[np.ndarray]) -> None:
        """Fill one section face light grey and hatch it at HATCH_DEG."""
        from matplotlib.patches import PathPatch
        from matplotlib.path import Path as MplPath
        path = MplPath.make_compound_path(*[MplPath(r, closed=True) for r in
                                            [np.vstack([r, r[:1]]) for r in rings_paper]])
        self.ax.add_patch(PathPatch(path, facecolor=HATCH_FILL, edgecolor="none"))
        self.lines(hatch_segments(rings_paper, HATCH_MM, HATCH_DEG), "hatch")

    def text_boxes(self) -> list[list[float]]:
        """Final text boxes [x0, y0, x1, y1] in sheet mm."""
        renderer, k = self.canvas.get_renderer(), 25.4 / self.fig.dpi
        return [[b.x0 * k, b.y0 * k, b.x1 * k, b.y1 * k]
                for b in (t.get_window_extent(renderer) for t in self.texts)]

    def save(self, svg_path: Path, png_path: Path | None) -> None:
        self.fig.savefig(svg_path, format="svg", metadata={"Date": None})
        if png_path is not None:
            self.fig.savefig(png_path, format="png", dpi=PNG_DPI, facecolor="white")


def hatch_segments(rings: list[np.ndarray], spacing: float, angle_deg: float
                   ) -> list[np.ndarray]:
    """Hatch lines inside the polygon ``rings`` (even-odd rule) on a fixed grid, so faces of
    one part hatch in step."""
    a = math.radians(angle_deg)
    rot = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])  # to hatch frame
    edges = [(r @ rot.T, np.roll(r @ rot.T, -1, axis=0)) for r in rings]
    ys = np.concatenate([p[:, 1] for p, _ in edges])
    out = []
    for c in np.arange(math.ceil(ys.min() / spacing), math.floor(ys.max() / spacing) + 1):
        y = c * spacing
        xs = []
        for p, q in edges:
            cross = (p[:, 1] <= y) != (q[:, 1] <= y)
            t = (y - p[cross, 1]) / (q[cross, 1] - p[cross, 1])
            xs += list(p[cross, 0] + t * (q[cross, 0] - p[cross, 0]))
        xs.sort()
        out += [np.array([[x0, y], [x1, y]]) @ rot for x0, x1 in zip(xs[::2], xs[1::2])]
    return out


def clip_half(polyline: np.ndarray, upper: bool) -> list[np.ndarray]:
    """Parts of a 2-D polyline with y ≥ 0 (upper) or y ≤ 0, cut exactly at y = 0."""
    side = polyline[:, 1] * (1.0 if upper else -1.0)
    pieces, current = [], []
    for i, (p, h) in enumerate(zip(polyline, side)):
        if i and (h < 0) != (side[i - 1] < 0):  # the segment crosses or touches the axis
            prev = polyline[i - 1]
            current.append(prev + (p - prev) * (side[i - 1] / (side[i - 1] - h)))
            if h < 0:
                pieces.append(current)
                current = []
        if h >= 0:
            current.append(p)
    pieces.append(current)
    return [np.array(piece) for piece in pieces if len(piece) > 1]
