"""Casing half of an FD-…-2 component set (harmonic differential gear).

Seed 001 p.315 (handling notes): when the FD-2 component set is used as a differential, its
casings and bearings follow the FD-0 unit. Each casing half is bolted to one circular spline
(S or D) and turns with it, carries the user's gear or pulley on its outer face, and holds a
support bearing (table 311-1 column Q) on the wave-generator shaft.

cq_warehouse style: ``FDCasingHalf.sizes(catalog)`` lists the sizes with an FD-0 (311-1) and
an FD-2 (312-1) row; ``FDCasingHalf(size, catalog, options, side)`` checks the request and
raises ValueError naming what is allowed; ``build()`` returns a :class:`Part` with the axis on
Z, the face that meets the circular spline at z = 0 and the body towards +z.

Layout along +z (T = thickness, s = spigot-recess depth):
  z = 0 … p          pilot recess Ø FD-2 φA (H7), p = FD-2 B + C/2 − running_gap/2
  z = p … p + Bb     bearing seat Ø D of bearing Q (ISO 15), open towards the spline
  z = p + Bb …       shoulder with the shaft hole Ø d + 2 × clearance
  … z = T − s        oil-seal recess Ø D2 × (b + allowance) (ISO 6194-1 / DIN 3760)
  z = T − s … T      gear/pulley spigot recess Ø FD-0 φB (H7)
Through the floor: J clearance holes (ISO 273 medium) on FD-2 φI for the spline screws,
counterbored for ISO 4762 heads from the outer face; L tap-drill holes for FD-0 M on φK; an
axial M10×1 oil fill/level hole.

Catalog data (seed tables) and standard data are kept apart from design choices: every number
that is not in a seed table is a named constant below, and the Part notes list each one.
"""

from __future__ import annotations

import math

from ..catalog import Catalog
from ..checks.bolts import MIN_ENGAGEMENT
from ..design_options import DesignOptions
from .part import BoltCircle, Part
from .primitives import cylinder, polar, ring_points, single_solid
from .standards import (DIN_974_1_CBORE_MM, ISO_273_MEDIUM_MM, ISO_4762_HEAD_MM,
                        ISO_4762_LENGTHS_MM, TAP_DRILL_MM, thread_diameter)

BEARING_TABLE = "deep_groove_bearing_iso15"   # ISO 15 60xx rows (catalog, standard data)
SEAL_TABLE = "shaft_seal_iso6194"             # ISO 6194-1 / DIN 3760 rows (catalog)

OIL_PLUG_THREAD = "M10×1"
OIL_PLUG_TAP_DRILL_MM = 9.0
"""Oil fill/level hole: ISO 261 fine thread M10×1, tap drill 9.0 mm (ISO 2306: d − P)."""

# ---------------------------------------------------------------------------------------------
# Design choices (not catalog or standard data); each is printed in the Part notes.
# ---------------------------------------------------------------------------------------------
EDGE_MARGIN_MM = 1.5       # least ligament between a hole and another edge (as in flanges.py)
CBORE_WALL_MIN_MM = 0.5    # least wall between a counterbore and the 3 mm spigot recess: sizes
#                            20/25 leave 0.75/1.0 mm with DIN 974-1 counterbores on FD-2 φI
SHAFT_CLEARANCE_MM = 1.0   # radial clearance of the shaft hole: the WG shaft turns in the casing
SPIGOT_DEPTH_MM = 3.0      # gear/pulley centring recess; no standard depth exists
SEAL_DEPTH_ALLOWANCE_MM = 0.3  # seal bore deeper than b so the seal seats on the shoulder
CBORE_SINK_MM = 0.5        # screw head sits this far below the outer face (gear sits on it)
MIN_FLOOR_MM = 3.0         # least material below a blind tapped hole
PLUG_ANGLE_STEP_DEG = 0.5  # search step for the oil-hole angle between the bolt holes
COLORS = {"S": (0.62, 0.66, 0.72), "D": (0.52, 0.58, 0.68)}


def _table_value(table: dict, key, what: str):
    if key not in table:
        raise ValueError(f"{what} {key!r} is not in hdcad.geometry.fd_casing's table; "
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


def _check_ring(label: str, ring_d: float, count: int, hole_d: float, inner_d: float,
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


def _slack(x: float, y: float, radius: float, holes: list[tuple[float, float, float]]) -> float:
    """Least ligament between a hole (x, y, radius) and the holes (x, y, radius)."""
    return min((math.hypot(x - hx, y - hy) - radius - hr for hx, hy, hr in holes),
               default=math.inf)


class FDCasingHalf:
    """One casing half (side S or D) of an FD-…-2 used as a differential; see module doc."""

    FD0, FD2, OIL = "fd0_dimensions", "fd2_dimensions", "fd_oil_level"
    SIDES = ("S", "D")
    NEEDED = {FD0: ("A_mm", "B_H7_mm", "D_mm", "K_mm", "L_count", "M_thread", "M_depth_mm",
                    "Q_bearing"),
              FD2: ("A_g7_mm", "B_mm", "C_mm", "D_mm", "E_mm", "H_mm", "I_mm", "J_count",
                    "K_thread", "K_depth_mm")}

    def __init__(self, size: int, catalog: Catalog, options: DesignOptions | None = None,
                 side: str = "S"):
        self.options = options or DesignOptions()
        if side not in self.SIDES:
            raise ValueError(f"side {side!r} is not a circular spline; allowed: S, D")
        if size not in self.sizes(catalog):
            raise ValueError(f"FD size {size!r} needs a row in tables 311-1 ({self.FD0}) and "
                             f"312-1 ({self.FD2}); allowed sizes: "
                             f"{', '.join(map(str, self.sizes(catalog)))}")
        self.size, self.side = size, side
        self.label = f"FD-{size}-2 casing half {side}"
        self.fd0 = self._row(catalog, self.FD0)
        self.fd2 = self._row(catalog, self.FD2)
        oil = catalog.find(self.OIL, size=size)
        if oil is None or oil.get("A_mm") is None:
            raise ValueError(f"{self.label}: oil level A (table 315-1, {self.OIL}) is missing")
        self.oil_level = float(oil["A_mm"])
        self._standard_parts(catalog)
        self._axial_layout()
        self._check_rings()
        self._place_oil_plug()

    @staticmethod
    def sizes(catalog: Catalog) -> list[int]:
        fd0 = {r["size"] for r in catalog.rows(FDCasingHalf.FD0)}
        return sorted(fd0 & {r["size"] for r in catalog.rows(FDCasingHalf.FD2)})

    def _row(self, catalog: Catalog, table: str) -> dict:
        row = catalog.find(table, size=self.size)
        missing = [c for c in self.NEEDED[table] if row.get(c) is None]
        if missing:
            raise ValueError(f"{self.label}: the {table} row lacks {', '.join(missing)}")
        return row

    # -- dimensions ------------------------------------------------------------------------------
    def _standard_parts(self, catalog: Catalog) -> None:
        """Bearing Q (ISO 15), its seal (ISO 6194-1) and the screw/hole sizes."""
        label = self.label
        self.bearing = str(self.fd0["Q_bearing"]).lstrip("#")
        try:
            self.bore_d, self.bearing_od, self.bearing_w = bearing_dimensions(catalog,
                                                                              self.bearing)
            self.seal_od, self.seal_w = seal_dimensions(catalog, self.bore_d)
        except ValueError as exc:
            raise ValueError(f"{label}: {exc}") from None
        self.screw, self.gear_thread = self.fd2["K_thread"], self.fd0["M_thread"]
        self.clearance = _table_value(ISO_273_MEDIUM_MM, self.screw, f"{label}: screw")
        self.cbore = DIN_974_1_CBORE_MM[self.screw]
        self.cbore_depth = ISO_4762_HEAD_MM[self.screw][1] + CBORE_SINK_MM
        self.tap_drill = _table_value(TAP_DRILL_MM, self.gear_thread, f"{label}: thread")
        self.shaft_hole = self.bore_d + 2 * SHAFT_CLEARANCE_MM

    def _axial_layout(self) -> None:
        fd0, fd2, gap = self.fd0, self.fd2, self.options.running_gap_mm
        # The splines sit C apart inside the unit; each half's face stands gap/2 off the
        # mid-plane, so the recess is the spline width plus C/2 minus gap/2 deep.
        self.pilot_depth = fd2["B_mm"] + fd2["C_mm"] / 2 - gap / 2
        if self.pilot_depth <= 0:
            raise ValueError(f"{self.label}: running_gap_mm {gap:g} leaves no pilot recess "
                             f"(FD-2 B {fd2['B_mm']:g}, C {fd2['C_mm']:g})")
        self.room = (fd0["D_mm"] - fd2["D_mm"]) / 2  # axial room per side behind the spline
        self.seal_depth = self.seal_w + SEAL_DEPTH_ALLOWANCE_MM
        self.floor_min = max(self.bearing_w + self.seal_depth + SPIGOT_DEPTH_MM
                             + self.options.wall_mm, fd0["M_depth_mm"] + MIN_FLOOR_MM)
        self.floor = max(self.room, self.floor_min)
        self.thickness = self.pilot_depth + self.floor
        self.cbore_depth = self.floor - self._grip()

    def _grip(self) -> float:
        """Grip [mm] under the spline-screw heads: the counterbore is sunk just deep enough
        for the longest ISO 4762 preferred length that engages ≥ k_m·d and does not bottom in
        the spline's K-deep thread (a floor this thick would otherwise need special screws)."""
        # the screws thread into the steel circular spline: least engagement as in bolt_pattern
        m_min = MIN_ENGAGEMENT["steel"] * thread_diameter(self.screw)
        depth = self.fd2["K_depth_mm"]
        grip_max = self.floor - (ISO_4762_HEAD_MM[self.screw][1] + CBORE_SINK_MM)
        # l fits some grip g ≤ grip_max with m_min ≤ l − g ≤ depth iff l − depth ≤ grip_max
        length = max((l for l in ISO_4762_LENGTHS_MM if l - depth <= grip_max), default=None)
        return grip_max if length is None else min(grip_max, length - m_min)

    def _check_rings(self) -> None:
        fd0, fd2, label = self.fd0, self.fd2, self.label
        if self.seal_od + 2 * EDGE_MARGIN_MM > fd0["B_H7_mm"]:
            raise ValueError(f"{label}: seal bore Ø{self.seal_od:g} does not fit inside the "
                             f"Ø{fd0['B_H7_mm']:g} spigot recess")
        # clearance holes run from the spline face (inside φA g7) past the bearing seat
        _check_ring(f"{label} spline_screws", fd2["I_mm"], fd2["J_count"], self.clearance,
                    self.bearing_od, fd2["A_g7_mm"])
        # counterbores and tapped holes share the outer face between spigot recess and rim
        _check_ring(f"{label} spline_screws counterbore", fd2["I_mm"], fd2["J_count"],
                    self.cbore, fd0["B_H7_mm"], fd0["A_mm"], CBORE_WALL_MIN_MM)
        _check_ring(f"{label} gear_mount", fd0["K_mm"], fd0["L_count"],
                    thread_diameter(self.gear_thread), fd0["B_H7_mm"], fd0["A_mm"])
        slack = min(_slack(x, y, self.cbore / 2, self._gear_holes())
                    for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0))
        if slack < EDGE_MARGIN_MM:
            raise ValueError(f"{label}: the gear_mount holes on Ø{fd0['K_mm']:g} cut the "
                             f"spline-screw counterbores on Ø{fd2['I_mm']:g}")

    def _gear_start_deg(self) -> float:
        # half a pitch off the spline screws: keeps the two rings apart when J = L
        return 180.0 / self.fd0["L_count"]

    def _gear_holes(self) -> list[tuple[float, float, float]]:
        r = thread_diameter(self.gear_thread) / 2
        return [(x, y, r) for x, y in ring_points(self.fd0["K_mm"], self.fd0["L_count"],
                                            self._gear_start_deg())]

    def _place_oil_plug(self) -> None:
        """Radius max(A, least radius clear of bearing seat and seal); angle with the widest
        ligament to the bolt holes. A is read as measured from the axis (see notes)."""
        half = OIL_PLUG_TAP_DRILL_MM / 2
        clear_r = max(self.bearing_od, self.seal_od) / 2 + EDGE_MARGIN_MM + half
        self.plug_r = max(self.oil_level, clear_r)
        if self.plug_r + half + EDGE_MARGIN_MM > self.fd2["A_g7_mm"] / 2:
            raise ValueError(f"{self.label}: oil hole at radius {self.plug_r:g} does not open "
                             f"into the Ø{self.fd2['A_g7_mm']:g} spline cavity")
        holes = self._gear_holes() + [(x, y, self.cbore / 2) for x, y in
                                      ring_points(self.fd2["I_mm"], self.fd2["J_count"], 0.0)]
        steps = int(360 / PLUG_ANGLE_STEP_DEG)
        best = max((_slack(*polar(self.plug_r, i * PLUG_ANGLE_STEP_DEG), half, holes),
                    i * PLUG_ANGLE_STEP_DEG) for i in range(steps))
        if best[0] < EDGE_MARGIN_MM:
            raise ValueError(f"{self.label}: no room for the {OIL_PLUG_THREAD} oil hole at "
                             f"radius {self.plug_r:g} between the bolt holes")
        self.plug_angle = best[1]

    # -- solid -----------------------------------------------------------------------------------
    def build(self) -> Part:
        fd0, fd2 = self.fd0, self.fd2
        p, t = self.pilot_depth, self.thickness
        seal_top = t - SPIGOT_DEPTH_MM
        cutters = [
            cylinder(fd2["A_g7_mm"], -1, p),                           # pilot recess
            cylinder(self.bearing_od, p - 1, p + self.bearing_w),      # bearing seat
            cylinder(self.shaft_hole, p - 1, t + 1),                   # shaft passage
            cylinder(self.seal_od, seal_top - self.seal_depth, seal_top + 1),
            cylinder(fd0["B_H7_mm"], seal_top, t + 1),                 # spigot recess
            cylinder(OIL_PLUG_TAP_DRILL_MM, p - 1, t + 1,
                      *polar(self.plug_r, self.plug_angle)),
        ]
        for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0):
            cutters += [cylinder(self.clearance, p - 1, t + 1, x, y),
                        cylinder(self.cbore, t - self.cbore_depth, t + 1, x, y)]
        for x, y, _ in self._gear_holes():
            cutters.append(cylinder(self.tap_drill, t - fd0["M_depth_mm"], t + 1, x, y))
        return Part(name=f"casing_half_{self.side}",
                    shape=single_solid(cylinder(fd0["A_mm"], 0, t), cutters, self.label),
                    color=COLORS[self.side], dimensions=self._dimensions(),
                    bolt_circles=self._bolt_circles(), notes=self._notes(),
                    purchased=self._purchased())

    def _bolt_circles(self) -> list[BoltCircle]:
        fd0, fd2 = self.fd0, self.fd2
        # annulus: the clearance holes pass through the casing floor (bearing seat … casing
        # φA; the spline's own tapped ring is the catalog's design); the gear-mount holes
        # sit between the spigot recess φB and the casing φA
        return [BoltCircle("spline_screws", fd2["I_mm"], fd2["J_count"], self.clearance,
                           self.screw, "clearance", fd2["K_depth_mm"],
                           annulus_inner_mm=self._dimensions()["bearing_seat_mm"],
                           annulus_outer_mm=fd0["A_mm"],
                           grip_mm=self.floor - self.cbore_depth),
                BoltCircle("gear_mount", fd0["K_mm"], fd0["L_count"], self.tap_drill,
                           self.gear_thread, "tapped", fd0["M_depth_mm"],
                           annulus_inner_mm=fd0["B_H7_mm"], annulus_outer_mm=fd0["A_mm"],
                           start_angle_deg=self._gear_start_deg())]

    def _purchased(self) -> list[dict]:
        """Bought parts this half holds (bill of materials)."""
        d, big_d, w = self.bore_d, self.bearing_od, self.bearing_w
        return [{"item": "bearing", "designation": f"{self.bearing} (ISO 15, {d:g}×{big_d:g}×{w:g})",
                 "quantity": 1, "note": "support bearing Q of table 311-1 on the WG shaft"},
                {"item": "seal", "designation": f"rotary shaft lip seal {d:g}×{self.seal_od:g}×"
                                                f"{self.seal_w:g} (ISO 6194-1 / DIN 3760)",
                 "quantity": 1, "note": "lip towards the oil"},
                {"item": "plug", "designation": f"screw plug {OIL_PLUG_THREAD} (DIN 906)",
                 "quantity": 1, "note": "oil fill/level hole"}]

    def _dimensions(self) -> dict[str, float]:
        return {"outer_diameter_mm": self.fd0["A_mm"], "pilot_recess_mm": self.fd2["A_g7_mm"],
                "pilot_depth_mm": self.pilot_depth, "spigot_recess_mm": self.fd0["B_H7_mm"],
                "spigot_depth_mm": SPIGOT_DEPTH_MM, "bearing_seat_mm": self.bearing_od,
                "bearing_seat_depth_mm": self.bearing_w, "shaft_hole_mm": self.shaft_hole,
                "seal_recess_mm": self.seal_od, "seal_recess_depth_mm": self.seal_depth,
                "floor_mm": self.floor, "thickness_mm": self.thickness,
                "oil_plug_radius_mm": self.plug_r, "oil_plug_angle_deg": self.plug_angle,
                "oil_level_A_mm": self.oil_level,
                "counterbore_diameter_mm": self.cbore, "counterbore_depth_mm": self.cbore_depth}

    def _notes(self) -> list[str]:
        return self._source_notes() + self._axial_notes() + self._oil_notes()

    def _source_notes(self) -> list[str]:
        fd0, fd2 = self.fd0, self.fd2
        d, big_d, w = self.bore_d, self.bearing_od, self.bearing_w
        return [
            f"seed 001 p.315: casings and bearings of an FD-2 differential follow the FD-0 unit; "
            f"outer Ø{fd0['A_mm']:g} = FD-0 φA, gear spigot recess Ø{fd0['B_H7_mm']:g} H7 = "
            f"FD-0 φB, {fd0['L_count']} × {self.gear_thread}×{fd0['M_depth_mm']:g} on "
            f"φK {fd0['K_mm']:g} (table 311-1); pilot recess Ø{fd2['A_g7_mm']:g} H7 for the "
            f"spline's φA g7, {fd2['J_count']} × {self.screw} spline screws on "
            f"φI {fd2['I_mm']:g} (table 312-1)",
            f"support bearing {self.bearing} (311-1 Q) = ISO 15 {d:g}×{big_d:g}×{w:g}: seat "
            f"Ø{big_d:g} × {w:g} deep from the spline side against a shoulder; shaft hole "
            f"Ø{self.shaft_hole:g} = d + 2 × {SHAFT_CLEARANCE_MM:g} mm (the WG shaft turns in "
            "the casing); the bearing's spline-side face is held by the user's design (circlip "
            "or WG hub shoulder, not modelled)",
            f"FD-2 WG hub φH {fd2['H_mm']:g} (= bearing bore) protrudes (E − D)/2 = "
            f"{(fd2['E_mm'] - fd2['D_mm']) / 2:g} mm beyond the spline face, less than the "
            f"bearing width {w:g}: the bearing needs a hub extension or the input shaft",
            f"oil seal ISO 6194-1 / DIN 3760 {d:g}×{self.seal_od:g}×{self.seal_w:g} outboard of "
            f"the bearing, lip towards the oil; recess Ø{self.seal_od:g} × {self.seal_depth:g} "
            f"(b + {SEAL_DEPTH_ALLOWANCE_MM:g} mm) below the spigot recess",
            f"{self.screw} clearance holes Ø{self.clearance:g} (ISO 273 medium), counterbore "
            f"Ø{self.cbore:g} (DIN 974-1) × {self.cbore_depth:g} from the outer face (at least "
            f"ISO 4762 k + {CBORE_SINK_MM:g} mm, sunk deeper so that a preferred screw length "
            f"fits); grip length "
            f"{self.floor - self.cbore_depth:g} mm + at most {fd2['K_depth_mm']:g} mm thread in "
            "the spline; holes at 0°",
            f"gear_mount: {self.gear_thread} modelled as tap-drill Ø{self.tap_drill:g} (ISO 2306"
            f") × {fd0['M_depth_mm']:g} deep (thread depth), at {self._gear_start_deg():g}° + "
            "k·pitch (half a pitch off the spline screws)",
            f"gear/pulley spigot recess Ø{fd0['B_H7_mm']:g} H7 × {SPIGOT_DEPTH_MM:g} mm: design "
            "value (no standard depth; deeper than the 1.5 mm pilot boss of the FD-0 drive "
            "flange in hdcad.geometry.flanges)",
            f"bolt-circle checks: every hole clears its annulus and its neighbours by "
            f"{EDGE_MARGIN_MM:g} mm (design value); counterbore to spigot recess at least "
            f"{CBORE_WALL_MIN_MM:g} mm",
        ] + self._thin_wall_notes()

    def _thin_wall_notes(self) -> list[str]:
        wall = (self.fd2["I_mm"] - self.cbore - self.fd0["B_H7_mm"]) / 2
        if wall >= EDGE_MARGIN_MM:
            return []
        return [f"only {wall:g} mm wall between the spline-screw counterbores and the "
                f"Ø{self.fd0['B_H7_mm']:g} spigot recess (catalog φI and φB are close): "
                "machine with care, or let the counterbores break into the recess"]

    def _axial_notes(self) -> list[str]:
        fd0, fd2, gap = self.fd0, self.fd2, self.options.running_gap_mm
        notes = [
            f"pilot depth {self.pilot_depth:g} = FD-2 B {fd2['B_mm']:g} + C/2 "
            f"{fd2['C_mm'] / 2:g} − running_gap/2 {gap / 2:g}: the two casing halves turn "
            f"relative to each other, so they must not touch; their faces stand running_gap_mm "
            f"= {gap:g} mm apart (design option) while the splines keep their FD-2 gap C",
            f"thickness {self.thickness:g} = pilot depth + floor {self.floor:g}; floor = "
            f"max((FD-0 D − FD-2 D)/2 = {self.room:g}, bearing width {self.bearing_w:g} + seal "
            f"recess {self.seal_depth:g} + spigot recess {SPIGOT_DEPTH_MM:g} + wall_mm "
            f"{self.options.wall_mm:g}, thread depth + {MIN_FLOOR_MM:g})",
            "table 313-2 row IV counts 4 support bearings in the unit; this design has one per "
            "casing half (two in all)",
        ]
        if self.floor > self.room:
            width = 2 * self.thickness + gap
            notes.append(f"floor thickened beyond the FD-0 room {self.room:g} mm: the unit is "
                         f"{width:g} mm wide instead of FD-0 D {fd0['D_mm']:g} mm")
        return notes

    def _oil_notes(self) -> list[str]:
        a, r = self.oil_level, self.plug_r
        notes = [
            f"oil fill/level hole {OIL_PLUG_THREAD} (ISO 261 fine thread; modelled as tap-drill "
            f"Ø{OIL_PLUG_TAP_DRILL_MM:g}), axial, through the floor into the cavity, at radius "
            f"{r:g} mm, {self.plug_angle:g}° from the spline screws; plug e.g. DIN 906 "
            "M10×1 (conical, seals in the thread: no seat face needed)",
            f"oil level A = {a:g} mm (table 315-1; figure 315-1 is lost) is read as the distance "
            "from the axis down to the oil surface with the axis horizontal at standstill; the "
            "casing halves rotate, so an axial hole at radius A fills to level A when it is "
            "turned to the bottom (oil runs out until the surface reaches the hole)",
            "the oil hole lies inside the gear bolt circle φK: the user's gear/pulley needs an "
            "access hole there",
        ]
        if r > a:
            turn = math.degrees(math.acos(a / r))
            notes.append(f"radius A = {a:g} mm lies inside the bearing seat/seal; the hole is at "
                         f"the least clear radius {r:g} mm instead: turn it {turn:.1f}° from the "
                         f"bottom so that it stands A = {a:g} mm below the axis, then fill")
        pitch_r = self.size * 2.54 / 2  # CS pitch Ø ≈ size × 2.54 mm (seed 000 table 027-3)
        if r + OIL_PLUG_TAP_DRILL_MM / 2 > pitch_r:
            notes.append(f"the oil hole reaches radius {r + OIL_PLUG_TAP_DRILL_MM / 2:g} mm, "
                         f"beyond the circular spline's pitch radius ≈ {pitch_r:g} mm: part of "
                         "it may open onto the spline face (the spline bore is not in table "
                         "312-1); check, or add a relief groove")
        return notes
