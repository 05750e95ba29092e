"""Views and annotations: the view along the axis, the half section, dimensions, bolt-circle
labels and the title strip."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import cadquery as cq
import numpy as np

from ..part import BoltCircle, Part
from .conventions import (ARROW_MM, CENTRE_OVER_MM, CHAIN_MM, DASH_MM, DIM_SPACING_MM, EXT_GAP_MM,
                          EXT_OVER_MM, GAP_MM, HALF_DIM_PAST_AXIS_MM, LANDING_MM, MARGIN_MM,
                          SHEET_MM, TEXT_PT, TITLE_H_MM, TITLE_PT, TOLERANCE_MM)
from .measure import hlr_polylines
from .dimensions import _agree, bolt_circle_label, Dimension, Measured
from .paper import clip_half, Sheet
from .layout import label_rows, Layout
from .running import draw_running, is_running


def _to_paper(lines: list[np.ndarray], origin, s: float) -> list[np.ndarray]:
    return [np.asarray(origin) + s * ln for ln in lines]


def draw_front(sheet: Sheet, solid: cq.Solid, m: Measured, lay: Layout,
               circles: list[tuple[BoltCircle, list]]) -> list[float]:
    """View from +Z (paper right = −Y, up = +X): outline, hidden edges, centre lines, bolt
    circles. Returns the view's paper box."""
    s, (cx, cy) = lay.scale, lay.front
    visible, hidden = hlr_polylines(solid, (0, 0, 1), (0, -1, 0))
    sheet.lines(_to_paper(hidden, lay.front, s), "thin", DASH_MM)
    sheet.lines(_to_paper(visible, lay.front, s), "visible")
    hu, hv = m.box.ylen / 2 * s, m.box.xlen / 2 * s
    o = CENTRE_OVER_MM
    sheet.lines([np.array([[cx - hu - o, cy], [cx + hu + o, cy]]),
                 np.array([[cx, cy - hv - o], [cx, cy + hv + o]])], "thin", CHAIN_MM)
    t = np.linspace(0, 2 * math.pi, 361)
    for bc, _ in circles:
        r = bc.diameter_mm / 2 * s
        sheet.lines([np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])], "thin",
                    CHAIN_MM)
    return [cx - hu, cy - hv, cx + hu, cy + hv]


def draw_side(sheet: Sheet, solid: cq.Solid, m: Measured, lay: Layout,
              circles: list[tuple[BoltCircle, list]]) -> list[float]:
    """Half section seen from +Y (paper right = +Z, up = +X): upper half cut at y = 0 and
    hatched, lower half the outside view; the axis as a chain line."""
    s, origin = lay.scale, (lay.side_x0 - m.box.zmin * lay.scale, lay.cy)
    reach = max(abs(m.box.xmin), abs(m.box.xmax), abs(m.box.ymin), abs(m.box.ymax)) + 1.0
    kept = solid.intersect(cq.Solid.makeBox(2 * reach, reach, m.box.zlen + 2,
                                            cq.Vector(-reach, -reach, m.box.zmin - 1)))
    for face in m.upper:
        sheet.hatch(_to_paper(face, origin, s))
    cut_view, _ = hlr_polylines(kept, (0, 1, 0), (0, 0, 1))
    outside, _ = hlr_polylines(solid, (0, 1, 0), (0, 0, 1))
    upper = [p for ln in cut_view for p in clip_half(ln, True)]
    lower = [p for ln in outside for p in clip_half(ln, False)]
    sheet.lines(_to_paper(upper + lower, origin, s), "visible")
    x0, x1 = lay.side_x0, lay.side_x0 + m.box.zlen * s
    o = CENTRE_OVER_MM
    sheet.lines([np.array([[x0 - o, lay.cy], [x1 + o, lay.cy]])], "thin", CHAIN_MM)
    _cut_hole_axes(sheet, m, lay, circles)
    r = m.box.xlen / 2 * s
    return [x0, lay.cy - r, x1, lay.cy + r]


SECTION_LETTER = "A"


def label_section(sheet: Sheet, m: Measured, lay: Layout) -> str:
    """ISO 128-44 designation of the half section: on the front view the cutting plane's end
    (a short thick stroke where the thin centre line leaves the outline, at x > 0) with an
    arrow in the direction of sight (towards −Y, paper right) and the letter; under the side
    view its name. Returns the name, e.g. ``A–A``."""
    s, (cx, cy) = lay.scale, lay.front
    top = cy + m.box.xlen / 2 * s
    sheet.lines([np.array([[cx, top + 0.6], [cx, top + 3.4]])], "visible")
    tip = (cx + 4.5, top + 3.4)
    sheet.lines([np.array([[cx, top + 3.4], tip])], "thin")
    sheet.arrow(tip, (cx, top + 3.4))
    sheet.text(tip[0] + 1.0, top + 2.0, SECTION_LETTER, ha="left", va="center")
    name = f"{SECTION_LETTER}–{SECTION_LETTER}"
    x_mid = lay.side_x0 + m.box.zlen * s / 2
    sheet.text(x_mid, cy - m.box.xlen / 2 * s - 3.2, name, va="center")
    return name


def _cut_hole_axes(sheet: Sheet, m: Measured, lay: Layout, circles) -> None:
    """Centre lines of bolt holes the section plane cuts (hole centre on +X)."""
    s = lay.scale
    for bc, centres in circles:
        for x, y in centres:
            if abs(y) > TOLERANCE_MM or x <= 0:
                continue
            zs = [(h.z0, h.z1) for h in m.holes if _agree(h.x, x) and _agree(h.y, y)]
            z0, z1 = min(z for z, _ in zs), max(z for _, z in zs)
            px = lay.side_x0 + (np.array([z0, z1]) - m.box.zmin) * s
            py = lay.cy + x * s
            sheet.lines([np.array([[px[0] - CENTRE_OVER_MM, py], [px[1] + CENTRE_OVER_MM, py]])],
                        "thin", CHAIN_MM)


def _top_at(m: Measured, z: float) -> float:
    """Largest x [mm] of the section at axial position z (where an extension line starts)."""
    xs = [p[1] for face in m.upper for ring in face for p in ring if abs(p[0] - z) < 1e-6]
    return max(xs, default=m.box.xmax)


def dimension_side_view(sheet: Sheet, m: Measured, lay: Layout, dims: list[Dimension]) -> None:
    """Stack the diameters left and right of the side view (smallest nearest) and the
    lengths above it (shortest nearest)."""
    s = lay.scale
    x_left, x_right = lay.side_x0, lay.side_x0 + m.box.zlen * s
    for side, sign, edge in (("left", -1, x_left), ("right", 1, x_right)):
        stack = sorted((d for d in dims if d.side == side), key=lambda d: d.measured_mm)
        for k, d in enumerate(stack, start=1):
            end_z = d.z0 if side == "left" else d.z1
            start = lay.side_x0 + (end_z - m.box.zmin) * s
            _diameter(sheet, d, lay, start, edge + sign * k * DIM_SPACING_MM)
    top = draw_running(sheet, dims, m, lay.side_x0, lay.cy, s, _top_at)
    parallel = sorted((d for d in dims if d.kind == "length" and not is_running(d)),
                      key=lambda d: d.measured_mm)
    for k, d in enumerate(parallel, start=1):
        _length(sheet, d, m, lay, top + k * DIM_SPACING_MM - 3.0)


def _diameter(sheet: Sheet, d: Dimension, lay: Layout, start_x: float, x: float) -> None:
    """Vertical dimension line at paper x: full (two arrows) for external diameters, a half
    dimension line past the axis for internal ones; text left of the line, read from the
    right (ISO 129-1)."""
    r = d.measured_mm / 2 * lay.scale
    ends = [1, -1] if d.external else [1]
    towards = 1 if x > start_x else -1
    for e in ends:
        y = lay.cy + e * r
        start = start_x + towards * EXT_GAP_MM
        sheet.lines([np.array([[start, y], [x + towards * EXT_OVER_MM, y]])], "thin")
    y_low = lay.cy - r if d.external else lay.cy - HALF_DIM_PAST_AXIS_MM
    sheet.lines([np.array([[x, y_low], [x, lay.cy + r]])], "thin")
    sheet.arrow((x, lay.cy + r), (x, lay.cy))
    if d.external:
        sheet.arrow((x, lay.cy - r), (x, lay.cy))
    # internal: centred on the half line, but kept below its arrow so the text stays
    # clear of the extension lines of larger diameters further out
    width = sheet.text_size(d.label)[0]
    y_text = lay.cy if d.external else min(lay.cy + r / 2, lay.cy + r - ARROW_MM - width / 2)
    sheet.text(x - 0.8, y_text, d.label, rotation=90, ha="center", va="bottom")


def _length(sheet: Sheet, d: Dimension, m: Measured, lay: Layout, y: float) -> None:
    """Horizontal dimension line above the side view; extension lines from the outline."""
    s = lay.scale
    xs = [lay.side_x0 + (z - m.box.zmin) * s for z in (d.z0, d.z1)]
    for z, x in zip((d.z0, d.z1), xs):
        y0 = lay.cy + _top_at(m, z) * s + EXT_GAP_MM
        sheet.lines([np.array([[x, y0], [x, y + EXT_OVER_MM]])], "thin")
    room = xs[1] - xs[0]
    width = sheet.text_size(d.label)[0]
    if room >= 2 * ARROW_MM + 1.0:  # arrows inside, pointing out
        sheet.lines([np.array([[xs[0], y], [xs[1], y]])], "thin")
        sheet.arrow((xs[0], y), (xs[1], y))
        sheet.arrow((xs[1], y), (xs[0], y))
    else:  # too short: arrows outside, pointing in (ISO 129-1)
        reach = ARROW_MM + 2.0
        sheet.lines([np.array([[xs[0] - reach, y], [xs[1] + reach, y]])], "thin")
        sheet.arrow((xs[0], y), (xs[0] - reach, y))
        sheet.arrow((xs[1], y), (xs[1] + reach, y))
    if width + 2.0 <= room:
        sheet.text((xs[0] + xs[1]) / 2, y + 0.8, d.label, va="bottom")
    else:  # text beyond the right end of the line
        sheet.text(xs[1] + ARROW_MM + 3.0, y + 0.8, d.label, ha="left", va="bottom")


def label_bolt_circles(sheet: Sheet, m: Measured, lay: Layout,
                       circles: list[tuple[BoltCircle, list]]) -> None:
    """Labels on landings above and below the front view (outer rows' landings reach further
    right so their leaders pass the inner rows), each with a leader to the hole of its circle
    nearest the landing's end; circles go to rows by least total leader length."""
    if not circles:
        return
    s, (cx, cy) = lay.scale, lay.front
    hv = m.box.xlen / 2 * s
    labels = [bolt_circle_label(bc) for bc, _ in circles]
    width = max(sheet.text_size(t)[0] for t in labels)
    text_h = lay.row_mm - 2.0
    ends = []
    for side, row in label_rows(len(circles)):
        y = (cy + hv + GAP_MM + row * lay.row_mm if side > 0
             else cy - hv - GAP_MM - text_h - 1.0 - row * lay.row_mm)
        ends.append((lay.label_x0 + width + LANDING_MM + row * lay.row_mm, y))
    holes = [[(cx - y * s, cy + x * s) for x, y in centres] for _, centres in circles]

    def nearest(i, end):
        return min(holes[i], key=lambda p: math.dist(p, end))

    order = min(itertools.permutations(range(len(circles))),
                key=lambda o: sum(math.dist(nearest(i, e), e) for i, e in zip(o, ends)))
    for i, end in zip(order, ends):
        bc = circles[i][0]
        sheet.lines([np.array([[lay.label_x0, end[1]], end])], "thin")
        hole = np.array(nearest(i, end))
        d = hole - end
        tip = hole - d / np.linalg.norm(d) * bc.hole_diameter_mm / 2 * s
        sheet.lines([np.array([end, tip])], "thin")
        sheet.arrow(tip, end)
        sheet.text(lay.label_x0, end[1] + 0.6, labels[i], ha="left", va="bottom")


def title_strip(sheet: Sheet, part: Part, step_path: Path, scale: float,
                notes: list[str] | None = None) -> None:
    """Frame and title block (ISO 7200 fields that apply): a notes row (general tolerances,
    edges, material, mass, fits) over the title row (part, scale, units, projection, source
    file). Cells are as wide as their text; the file name is shortened from the left if the
    row is full."""
    w, h = SHEET_MM
    m, th, pad = MARGIN_MM, TITLE_H_MM, 2.0
    row = th / 3
    frame = np.array([[m, m], [w - m, m], [w - m, h - m], [m, h - m], [m, m]])
    sheet.lines([frame, np.array([[m, m + th], [w - m, m + th]]),
                 np.array([[m, m + row], [w - m, m + row]]),
                 np.array([[m, m + 2 * row], [w - m, m + 2 * row]])], "thin")
    from .gdt import tolerance_row
    if not tolerance_row(sheet, part, m + pad, w - m - pad, m + 2 * row, row):
        sheet.text(m + pad, m + row * 2.5, "geometric tolerances: none stated", size=TEXT_PT,
                   ha="left")
    text = " · ".join(notes or [])
    while notes and sheet.text_size(text, TEXT_PT)[0] > w - 2 * m - 2 * pad and len(text) > 8:
        text = text[:-6] + " …"
    sheet.text(m + pad, m + row * 1.5, text, size=TEXT_PT, ha="left")
    ratio = f"{scale:g}:1" if scale >= 1 else f"1:{1 / scale:g}"
    cells = [part.name, f"scale {ratio} at {w:g} × {h:g} mm", "dimensions in mm",
             "first-angle projection"]
    x = m
    for i, txt in enumerate(cells):
        weight = "bold" if i == 0 else "normal"
        sheet.text(x + pad, m + row / 2, txt, size=TITLE_PT, ha="left", fontweight=weight)
        x += sheet.text_size(txt, TITLE_PT, weight)[0] + 2 * pad
        sheet.lines([np.array([[x, m], [x, m + row]])], "thin")
    name = f"from {Path(step_path).name}"
    while sheet.text_size(name, TITLE_PT)[0] > w - m - x - 2 * pad and len(name) > 8:
        name = "from …" + name[7:]
    sheet.text(x + pad, m + row / 2, name, size=TITLE_PT, ha="left")
