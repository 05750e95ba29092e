"""Layout: the ISO 5455 scale and where each view, dimension stack and label goes."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from .conventions import (CENTRE_OVER_MM, DIM_SPACING_MM, GAP_MM, LANDING_MM, MARGIN_MM, SCALES,
                          SHEET_MM, TITLE_H_MM, TOLERANCE_MM, VIEW_GAP_MM)
from .measure import _inside
from .dimensions import _agree, Dimension, Measured
from . import running
from .paper import Sheet
from .running import is_running


@dataclass
class Layout:
    scale: float
    front: tuple[float, float]   # paper position of the axis in the front view
    side_x0: float               # paper x of z = zmin in the side view
    cy: float                    # paper y of the axis in both views (first-angle alignment)
    row_mm: float                # pitch of the bolt-circle label rows
    label_x0: float              # paper x where the bolt-circle labels start


def label_rows(n: int) -> list[tuple[int, int]]:
    """(side, row) of each bolt-circle label: alternately above (+1) and below (−1) the
    front view, stacked away from it."""
    return [(1 if i % 2 == 0 else -1, i // 2) for i in range(n)]


def _extents(sheet: Sheet, m: Measured, dims: list[Dimension], labels: list[str], s: float
             ) -> tuple[float, float, float, float]:
    """Width of the front block and of the side block, height above and below the axis
    [mm] at scale ``s``."""
    half_u, half_v = m.box.ylen / 2 * s, m.box.xlen / 2 * s
    row = sheet.text_size("Ø0")[1] + 2.0
    label_w = max((sheet.text_size(t)[0] for t in labels), default=0.0)
    front_w = max(2 * half_u, label_w + LANDING_MM + row * len(labels))
    stacks = DIM_SPACING_MM * (_count(dims, "left") + _count(dims, "right"))
    side_w = stacks + m.box.zlen * s
    sides = [side for side, _ in label_rows(len(labels))]
    parallel = sum(d.kind == "length" and not is_running(d) for d in dims)
    above = max(half_v + GAP_MM + row * sides.count(1),
                half_v + running.height(sheet, dims, m, s) + DIM_SPACING_MM * parallel + row)
    below = max(half_v + (GAP_MM + row * sides.count(-1) if -1 in sides else CENTRE_OVER_MM + 1),
                half_v + row + 1.5)  # the section's name under the side view
    return front_w, side_w, above, below


def _count(dims: list[Dimension], side: str) -> int:
    return sum(d.side == side for d in dims)


def layout(sheet: Sheet, m: Measured, dims: list[Dimension], labels: list[str]) -> Layout:
    """Largest ISO 5455 scale that fits; the drawing centred in the frame above the title."""
    w, h = SHEET_MM
    room_w = w - 2 * MARGIN_MM - 2 * GAP_MM
    room_h = h - 2 * MARGIN_MM - TITLE_H_MM - 2.0
    for s in SCALES:
        front_w, side_w, above, below = _extents(sheet, m, dims, labels, s)
        if front_w + VIEW_GAP_MM + side_w <= room_w and above + below <= room_h:
            break
    else:
        raise ValueError(f"part {m.box.xlen:g} × {m.box.zlen:g} mm does not fit the sheet at "
                         f"scale 1:{1 / SCALES[-1]:g}")
    left = MARGIN_MM + GAP_MM + (room_w - front_w - VIEW_GAP_MM - side_w) / 2
    cx = left + max(front_w, m.box.ylen * s) / 2
    cy = MARGIN_MM + TITLE_H_MM + 1.0 + (room_h - above - below) / 2 + below
    side_x0 = left + front_w + VIEW_GAP_MM + DIM_SPACING_MM * _count(dims, "left")
    return Layout(s, (cx, cy), side_x0, cy, sheet.text_size("Ø0")[1] + 2.0, left)


def assign_sides(dims: list[Dimension], m: Measured) -> None:
    """Put each diameter left or right of the side view, where its extension line runs
    through no material; ties go to the nearer end, then to the shorter stack."""
    ties = []
    for d in (d for d in dims if d.kind == "diameter"):
        left = _clear(m, d.measured_mm / 2, m.box.zmin - 1, d.z0)
        right = _clear(m, d.measured_mm / 2, d.z1, m.box.zmax + 1)
        if left and right and _agree(d.z0 - m.box.zmin, m.box.zmax - d.z1):
            ties.append(d)
        elif left and right:
            d.side = "left" if d.z0 - m.box.zmin < m.box.zmax - d.z1 else "right"
        else:
            d.side = "right" if right else "left"
    for d in sorted(ties, key=lambda d: d.measured_mm):
        d.side = "left" if _count(dims, "left") <= _count(dims, "right") else "right"


def _clear(m: Measured, r: float, z0: float, z1: float) -> bool:
    """True when the line x = r, z0 < z < z1 passes through no material (it may run along
    a surface)."""
    z = np.linspace(z0, z1, 64)[1:-1]
    eps = 10 * TOLERANCE_MM
    above = _inside(m.upper, np.column_stack([z, np.full_like(z, r + eps)]))
    below = _inside(m.upper, np.column_stack([z, np.full_like(z, r - eps)]))
    return not np.any(above & below)
