"""Superimposed running dimensions (ISO 129-1): the axial positions of the functional faces,
measured from the mating face z = 0, on one dimension line with an origin circle, each value
written along its extension line. Values too close to share a line go to a second line above.
One or two lines replace a stack of parallel dimensions, so the side view keeps its scale."""

from __future__ import annotations

import numpy as np

from .conventions import DIM_SPACING_MM, EXT_GAP_MM, EXT_OVER_MM
from .dimensions import Dimension, Measured
from .paper import Sheet

ORIGIN_R_MM = 1.0      # origin circle of a running dimension (ISO 129-1)
TEXT_OFFSET_MM = 0.6   # value text beside its extension line
TEXT_LIFT_MM = 1.0     # value text starts this far above the dimension line
ROW_GAP_MM = 2.0       # between the top of one line's values and the next line


def is_running(d: Dimension) -> bool:
    """A length measured from the mating face z = 0 (not the overall length)."""
    return d.kind == "length" and abs(d.z0) < 1e-9 and d.key != "overall_length_mm"


def running_rows(sheet: Sheet, dims: list[Dimension], m: Measured, scale: float
                 ) -> list[list[Dimension]]:
    """The running dimensions split into lines: a value goes to the lowest line where its
    text clears the other texts of that line and no extension line of a higher line crosses
    it (extension lines run up to their own line)."""
    h = sheet.text_size("0")[1]
    rows: list[list[tuple[float, Dimension]]] = []
    for d in sorted((d for d in dims if is_running(d)), key=lambda d: d.z1):
        x = (d.z1 - m.box.zmin) * scale
        box = (x - TEXT_OFFSET_MM - h, x - TEXT_OFFSET_MM + 0.01)
        for k, row in enumerate(rows):
            same = all(not (box[0] < xo + 0.4 and xo - TEXT_OFFSET_MM - h - 0.4 < box[1])
                       for xo, _ in row)
            # this line's extension line crosses every lower line's texts
            lower = all(not (xo - TEXT_OFFSET_MM - h - 0.4 < x < xo + 0.4)
                        for below in rows[:k] for xo, _ in below)
            if same and lower:
                row.append((x, d))
                break
        else:  # a new line above the others
            rows.append([(x, d)])
    return [[d for _, d in row] for row in rows]


def _widest(sheet: Sheet, dims: list[Dimension]) -> float:
    return max((sheet.text_size(d.label)[0] for d in dims if is_running(d)), default=0.0)


def row_pitch(sheet: Sheet, dims: list[Dimension]) -> float:
    """Height of one running line with its values [mm]."""
    return max(DIM_SPACING_MM, TEXT_LIFT_MM + _widest(sheet, dims) + ROW_GAP_MM)


def _row_y(k: int, pitch: float) -> float:
    """Height of running line k above the side view's top [mm]."""
    return DIM_SPACING_MM + k * pitch


def height(sheet: Sheet, dims: list[Dimension], m: Measured, scale: float) -> float:
    """Paper height [mm] from the side view's top to the top of the last line's values."""
    n = len(running_rows(sheet, dims, m, scale))
    if not n:
        return 0.0
    return _row_y(n - 1, row_pitch(sheet, dims)) + TEXT_LIFT_MM + _widest(sheet, dims)


def draw_running(sheet: Sheet, dims: list[Dimension], m: Measured, side_x0: float, cy: float,
                 scale: float, top_at) -> float:
    """Draw the running lines above the side view; returns the paper y of the top of the
    last line's values (the side view's top when there are none)."""
    rows = running_rows(sheet, dims, m, scale)
    top = cy + m.box.xmax * scale
    if not rows:
        return top
    pitch = row_pitch(sheet, dims)
    origin_x = side_x0 + (0.0 - m.box.zmin) * scale
    t = np.linspace(0, 2 * np.pi, 37)
    ys = [top + _row_y(k, pitch) for k in range(len(rows))]
    y0 = cy + top_at(m, 0.0) * scale + EXT_GAP_MM  # the origin's extension line, once
    sheet.lines([np.array([[origin_x, y0], [origin_x, ys[-1] + EXT_OVER_MM]])], "thin")
    for row, y in zip(rows, ys):
        xs = [side_x0 + (d.z1 - m.box.zmin) * scale for d in row]
        sheet.lines([np.array([[origin_x, y], [max(xs), y]]),
                     np.column_stack([origin_x + ORIGIN_R_MM * np.cos(t),
                                      y + ORIGIN_R_MM * np.sin(t)])], "thin")
        for d, x in zip(row, xs):
            y_ext = cy + top_at(m, d.z1) * scale + EXT_GAP_MM
            sheet.lines([np.array([[x, y_ext], [x, y + EXT_OVER_MM]])], "thin")
            sheet.arrow((x, y), (origin_x, y))
            sheet.text(x - TEXT_OFFSET_MM, y + TEXT_LIFT_MM, d.label, rotation=90,
                       ha="left", va="bottom")
    return ys[-1] + TEXT_LIFT_MM + _widest(sheet, dims)
