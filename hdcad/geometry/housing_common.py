"""Helpers the housing families share: bearing and seal rows, hole-ring checks, design
constants for screws in clearance holes.

Catalog data (seed tables) and standard data are kept apart from design choices: every number
that is not in a table is a named constant below, and the parts' notes list each one.
"""

from __future__ import annotations

import math

from ..catalog import Catalog

BEARING_TABLE = "deep_groove_bearing_iso15"   # ISO 15 60xx rows (catalog, standard data)
SEAL_TABLE = "shaft_seal_iso6194"             # ISO 6194-1 / DIN 3760 rows (catalog)

# ---------------------------------------------------------------------------------------------
# Design choices (not catalog or standard data); each is printed in the Part notes.
# ---------------------------------------------------------------------------------------------
EDGE_MARGIN_MM = 1.5       # least ligament between a hole and any other edge (outer, pilot, bore, neighbour)
CBORE_WALL_MIN_MM = 0.5    # least wall between a counterbore and the 3 mm spigot recess: sizes
#                            20/25 leave 0.75/1.0 mm with DIN 974-1 counterbores on FD-2 φI
SHAFT_CLEARANCE_MM = 1.0   # radial clearance of the shaft hole: the WG shaft turns in the casing
SEAL_DEPTH_ALLOWANCE_MM = 0.3  # seal bore deeper than b so the seal seats on the shoulder
CBORE_SINK_MM = 0.5        # screw head sits this far below the outer face (gear sits on it)
MIN_FLOOR_MM = 3.0         # least material below a blind tapped hole
EDGE_FACTOR = 1.5          # hole centre ≥ 1.5·d from the outer edge (HOUSING_RULES §4)
TAP_RUNOUT_PITCHES = 3.0   # blind tap drill deeper than the usable thread by 3·P (HOUSING_RULES §4)
PILOT_LEAD_IN_MM = 1.0     # axial length of the 20° lead-in on pilots and spigots (HOUSING_RULES §4)


def whole_mm(need_mm: float) -> float:
    """A plate's least thickness rounded up to a whole millimetre [mm]: plates are ordered
    and drawn in whole millimetres, and a computed least value (a drill point's 1.26 mm)
    would print as 18.6618 on the drawing."""
    return float(math.ceil(need_mm))


def table_value(table: dict, key, what: str):
    if key not in table:
        raise ValueError(f"{what} {key!r} is not in hdcad.geometry.standards' table; "
                         f"known: {', '.join(map(str, table))}")
    return table[key]


def bearing_dimensions(catalog: Catalog, designation: str) -> tuple[float, float, float]:
    """Bore d, outside diameter D and width B [mm] of a 60xx deep groove ball bearing.

    References
    ----------
    ISO 15:2017, diameter series 0: catalog table ``deep_groove_bearing_iso15``.
    """
    row = catalog.find(BEARING_TABLE, model=str(designation))
    if row is None:
        known = ", ".join(r["model"] for r in catalog.rows(BEARING_TABLE))
        raise ValueError(f"bearing {designation!r} is not in catalog table {BEARING_TABLE}; "
                         f"known: {known}")
    return row["d_mm"], row["D_mm"], row["B_mm"]


def seal_dimensions(catalog: Catalog, shaft_mm: float) -> tuple[float, float]:
    """Housing bore d2 and width b [mm] of the rotary shaft lip seal for shaft d1 [mm].

    References
    ----------
    ISO 6194-1:1982 / DIN 3760:1996: catalog table ``shaft_seal_iso6194`` (one size per d1).
    """
    row = catalog.find(SEAL_TABLE, d1_mm=float(shaft_mm))
    if row is None:
        known = ", ".join(f"{r['d1_mm']:g}" for r in catalog.rows(SEAL_TABLE))
        raise ValueError(f"no shaft seal for a {shaft_mm:g} mm shaft in catalog table "
                         f"{SEAL_TABLE}; shafts: {known}")
    return row["d2_mm"], row["b_mm"]


def check_ring(label: str, ring_d: float, count: int, hole_d: float, inner_d: float,
                outer_d: float, margin: float = EDGE_MARGIN_MM) -> None:
    """ValueError unless the holes lie in the annulus inner_d…outer_d and clear each other,
    each by ``margin``."""
    r, half, m = ring_d / 2, hole_d / 2, margin
    if r - half - m < inner_d / 2 or r + half + m > outer_d / 2:
        raise ValueError(f"{label}: Ø{hole_d:g} holes on Ø{ring_d:g} do not fit in the annulus "
                         f"Ø{inner_d:g}…Ø{outer_d:g} with {m:g} mm ligaments; the bolt circle "
                         f"must lie within Ø{inner_d + hole_d + 2 * m:g}…"
                         f"Ø{outer_d - hole_d - 2 * m:g}")
    pitch = 2 * r * math.sin(math.pi / count) if count > 1 else math.inf
    if pitch < hole_d + m:
        raise ValueError(f"{label}: {count} holes Ø{hole_d:g} on Ø{ring_d:g} overlap their "
                         f"neighbours (pitch {pitch:.2f} mm < {hole_d + m:g} mm)")


def slack(x: float, y: float, radius: float, holes: list[tuple[float, float, float]]) -> float:
    """Least ligament between a hole (x, y, radius) and the holes (x, y, radius)."""
    return min((math.hypot(x - hx, y - hy) - radius - hr for hx, hy, hr in holes),
               default=math.inf)
