"""The geometric-tolerance row of the title block: ISO 1101 feature control frames (symbol,
tolerance, datum) with the feature each applies to, and the datum letters (ISO 5459)."""

from __future__ import annotations

import numpy as np

from ..part import Part
from .conventions import TEXT_PT

# ISO 1101 symbols as glyphs the drawing font (DejaVu Sans) has: ⊥ for ⟂ and ⊕ for ⌖,
# which it lacks (they printed as empty boxes); a test checks every symbol is in the font
SYMBOLS = {"coaxiality": "◎", "runout": "↗", "axial runout": "↗", "perpendicularity": "⊥",
           "parallelism": "∥", "flatness": "⏥", "position": "⊕", "cylindricity": "○"}
"""ISO 1101 symbols of the characteristics the parts carry."""
DIAMETER_ZONE = ("coaxiality", "position")  # cylindrical tolerance zone: value shown as Ø


def frame_cells(t) -> list[str]:
    """The cells of one frame: symbol, tolerance, datum reference (ISO 1101)."""
    value = f"{'Ø' if t.characteristic in DIAMETER_ZONE else ''}{t.value_mm:g}"
    return [SYMBOLS.get(t.characteristic, t.characteristic), value] + \
        ([t.datums] if t.datums else [])


def _box(sheet, x: float, y: float, w: float, h: float) -> None:
    sheet.lines([np.array([[x, y], [x + w, y], [x + w, y + h], [x, y + h], [x, y]])], "thin")


def tolerance_row(sheet, part: Part, x0: float, x1: float, y: float, h: float) -> int:
    """Draw datums then frames between paper x0 and x1 in the row of height h at y; returns
    how many tolerances were drawn (the rest are in results.json and the sheet)."""
    pad, cell_h, x, drawn = 1.2, h - 2.4, x0, 0
    items = ([("datum", t) for t in part.tolerances if t.characteristic == "datum"]
             + [("frame", t) for t in part.tolerances if t.characteristic != "datum"])
    for kind, t in items:
        cells = [t.datums] if kind == "datum" else frame_cells(t)
        widths = [sheet.text_size(c, TEXT_PT)[0] + 2 * pad for c in cells]
        label = t.feature
        need = sum(widths) + pad + sheet.text_size(label, TEXT_PT)[0] + 3 * pad
        if x + need > x1:
            break
        cx = x
        for c, wd in zip(cells, widths):
            _box(sheet, cx, y + 1.2, wd, cell_h)
            sheet.text(cx + wd / 2, y + h / 2, c, size=TEXT_PT)
            cx += wd
        sheet.text(cx + pad, y + h / 2, label, size=TEXT_PT, ha="left")
        x = cx + pad + sheet.text_size(label, TEXT_PT)[0] + 3 * pad
        drawn += 1
    return drawn
