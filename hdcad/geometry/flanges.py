"""Flange part families: the FD-0 drive flange and the CSF-/CSG-GH motor adapter flange.

cq_warehouse style: one class per family, built from one catalog table. ``sizes()`` and
``codes()`` list what the catalog offers; an unknown size or code raises ValueError naming the
allowed values. ``build()`` returns a :class:`Part` with its axis on Z, its mating face at
z = 0 and its body towards +z. A request whose bolt circle cannot be made (holes cutting the
pilot, the bore, the outer edge or each other) raises ValueError with a one-line message.

Catalog data (seed tables) and design choices are kept apart: every number that is not in a
seed table is a named constant below, and each Part lists its interpretations in ``notes``.
"""

from __future__ import annotations

import math

import cadquery as cq

from ..catalog import Catalog
from ..design_options import DesignOptions
from .drive_feature import drive_feature
from .features import blind_hole, countersink, drill_point, lead_in, shaft_lead_in
from .gh_interface import NOT_FOR_MANUFACTURE, gear_head_face
from .housing_common import EDGE_MARGIN_MM, PILOT_LEAD_IN_MM, TAP_RUNOUT_PITCHES, whole_mm
from .iso286 import iso286_fit
from .part import BoltCircle, Part
from .primitives import EDGE_BREAK_MM, break_outer_edges, cylinder, ring_points, single_solid
from .standards import (DIN_974_1_CBORE_MM, ISO_261_PITCH_MM, ISO_273_MEDIUM_MM, ISO_4762_HEAD_MM,
                        TAP_DRILL_MM, thread_diameter)

# ---------------------------------------------------------------------------------------------
# Design choices (not catalog data); each is printed in the Part notes where it is used.
# ---------------------------------------------------------------------------------------------
BORE_CLEARANCE_MM = 1.0      # radial clearance of a central bore around a part that turns relative to it
PILOT_BOSS_HEIGHT_MM = 1.5   # FD boss into the φB recess; below the smallest FD-0 H (2 mm) in case H is the recess depth
CBORE_SINK_MM = 0.5          # screw head sits this far below the face
MIN_UNDER_HEAD_MM = 3.0      # least plate under a counterbore (also >= d/2)
MIN_FLOOR_MM = 3.0           # least material below a blind tapped hole or the pilot recess
DEFAULT_PILOT_DEPTH_MM = 10.0  # largest pilot depth printed in 055-1/056-1/064-1: clears any listed motor spigot
MOTOR_HOLE_COUNT = 4         # not in the seed tables; IEC 60072-1 FF/FT flanges up to FF265 have 4 holes
MOTOR_HOLE_START_DEG = 45.0  # holes on the diagonals, where a square flange has room
DRIVE_FLANGE_COLOR = (0.80, 0.62, 0.30)
MOTOR_FLANGE_COLOR = (0.62, 0.66, 0.72)
EDGE_NOTE = (f"outer edges broken {EDGE_BREAK_MM:g} × 45° (ISO 13715); other edges -0.3/+0.3 "
             "per the drawing's edge note")


def check_ring(label: str, ring_d: float, count: int, hole_d: float, inner_d: float,
               outer_d: float | None = None, square: float | None = None,
               start_deg: float = 0.0) -> None:
    """ValueError unless ``count`` holes Ø hole_d on Ø ring_d clear the inner Ø, the outer
    edge (round Ø or square, holes at start_deg) and each other by EDGE_MARGIN_MM."""
    r, half, m = ring_d / 2, hole_d / 2, EDGE_MARGIN_MM
    if r - half - m < inner_d / 2:
        raise ValueError(f"{label}: bolt circle Ø{ring_d:g} with Ø{hole_d:g} holes cuts the "
                         f"Ø{inner_d:g} pilot/bore; needs Ø >= {inner_d + hole_d + 2 * m:g}")
    if outer_d is not None and r + half + m > outer_d / 2:
        raise ValueError(f"{label}: bolt circle Ø{ring_d:g} with Ø{hole_d:g} holes does not fit "
                         f"inside the Ø{outer_d:g} outer edge; needs Ø <= {outer_d - hole_d - 2 * m:g}")
    if square is not None:
        # nearest edge distance of every hole centre in a square centred on the axis
        angles = [math.radians(start_deg + 360.0 * i / count) for i in range(count)]
        reach = max(max(abs(math.cos(a)), abs(math.sin(a))) * r for a in angles)
        if reach + half + m > square / 2:
            raise ValueError(f"{label}: bolt circle Ø{ring_d:g} with Ø{hole_d:g} holes does not "
                             f"fit inside the □{square:g} square flange")
    pitch = 2 * r * math.sin(math.pi / count) if count > 1 else math.inf
    if pitch < hole_d + m:
        raise ValueError(f"{label}: {count} holes Ø{hole_d:g} on Ø{ring_d:g} overlap their "
                         f"neighbours (pitch {pitch:.2f} mm)")


def _missing(row: dict, columns: tuple[str, ...]) -> list[str]:
    return [c for c in columns if row.get(c) is None]


# ---------------------------------------------------------------------------------------------
# FD-0 drive flange
# ---------------------------------------------------------------------------------------------
class FDDriveFlange:
    """Flange on a turning casing half of an FD-…-0 unit, carrying the user's gear or pulley.

    Seed 001 p.302: the unit is cased so that gears and pulleys mount directly. From table
    311-1 (fd0_dimensions): φA outer, φB (H7) recess for the pilot boss, φC shaft at the
    support bearings, L screws M on φK. Layout along +z: pilot boss Ø φB (z < 0, into the
    recess), mating face z = 0, plate Ø φA, gear pilot hub Ø φB on the far face.
    """

    TABLE = "fd0_dimensions"
    NEEDED = ("A_mm", "B_H7_mm", "C_mm", "K_mm", "L_count", "M_thread", "M_depth_mm")

    def __init__(self, size: int, catalog: Catalog, options: DesignOptions | None = None):
        options = options or DesignOptions()
        row = catalog.find(self.TABLE, size=size)
        if row is None:
            raise ValueError(f"FD-0 size {size!r} is not in table 311-1 ({self.TABLE}); "
                             f"allowed sizes: {', '.join(map(str, self.sizes(catalog)))}")
        missing = _missing(row, self.NEEDED)
        if missing:
            raise ValueError(f"FD-0 size {size}: table 311-1 row lacks {', '.join(missing)}")
        self.size, self.row, self.options, self.catalog = size, row, options, catalog
        self.label = f"FD-{size}-0 drive flange"
        self._dimension()
        self._check()

    @staticmethod
    def sizes(catalog: Catalog) -> list[int]:
        return sorted({r["size"] for r in catalog.rows(FDDriveFlange.TABLE)})

    def _dimension(self) -> None:
        row, thread = self.row, self.row["M_thread"]
        d = thread_diameter(thread)
        self.thread, self.count = thread, int(row["L_count"])
        self.outer, self.pilot, self.ring = row["A_mm"], row["B_H7_mm"], row["K_mm"]
        self.hole = ISO_273_MEDIUM_MM[thread]
        self.cbore = DIN_974_1_CBORE_MM[thread]
        self.cbore_depth = ISO_4762_HEAD_MM[thread][1] + CBORE_SINK_MM
        # thicken the plate when wall_mm leaves too little under the sunk screw head
        self.thickness = max(self.options.wall_mm,
                             self.cbore_depth + max(MIN_UNDER_HEAD_MM, d / 2))
        self.bore = row["C_mm"] + 2 * BORE_CLEARANCE_MM  # WG shaft φC turns relative to the casing
        self.hub_length = self.options.wall_mm

    def _check(self) -> None:
        if self.bore + 2 * EDGE_MARGIN_MM > self.pilot:
            raise ValueError(f"{self.label}: bore Ø{self.bore:g} does not fit inside the "
                             f"Ø{self.pilot:g} pilot boss")
        # the counterbore is the widest part of each hole; hub and boss are both Ø φB
        check_ring(self.label, self.ring, self.count, self.cbore, self.pilot, outer_d=self.outer)

    def build(self) -> Part:
        t, top = self.thickness, self.thickness + self.hub_length
        body = cylinder(self.outer, 0, t).fuse(
            cylinder(self.pilot, -PILOT_BOSS_HEIGHT_MM, 0), cylinder(self.pilot, t, top))
        cutters = [cylinder(self.bore, -PILOT_BOSS_HEIGHT_MM - 1, top + 1),
                   # lead-ins: the boss into the unit's φB recess, the user's gear onto the hub
                   shaft_lead_in(self.pilot, -PILOT_BOSS_HEIGHT_MM, PILOT_BOSS_HEIGHT_MM / 3,
                                 towards=-1),
                   shaft_lead_in(self.pilot, top, min(PILOT_LEAD_IN_MM, self.hub_length / 3))]
        for x, y in ring_points(self.ring, self.count, 0.0):
            cutters += [cylinder(self.hole, -1, t + 1, x, y),
                        cylinder(self.cbore, t - self.cbore_depth, t + 1, x, y)]
        extra, circles, notes = drive_feature(self.options.drive, self.pilot, self.bore, t,
                                              top, self.catalog)
        shape = break_outer_edges(single_solid(body, cutters + extra, self.label), self.outer)
        return Part(name="drive_flange", shape=shape,
                    color=DRIVE_FLANGE_COLOR, dimensions=self._dimensions(),
                    bolt_circles=[self._bolt_circle()] + circles,
                    notes=self._notes() + notes + [EDGE_NOTE], fits=self._fits(),
                    material="S355J2 (EN 10025-2)", turns_with="unit")

    def _fits(self) -> list:
        return [iso286_fit(self.catalog, "pilot boss", self.pilot, "h7",
                           "FD-0 casing recess φB H7 (table 311-1)", "centring on the unit"),
                iso286_fit(self.catalog, "gear/pulley hub", self.pilot, "g6",
                           "the user's gear bore H7", "slide fit, the drive feature carries "
                           "the torque")]

    def _bolt_circle(self) -> BoltCircle:
        # depth = thread engagement the casing offers (311-1 M = thread × depth)
        return BoltCircle("casing screws", self.ring, self.count, self.hole, self.thread,
                          "clearance", self.row["M_depth_mm"], annulus_inner_mm=self.pilot,
                          annulus_outer_mm=self.outer,
                          grip_mm=self.thickness - self.cbore_depth)

    def _dimensions(self) -> dict[str, float]:
        return {"outer_diameter_mm": self.outer, "pilot_boss_diameter_mm": self.pilot,
                "pilot_boss_height_mm": PILOT_BOSS_HEIGHT_MM, "bore_mm": self.bore,
                "thickness_mm": self.thickness, "hub_diameter_mm": self.pilot,
                "hub_length_mm": self.hub_length, "bolt_circle_mm": self.ring,
                "clearance_hole_mm": self.hole, "counterbore_diameter_mm": self.cbore,
                "counterbore_depth_mm": self.cbore_depth,
                "overall_length_mm": PILOT_BOSS_HEIGHT_MM + self.thickness + self.hub_length}

    def _notes(self) -> list[str]:
        row = self.row
        notes = [
            f"FD-0 table 311-1 size {self.size}: outer φA {row['A_mm']:g}, recess φB H7 "
            f"{row['B_H7_mm']:g}, shaft φC {row['C_mm']:g}, {self.count} × {self.thread}"
            f"×{row['M_depth_mm']:g} on φK {row['K_mm']:g} (figure 311-1 is lost: column "
            "meanings per catalog/SOURCES.fd_engineering.yaml)",
            f"pilot boss Ø{self.pilot:g} (machine h7 for the φB H7 recess), "
            f"{PILOT_BOSS_HEIGHT_MM:g} mm long: design value kept below the smallest FD-0 H "
            "(2 mm) because the recess depth is not known; check the delivery drawing",
            f"bore Ø{self.bore:g} = φC + 2 × {BORE_CLEARANCE_MM:g} mm running clearance "
            "(the wave-generator shaft turns relative to the casing half)",
            f"{self.thread} clearance holes Ø{self.hole:g} (ISO 273 medium), counterbore "
            f"Ø{self.cbore:g} (DIN 974-1) × {self.cbore_depth:g} deep for ISO 4762 heads "
            f"(k + {CBORE_SINK_MM:g} mm), from the far face; hole angular position 0° "
            "(clock it to the casing's tapped holes)",
            f"gear/pulley pilot hub Ø{self.pilot:g} × {self.hub_length:g} (= wall_mm): design "
            "choice; the user's gear is centred on it",
        ]
        if self.thickness > self.options.wall_mm:
            notes.append(f"plate thickened from wall_mm {self.options.wall_mm:g} to "
                         f"{self.thickness:g} mm to leave >= max({MIN_UNDER_HEAD_MM:g} mm, d/2) "
                         "under the counterbore")
        return notes


# ---------------------------------------------------------------------------------------------
# CSF-/CSG-GH motor adapter flange
# ---------------------------------------------------------------------------------------------
class GHMotorFlange:
    """Motor adapter flange of a CSF-/CSG-…-GH gear head for one flange code.

    From table gh_motor_flange (seed 003 tables 053-1 … 064-1): motor pilot Ø (H7) and depth,
    tapped holes thread × depth on the motor bolt circle, square flange size, input-coupling
    bore range. Layout: gear-head side face at z = 0, motor face at z = thickness with the
    pilot recess, tapped holes and square (or round) outline; a clearance bore for the coupling.
    """

    TABLE = "gh_motor_flange"
    NEEDED = ("pilot_H7_mm", "bolt_circle_mm", "thread", "thread_depth_mm",
              "coupling_bore_max_mm")

    def __init__(self, series: str, size: int, flange_code: str, catalog: Catalog,
                 options: DesignOptions | None = None):
        self.options = options or DesignOptions()
        code = str(flange_code).strip().upper()
        self.series, self.size, self.code = series, size, code
        self.label = f"{series}-{size} motor flange {code}"
        self.catalog = catalog
        self.face = gear_head_face(catalog, series, size)
        self.row = self._row(catalog)
        self._dimension()
        self._check()

    # -- catalog look-ups ---------------------------------------------------------------------
    @staticmethod
    def series_names(catalog: Catalog) -> list[str]:
        return sorted({r["series"] for r in catalog.rows(GHMotorFlange.TABLE)})

    @staticmethod
    def codes(catalog: Catalog, series: str, size: int) -> list[str]:
        """Flange codes (table order) whose row has pilot, bolt circle, thread and bore."""
        out: list[str] = []
        for r in catalog.rows(GHMotorFlange.TABLE, series=series, size=size):
            row = catalog.find(GHMotorFlange.TABLE, series=series, size=size,
                               flange_code=r["flange_code"])  # overlay rows win
            if not _missing(row, GHMotorFlange.NEEDED) and row["flange_code"] not in out:
                out.append(row["flange_code"])
        return out

    @staticmethod
    def sizes(catalog: Catalog, series: str) -> list[int]:
        """Sizes of ``series`` with at least one complete flange code."""
        sizes = {r["size"] for r in catalog.rows(GHMotorFlange.TABLE, series=series)}
        return sorted(s for s in sizes if GHMotorFlange.codes(catalog, series, s))

    def _row(self, catalog: Catalog) -> dict:
        if not catalog.rows(self.TABLE, series=self.series):
            raise ValueError(f"series {self.series!r} has no motor-flange table; allowed: "
                             f"{', '.join(self.series_names(catalog))}")
        sizes = self.sizes(catalog, self.series)
        if self.size not in sizes:
            raise ValueError(f"{self.series} size {self.size!r} has no motor-flange table in the "
                             f"catalog; allowed sizes: {', '.join(map(str, sizes))}")
        codes = self.codes(catalog, self.series, self.size)
        row = catalog.find(self.TABLE, series=self.series, size=self.size, flange_code=self.code)
        if row is None:
            raise ValueError(f"{self.label}: unknown flange code; complete codes: "
                             f"{', '.join(codes)}")
        missing = _missing(row, self.NEEDED)
        if missing:
            raise ValueError(f"{self.label}: table {row['table']} row lacks {', '.join(missing)} "
                             f"(blank or misaligned in the seed); complete codes: {', '.join(codes)}")
        return row

    # -- dimensions ------------------------------------------------------------------------------
    def _dimension(self) -> None:
        row, thread = self.row, self.row["thread"]
        d = thread_diameter(thread)
        self.thread, self.pilot, self.ring = thread, row["pilot_H7_mm"], row["bolt_circle_mm"]
        self.pilot_depth = row["pilot_depth_mm"] or DEFAULT_PILOT_DEPTH_MM
        self.tap_drill = TAP_DRILL_MM[thread]
        self.thread_depth = row["thread_depth_mm"]
        self.drill_depth = self.thread_depth + TAP_RUNOUT_PITCHES * ISO_261_PITCH_MM[thread]
        self.square = row["square_mm"]
        # round flange: bolt circle + thread Ø + one thread Ø of wall each side
        self.outer = None if self.square else self.ring + 3 * d
        if self.face is not None and not self.square and self.face.row.get("outline_mm"):
            # the gear-head face's outline, when larger than the motor side needs
            self.outer = max(self.outer, self.face.row["outline_mm"])
        self.bore = row["coupling_bore_max_mm"] + 2 * BORE_CLEARANCE_MM
        floor = drill_point(self.tap_drill) + MIN_FLOOR_MM   # under the drill's tip
        need = max(self.pilot_depth + MIN_FLOOR_MM, self.drill_depth + floor)
        if self.face is not None:
            # under the counterbores, and between a gear-head recess and the motor side
            recess = 0.0 if self.face.spigot else self.face.row["pilot_depth_mm"]
            need = max(need, self.face.least_thickness_mm(MIN_UNDER_HEAD_MM), recess + need)
        self.thickness = max(self.options.wall_mm, whole_mm(need))
        self.hole_for_fit = d  # thread major diameter: the ligament is measured from it

    def _check(self) -> None:
        shaft = self.options.input_shaft_mm
        lo, hi = self.row["coupling_bore_min_mm"], self.row["coupling_bore_max_mm"]
        if shaft is not None and lo is not None and not lo <= shaft <= hi:
            raise ValueError(f"{self.label}: input_shaft_mm {shaft:g} is outside the input "
                             f"coupling bore range {lo:g}-{hi:g} mm")
        if self.bore + 2 * EDGE_MARGIN_MM > self.pilot:
            raise ValueError(f"{self.label}: coupling bore Ø{self.bore:g} does not fit inside "
                             f"the Ø{self.pilot:g} motor pilot")
        check_ring(self.label, self.ring, MOTOR_HOLE_COUNT, self.hole_for_fit, self.pilot,
                   outer_d=self.outer, square=self.square, start_deg=MOTOR_HOLE_START_DEG)

    # -- solid -----------------------------------------------------------------------------------
    def build(self) -> Part:
        t = self.thickness
        if self.square:
            body = cq.Solid.makeBox(self.square, self.square, t,
                                    cq.Vector(-self.square / 2, -self.square / 2, 0))
        else:
            body = cylinder(self.outer, 0, t)
        cutters = [cylinder(self.bore, -1, t + 1),
                   cylinder(self.pilot, t - self.pilot_depth, t + 1),
                   lead_in(self.pilot, t, PILOT_LEAD_IN_MM, inward=False)]
        for x, y in ring_points(self.ring, MOTOR_HOLE_COUNT, MOTOR_HOLE_START_DEG):
            cutters += [blind_hole(self.tap_drill, t, self.drill_depth, x, y),
                        countersink(thread_diameter(self.thread), t, x, y)]
        circles = [BoltCircle("motor screws", self.ring, MOTOR_HOLE_COUNT, self.tap_drill,
                              self.thread, "tapped", self.thread_depth,
                              annulus_inner_mm=self.pilot, annulus_outer_mm=self.outer,
                              outline_square_mm=self.square,
                              start_angle_deg=MOTOR_HOLE_START_DEG)]
        if self.face is not None:
            add, cut = self.face.solids(t, self.bore)
            body = body.fuse(*add) if add else body
            cutters += cut
            circles.append(self.face.bolt_circle(t, self.bore, self.outer, self.square))
        shape = break_outer_edges(single_solid(body, cutters, self.label), self.outer,
                                  self.square)
        return Part(name="motor_flange", shape=shape,
                    color=MOTOR_FLANGE_COLOR, dimensions=self._dimensions(),
                    bolt_circles=circles, notes=self._notes() + [EDGE_NOTE],
                    fits=self._fits(),
                    neighbours=self.face.neighbours(t) if self.face is not None else [])

    def _fits(self) -> list:
        fits = [iso286_fit(self.catalog, "motor pilot", self.pilot, "H7",
                           "motor spigot (j6/h7 per the motor maker)",
                           f"seed 003 table {self.row['table']}: pilot A (H7)")]
        if self.face is not None:
            r = self.face.row
            fits.append(iso286_fit(self.catalog, "gear-head pilot", r["pilot_diameter_mm"],
                                   self.face.pilot_fit(), "gear-head housing pilot",
                                   "locates the flange on the gear head (HOUSING_RULES §4: "
                                   "pilot H7/g6)"))
        return fits

    def _dimensions(self) -> dict[str, float]:
        size = ({"square_mm": self.square} if self.square else {"outer_diameter_mm": self.outer})
        return {**size, "pilot_diameter_mm": self.pilot, "pilot_depth_mm": self.pilot_depth,
                "bore_mm": self.bore, "thickness_mm": self.thickness,
                "bolt_circle_mm": self.ring, "tap_drill_mm": self.tap_drill,
                "thread_depth_mm": self.thread_depth, "drill_depth_mm": self.drill_depth}

    def _notes(self) -> list[str]:
        row = self.row
        notes = [
            f"{self.series}-{self.size} flange code {self.code} (type {row['flange_type']}), "
            f"seed 003 table {row['table']}: motor pilot Ø{self.pilot:g} H7, "
            f"{self.thread}×{self.thread_depth:g} on Ø{self.ring:g}, input coupling bore "
            f"{row['coupling_bore_min_mm']:g}-{row['coupling_bore_max_mm']:g} H7",
            f"{MOTOR_HOLE_COUNT} tapped holes at {MOTOR_HOLE_START_DEG:g}° + k·90°: the hole "
            "count is not in the seed table (assumed 4, as IEC 60072-1 FF/FT flanges up to "
            "FF265 and square servo-motor flanges)",
            f"tap drill Ø{self.tap_drill:g} (ISO 2306 / DIN 336 for ISO 261 coarse thread), "
            f"drilled {self.drill_depth:g} deep = thread depth + {TAP_RUNOUT_PITCHES:g}·P",
            f"coupling clearance bore Ø{self.bore:g} = max coupling bore + 2 × "
            f"{BORE_CLEARANCE_MM:g} mm (coupling outside diameter is not in the seed)",
            *(self.face.notes() if self.face is not None else [NOT_FOR_MANUFACTURE]),
            f"thickness {self.thickness:g} mm = max(wall_mm, pilot depth + {MIN_FLOOR_MM:g}, "
            f"drill depth + 118° point {drill_point(self.tap_drill):.1f} + {MIN_FLOOR_MM:g} "
            "rounded up to a whole millimetre)",
        ]
        if row["pilot_depth_mm"] is None:
            notes.append(f"pilot depth not in table {row['table']} for {self.code}: design value "
                         f"{DEFAULT_PILOT_DEPTH_MM:g} mm (largest depth printed in the GH tables, "
                         "deep enough for the motor spigots they list)")
        if self.square:
            notes.append(f"square flange □{self.square:g} from the table")
        else:
            notes.append(f"no square in the table: round flange Ø{self.outer:g} = bolt circle "
                         "+ 3 × thread diameter (design choice)")
        return notes
