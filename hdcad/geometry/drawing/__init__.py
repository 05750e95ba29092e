"""Part drawings from the STEP geometry: a view along the axis and a half section.

``part_drawing(step_path, part, svg_path, png_path)`` re-imports the STEP file and draws what it
contains, never the in-memory shape: on the left the view along the axis (from +Z, hidden
edges thin dashed, bolt circles as chain lines with their labels), on the right a half section
through the axis (upper half cut in the XZ plane and hatched, lower half the outside view), in
first-angle projection (the view from +Y stands to the right of the view from +Z) on one
250 × 150 mm sheet with a title strip.

The dimensions come from ``part.dimensions`` and ``part.bolt_circles`` but each one is measured
on the re-imported solid first; a value that differs from the geometry by more than
``TOLERANCE_MM`` raises ValueError, so the drawing cannot state a size the STEP file lacks.
Diameters of internal features use half dimension lines (one arrow, the line running a little
past the axis), as ISO 129-1 allows for half sections.

Text is written as glyph paths (as in ``hdcad.report.plots``) so WeasyPrint needs no font;
matplotlib puts each string in an SVG comment before its glyphs, which is how tests read them.

References
----------
ISO 128-2 (line types: continuous wide for visible outlines, thin dashed for hidden edges,
thin chain for centre lines and pitch circles), ISO 128-50 (section hatching at 45°),
ISO 128-44/ISO 129-1 (half sections; dimension, extension and half dimension lines, closed
filled arrowheads), ISO 5456-2 (first-angle projection, also JIS B 0001), ISO 5455 (scales).
"""

from __future__ import annotations

import time
from pathlib import Path

from ..part import Part
from .conventions import EDGE_NOTE, GENERAL_TOLERANCE
from .measure import load_step_solid, section_extent
from .dimensions import (bolt_circle_holes, bolt_circle_label, diameter_dimensions, Dimension,
                         length_dimensions, Measured, outer_dimension, axial_dimensions)
from .paper import clip_half, Sheet
from .layout import assign_sides, layout
from .views import (dimension_side_view, draw_front, draw_side, label_bolt_circles, label_section,
                    title_strip)


def verified_dimensions(part: Part, m: Measured) -> list[Dimension]:
    """The part's main dimensions, each checked against the measured solid."""
    return ([outer_dimension(part, m)] + diameter_dimensions(part, m)
            + length_dimensions(part, m) + axial_dimensions(part, m))


def drawing_notes(part: Part, mass_kg: float | None = None, material: str = "") -> list[str]:
    """The notes row of the title block: general tolerances, edges, material, mass, fits."""
    notes = [f"general tolerances {GENERAL_TOLERANCE}", EDGE_NOTE]
    if part.material or material:
        notes.append(f"material {part.material or material}")
    if mass_kg is not None:
        notes.append(f"mass {mass_kg:.3g} kg")
    notes += [f"Ø{f.nominal_mm:g} {f.code} ({f.deviations_um[0] / 1000:+.3f}/"
              f"{f.deviations_um[1] / 1000:+.3f})" for f in part.fits]
    return notes


def part_drawing(step_path: Path, part: Part, svg_path: Path, png_path: Path | None = None,
                 mass_kg: float | None = None, material: str = "") -> dict:
    """Draw ``part`` as its STEP file holds it: view along the axis and half section with the
    main dimensions and bolt circles, to SVG (and PNG when ``png_path`` is given).

    Parameters
    ----------
    step_path : the part's STEP file [mm], axis on Z, mating face at z = 0
    part : the Part record whose ``dimensions`` [mm] and ``bolt_circles`` are drawn
    svg_path, png_path : output files (PNG at PNG_DPI)
    mass_kg, material : printed in the title block's notes row (with the general tolerance,
        the edge note and the part's ISO 286 fits)

    Returns
    -------
    dict with ``svg``, ``png`` (paths or None), ``views`` (name, paper box [mm]),
    ``dimensions`` (label, stated and measured value [mm]), ``bolt_circles`` (label, count
    found), ``section_extent_mm`` ({"x": [min, max], "z": [min, max]} of the cut through the
    axis), ``scale``, ``text_boxes_mm`` and ``time_s``.

    Raises
    ------
    ValueError when a stated dimension or bolt circle differs from the STEP geometry by more
    than TOLERANCE_MM [mm], or the file holds other than one solid.
    """
    started = time.perf_counter()
    solid = load_step_solid(step_path)
    m = Measured.of(solid)
    dims = verified_dimensions(part, m)
    circles = [(bc, bolt_circle_holes(part, bc, m)) for bc in part.bolt_circles]
    assign_sides(dims, m)
    sheet = Sheet()
    lay = layout(sheet, m, dims, [bolt_circle_label(bc) for bc in part.bolt_circles])
    views = [{"name": "front (from +Z)", "box_mm": draw_front(sheet, solid, m, lay, circles)},
             {"name": "side (half section in XZ, from +Y)",
              "box_mm": draw_side(sheet, solid, m, lay, circles)}]
    views[1]["section"] = label_section(sheet, m, lay)
    dimension_side_view(sheet, m, lay, dims)
    label_bolt_circles(sheet, m, lay, circles)
    title_strip(sheet, part, step_path, lay.scale, drawing_notes(part, mass_kg, material))
    boxes = sheet.text_boxes()
    sheet.save(Path(svg_path), None if png_path is None else Path(png_path))
    return {"svg": str(svg_path), "png": None if png_path is None else str(png_path),
            "views": views, "dimensions": [d.as_dict() for d in dims],
            "bolt_circles": [{"name": bc.name, "label": bolt_circle_label(bc),
                              "count_found": len(c)} for bc, c in circles],
            "section_extent_mm": section_extent(m.section), "scale": lay.scale,
            "text_boxes_mm": boxes, "time_s": time.perf_counter() - started}


__all__ = ["part_drawing", "drawing_notes", "verified_dimensions", "clip_half"]
