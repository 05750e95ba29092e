"""Drawing conventions of the part drawings: sheet, line types, text, scales (ISO 128-2,
ISO 3098, ISO 5455); design choices, not catalog data."""

from __future__ import annotations


TOLERANCE_MM = 0.01        # a drawn dimension may differ from the STEP solid by at most this
DEFLECTION_MM = 0.01       # chord error when curves are drawn as polylines (invisible in print)
SHEET_MM = (250.0, 150.0)  # A4-landscape-like sheet the calculation sheet scales to its width
MARGIN_MM = 5.0            # sheet edge to frame
TITLE_H_MM = 27.0          # title block along the bottom: tolerance frames, notes, title rows
GENERAL_TOLERANCE = "ISO 2768-mK"  # general tolerances on the title block (HOUSING_RULES §4)
EDGE_NOTE = "edges ISO 13715 −0.3 +0.3"
GAP_MM = 4.0               # free space around a view (centre lines overshoot 3 mm into it)
VIEW_GAP_MM = 10.0         # between the front view and the side view's left dimension stack
DIM_SPACING_MM = 7.0       # between stacked parallel dimension lines: text height + clearance
EXT_GAP_MM, EXT_OVER_MM = 1.0, 2.0  # extension line: gap to the outline, overshoot of the line
HALF_DIM_PAST_AXIS_MM = 4.0  # a half dimension line runs this far past the axis (ISO 129-1)
ARROW_MM, ARROW_DEG = 2.5, 15.0     # closed filled arrowhead, 30° included angle
HATCH_MM, HATCH_DEG = 2.0, 45.0     # section hatching spacing on paper and angle
CENTRE_OVER_MM = 3.0       # centre lines run past the outline by this much
LANDING_MM = 3.0           # horizontal landing of a leader beyond its text
PT_PER_MM = 72.0 / 25.4
LINE_MM = {"visible": 0.7, "thin": 0.35, "hatch": 0.18}  # ISO 128-2 line group 0.7
TEXT_PT, TITLE_PT = 8.0, 9.0  # 8 pt ≈ 2.8 mm capitals: above the 2.5 mm ISO 3098 minimum
CHAIN_MM = (8.0, 1.0, 0.5, 1.0)  # long dash, gap, dot, gap (thin chain line, ISO 128-2 type 04)
DASH_MM = (3.0, 1.0)             # thin dashed line (ISO 128-2 type 02)
SCALES = (5.0, 2.0, 1.0, 1 / 2, 1 / 5, 1 / 10, 1 / 20)  # ISO 5455 preferred scales
PNG_DPI = 150
INK, HATCH_FILL = "#000000", "#E6E6E6"

DIAMETER_KEYS = ("outer_diameter_mm", "square_mm", "body_diameter_mm", "pilot_recess_mm",
                 "pilot_boss_diameter_mm", "gap_seal_journal_mm",
                 "pilot_diameter_mm", "spigot_recess_mm", "spigot_diameter_mm",
                 "hub_diameter_mm", "journal_diameter_mm", "bearing_seat_mm", "seal_recess_mm",
                 "bore_mm", "shaft_hole_mm", "relief_groove_floor_mm")
"""Part.dimensions keys drawn as diameters in the side view (those a part has)."""
OUTER_KEYS = ("outer_diameter_mm", "square_mm")
AXIAL_KEYS = ("front_z_mm", "pilot_floor_z_mm", "bearing_seat_z_mm", "shoulder_z_mm",
              "seal_z_mm", "relief_groove_z0_mm", "relief_groove_z1_mm")
"""Part.dimensions keys that are positions of faces along the axis from z = 0 (the mating
face): drawn as parallel dimensions from it."""
BORE_KEYS = ("bore_mm", "shaft_hole_mm")
