"""Motor adapter plate between a GH motor-flange code's motor side and the user's motor.

The seeds give, per flange code, only the motor side of Harmonic Drive's own motor flange:
pilot A (H7) and its depth B, bolt circle C with thread D × depth, square E, coupling bore
F min-max (tables 053-1 … 064-1). When the user's motor (design option ``motor:``) matches a
code, no adapter is needed: order that code. Otherwise hdcad picks the code whose coupling
takes the motor shaft and whose pilot and bolt circle are nearest, and builds a plate:

  z = −s … 0       spigot Ø A g6 into the flange's pilot A (H7), s ≤ B − 0.5
  z = 0 … T        plate; through bore for the motor shaft
  z = T − r … T    motor pilot recess Ø P H7, r = motor pilot length + 0.5
  ring C           clearance holes (ISO 273) for ISO 4762 D screws into the flange, counter-
                   bored (DIN 974-1) from the motor side, below the recess floor when inside it
  ring M           tapped holes for the motor's screws (or clearance holes when the motor's
                   flange is tapped), clocked to keep the two rings apart
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..catalog import Catalog
from ..checks.bolts import MIN_ENGAGEMENT
from ..design_options import DesignOptions
from .features import (COUNTERSINK_FACTOR, LEAD_IN_DEG, OringGland, blind_hole, countersink,
                       drill_point, lead_in, screw_body, screw_for_grip, shaft_lead_in)
from .housing_common import EDGE_FACTOR, PILOT_LEAD_IN_MM, TAP_RUNOUT_PITCHES, whole_mm
from .iso286 import iso286_fit
from .part import BoltCircle, Neighbour, Part
from .primitives import break_outer_edges, cylinder, ring_points, single_solid
from .standards import (DIN_974_1_CBORE_MM, ISO_261_PITCH_MM, ISO_273_MEDIUM_MM,
                        ISO_4762_HEAD_MM, TAP_DRILL_MM, thread_diameter)

FLANGE_HOLES = 4            # the flange code's D holes: count not in the seeds (as flanges.py)
FLANGE_START_DEG = 45.0
SPIGOT_MM = 3.0             # spigot length into pilot A, at most B − 0.5
SHAFT_CLEARANCE_MM = 1.0    # radial, around the motor shaft in the plate
FLOOR_MM = 3.0              # least material under a blind hole or a counterbore
LIGAMENT_MM = 2.0           # least ligament between holes (HOUSING_RULES §4)
DIRECT_TOL_MM = 0.05        # a pilot or bolt circle this close counts as the same
COLOR = (0.55, 0.62, 0.74)
FACE_ORING_D2_MM = 1.78     # static face O-rings: the thinnest ISO 3601-1 section fits the rings
FACE_LAND_MM = 1.5          # least land between a face groove and a hole (groove flank, ISO 3601-2)
PILOT_LAND_MM = LIGAMENT_MM  # land between a face groove and the pilot or its lead-in


@dataclass(frozen=True)
class Motor:
    """The user's motor flange and shaft (design option ``motor:``), in mm."""

    pilot_diameter_mm: float
    pilot_length_mm: float
    bolt_circle_mm: float
    bolt_count: int
    bolt_thread: str
    shaft_diameter_mm: float
    shaft_length_mm: float
    square_mm: float | None = None
    holes: str = "clearance"    # the motor flange's holes: clearance (adapter tapped) | tapped

    @classmethod
    def from_options(cls, options: DesignOptions) -> "Motor | None":
        return cls(**options.motor) if options.motor else None


def _complete(row: dict) -> bool:
    return all(row.get(k) not in (None, "") for k in
               ("pilot_H7_mm", "bolt_circle_mm", "thread", "coupling_bore_min_mm",
                "coupling_bore_max_mm"))


def mismatches(row: dict, motor: Motor) -> list[str]:
    """What keeps ``motor`` from bolting straight onto the flange code ``row``."""
    out = []
    if abs(row["pilot_H7_mm"] - motor.pilot_diameter_mm) > DIRECT_TOL_MM:
        out.append(f"pilot Ø{motor.pilot_diameter_mm:g} ≠ A Ø{row['pilot_H7_mm']:g}")
    if abs(row["bolt_circle_mm"] - motor.bolt_circle_mm) > DIRECT_TOL_MM:
        out.append(f"bolt circle Ø{motor.bolt_circle_mm:g} ≠ C Ø{row['bolt_circle_mm']:g}")
    if motor.bolt_thread != row["thread"] or motor.holes != "clearance":
        out.append(f"screws {motor.bolt_thread} through clearance holes ≠ D {row['thread']} "
                   "tapped in the flange")
    if motor.bolt_count != FLANGE_HOLES:
        out.append(f"{motor.bolt_count} holes ≠ {FLANGE_HOLES} (assumed for the flange)")
    if row.get("pilot_depth_mm") and motor.pilot_length_mm > row["pilot_depth_mm"]:
        out.append(f"motor pilot {motor.pilot_length_mm:g} long > recess B "
                   f"{row['pilot_depth_mm']:g}")
    return out


def choose_code(catalog: Catalog, series: str, size: int, motor: Motor
                ) -> tuple[dict, list[str]]:
    """(flange-code row, mismatches): a direct fit if one exists, else the code whose
    coupling takes the shaft with the nearest pilot and bolt circle. ValueError if no code's
    coupling bore range F takes the motor shaft."""
    rows = [r for r in catalog.rows("gh_motor_flange", series=series, size=size) if _complete(r)]
    shaft = motor.shaft_diameter_mm
    takes = [r for r in rows if r["coupling_bore_min_mm"] <= shaft <= r["coupling_bore_max_mm"]]
    if not takes:
        ranges = sorted({(r["coupling_bore_min_mm"], r["coupling_bore_max_mm"]) for r in rows})
        raise ValueError(f"motor.shaft_diameter_mm {shaft:g}: no {series}-{size} flange code's "
                         "input coupling takes it; coupling bores "
                         + ", ".join(f"{a:g}-{b:g}" for a, b in ranges))
    direct = [r for r in takes if not mismatches(r, motor)]
    if direct:
        return direct[0], []
    # nearest pilot and bolt circle; then the thread nearest the motor's, then the code
    best = min(takes, key=lambda r: (abs(r["pilot_H7_mm"] - motor.pilot_diameter_mm)
                                     + abs(r["bolt_circle_mm"] - motor.bolt_circle_mm),
                                     abs(thread_diameter(r["thread"])
                                         - thread_diameter(motor.bolt_thread)),
                                     r["flange_code"]))
    return best, mismatches(best, motor)


class MotorAdapter:
    """The plate for flange-code row ``row`` and ``motor``; see the module doc."""

    def __init__(self, row: dict, motor: Motor, catalog: Catalog, options: DesignOptions,
                 mismatch_text: list[str] | None = None):
        self.row, self.motor, self.catalog, self.options = row, motor, catalog, options
        self.mismatch_text = mismatch_text or mismatches(row, motor)
        self.label = f"motor adapter to flange {row['flange_code']}"
        self.d_flange, self.d_motor = thread_diameter(row["thread"]), \
            thread_diameter(motor.bolt_thread)
        self.spigot = min(SPIGOT_MM, (row.get("pilot_depth_mm") or SPIGOT_MM + 0.5) - 0.5)
        self.recess = motor.pilot_length_mm + 0.5
        self.recess_lead = min(PILOT_LEAD_IN_MM, self.recess / 3)  # 20° lead-in at its mouth
        self.bore = motor.shaft_diameter_mm + 2 * SHAFT_CLEARANCE_MM
        self._motor_holes()
        self._flange_screws()
        self.thickness = self._thickness()
        self.motor_start = self._clocking()
        self.outline = self._outline()
        self._check()
        self.gland = OringGland.from_catalog(catalog, FACE_ORING_D2_MM)
        self.face_glands = self._face_glands()

    def _face_glands(self) -> dict[str, float]:
        """Inner Ø of the static face O-ring grooves (seed 000 p.028: O-ring or sealant on
        flange faces) on the gear-head face (outside the spigot, inside the flange screws) and
        the motor face (outside the recess's lead-in, inside the motor holes and counterbores),
        where a groove fits with PILOT_LAND_MM inside and the hole ligament outside; a face
        without one is sealed with liquid gasket."""
        row, m = self.row, self.motor
        # the groove keeps the hole ligament of HOUSING_RULES §4 (≥ 0.5·d and ≥ 2 mm)
        to_motor = max(FACE_LAND_MM, 0.5 * self.d_motor, LIGAMENT_MM)
        to_flange = max(FACE_LAND_MM, 0.5 * self.d_flange, LIGAMENT_MM)
        entry = max(self.motor_hole, COUNTERSINK_FACTOR * self.d_motor)
        motor_holes = m.bolt_circle_mm - entry - 2 * to_motor
        flange_holes = row["bolt_circle_mm"] - self.flange_hole - 2 * to_flange
        counterbores = row["bolt_circle_mm"] - self.cbore - 2 * to_flange
        mouth = m.pilot_diameter_mm + 2 * self.recess_lead * math.tan(math.radians(LEAD_IN_DEG))
        limits = {"gear-head face": (row["pilot_H7_mm"], flange_holes),
                  "motor face": (mouth,
                                 motor_holes if self.cbore_from_recess else
                                 min(motor_holes, counterbores))}
        out = {}
        for face, (inner, outer) in limits.items():
            d_in = math.ceil((inner + 2 * PILOT_LAND_MM) * 10) / 10
            if d_in + 2 * self.gland.face_width <= outer:
                out[face] = d_in
        return out

    def _face_plane(self, face: str) -> tuple[float, int]:
        """(z of the face, side its material lies on) of the plate face ``face``."""
        return (0.0, 1) if face == "gear-head face" else (self.thickness, -1)

    def face_cutters(self) -> list:
        return [self.gland.groove_in_face(d_in, *self._face_plane(face))
                for face, d_in in self.face_glands.items()]

    def face_orings(self) -> list[Neighbour]:
        return [Neighbour("oring", f"O-ring {d_in:.0f}×{self.gland.d2:g} ({face})",
                          {"d2": self.gland.d2}, self._face_plane(face)[0],
                          body=self.gland.ring_in_face(d_in, *self._face_plane(face)))
                for face, d_in in self.face_glands.items()]

    # -- holes -------------------------------------------------------------------------------
    def _motor_holes(self) -> None:
        m, d = self.motor, self.d_motor
        if m.holes == "clearance":  # the motor's screws thread into the plate
            eng = MIN_ENGAGEMENT[self.options.material] * d
            self.motor_hole = TAP_DRILL_MM[m.bolt_thread]
            self.motor_thread_depth = math.ceil(max(1.5 * d, eng))
            self.motor_drill = (self.motor_thread_depth
                                + TAP_RUNOUT_PITCHES * ISO_261_PITCH_MM[m.bolt_thread])
        else:
            self.motor_hole = ISO_273_MEDIUM_MM[m.bolt_thread]
            self.motor_thread_depth = self.motor_drill = None

    def _flange_screws(self) -> None:
        thread = self.row["thread"]
        self.flange_hole = ISO_273_MEDIUM_MM[thread]
        self.cbore = DIN_974_1_CBORE_MM[thread]
        self.head_k = ISO_4762_HEAD_MM[thread][1]
        r = self.row["bolt_circle_mm"] / 2
        inside = r - self.cbore / 2 < self.motor.pilot_diameter_mm / 2 + 0.5
        self.cbore_from_recess = inside  # heads below the recess floor, under the motor spigot

    def _thickness(self) -> float:
        need = [self.options.wall_mm, self.recess + FLOOR_MM + 1.0]
        head_seat = self.head_k + 0.5 + max(FLOOR_MM, self.d_flange / 2)
        need.append(head_seat + (self.recess if self.cbore_from_recess else 0.0))
        if self.motor_drill is not None:
            need.append(self.motor_drill + drill_point(self.motor_hole) + FLOOR_MM)
        return whole_mm(max(need))

    @property
    def cbore_depth(self) -> float:
        """From the motor face: head k + 0.5 below the face, or below the recess floor."""
        return self.head_k + 0.5 + (self.recess if self.cbore_from_recess else 0.0)

    @property
    def grip(self) -> float:
        return self.thickness - self.cbore_depth

    def screw_length(self) -> tuple[int | None, float]:
        """(ISO 4762 length, engagement in the flange's D thread): the longest existing
        length that does not bottom in the D-deep thread and engages ≥ 1·d."""
        return screw_for_grip(self.row["thread"], self.grip,
                              self.row["thread_depth_mm"] or 0.0, self.d_flange)

    def _holes(self) -> list[tuple[float, float, float]]:
        """(x, y, d) of both hole rings: flange screws and motor screws."""
        m = self.motor
        return ([(x, y, self.d_flange) for x, y in
                 ring_points(self.row["bolt_circle_mm"], FLANGE_HOLES, FLANGE_START_DEG)]
                + [(x, y, self.d_motor) for x, y in
                   ring_points(m.bolt_circle_mm, m.bolt_count, self.motor_start)])

    def _outline(self) -> tuple[str, float]:
        """Square when the flange or the motor is square (side: both squares, and every hole
        centre ≥ 1.5·d from the edge), else round (every hole ≥ 1.5·d from the rim)."""
        squares = [s for s in (self.row.get("square_mm"), self.motor.square_mm) if s]
        if squares:
            half = max(max(abs(x), abs(y)) + EDGE_FACTOR * d for x, y, d in self._holes())
            return "square", math.ceil(max(max(squares), 2 * half))
        return "round", math.ceil(2 * max(math.hypot(x, y) + EDGE_FACTOR * d
                                          for x, y, d in self._holes()))

    def _clocking(self) -> float:
        """Motor-ring start angle (0 … one pitch) that keeps it furthest from the flange
        screws' counterbores."""
        best = max((self._ring_gap(a), a) for a in
                    (i * 360.0 / self.motor.bolt_count / 24 for i in range(24)))
        return best[1]

    def _ring_gap(self, start: float) -> float:
        flange = ring_points(self.row["bolt_circle_mm"], FLANGE_HOLES, FLANGE_START_DEG)
        motor = ring_points(self.motor.bolt_circle_mm, self.motor.bolt_count, start)
        return min(math.dist(f, m) - self.cbore / 2 - self.motor_hole / 2
                   for f in flange for m in motor)

    def _check(self) -> None:
        m, row = self.motor, self.row
        if self._ring_gap(self.motor_start) < LIGAMENT_MM:
            raise ValueError(f"{self.label}: the motor's holes on Ø{m.bolt_circle_mm:g} and the "
                             f"flange screws on Ø{row['bolt_circle_mm']:g} overlap at every "
                             "clocking; use another motor_flange code")
        if self.bore + 2 * LIGAMENT_MM > min(row["pilot_H7_mm"], m.pilot_diameter_mm):
            raise ValueError(f"{self.label}: the shaft bore Ø{self.bore:g} leaves no wall "
                             "inside the pilots")
        inner = m.pilot_diameter_mm + self.motor_hole + 2 * LIGAMENT_MM
        if m.bolt_circle_mm < inner:
            raise ValueError(f"motor.bolt_circle_mm {m.bolt_circle_mm:g} cuts the motor pilot "
                             f"Ø{m.pilot_diameter_mm:g}; allowed ≥ {inner:g}")

    # -- solid -------------------------------------------------------------------------------
    def build(self) -> Part:
        from .motor_adapter_record import adapter_record
        t, kind, size = self.thickness, *self.outline
        if kind == "square":
            import cadquery as cq
            body = cq.Solid.makeBox(size, size, t, cq.Vector(-size / 2, -size / 2, 0))
        else:
            body = cylinder(size, 0, t)
        body = body.fuse(cylinder(self.row["pilot_H7_mm"], -self.spigot, 0.01))
        cuts = [cylinder(self.bore, -self.spigot - 1, t + 1),
                cylinder(self.motor.pilot_diameter_mm, t - self.recess, t + 1),
                shaft_lead_in(self.row["pilot_H7_mm"], -self.spigot, self.spigot / 3, towards=-1),
                lead_in(self.motor.pilot_diameter_mm, t, self.recess_lead, inward=False)]
        for x, y in ring_points(self.row["bolt_circle_mm"], FLANGE_HOLES, FLANGE_START_DEG):
            cuts += [cylinder(self.flange_hole, -1, t + 1, x, y),
                     cylinder(self.cbore, t - self.cbore_depth, t + 1, x, y)]
        for x, y in ring_points(self.motor.bolt_circle_mm, self.motor.bolt_count,
                                self.motor_start):
            cuts.append(blind_hole(self.motor_hole, t, self.motor_drill, x, y)
                        if self.motor_drill else cylinder(self.motor_hole, -1, t + 1, x, y))
            if self.motor.holes == "clearance":  # tapped here: countersunk entry
                cuts.append(countersink(thread_diameter(self.motor.bolt_thread), t, x, y))
        shape = single_solid(body, cuts + self.face_cutters(), self.label)
        shape = break_outer_edges(shape, size if kind == "round" else None,
                                  size if kind == "square" else None)
        return Part(name="motor_adapter", shape=shape, color=COLOR, **adapter_record(self))

    def fits(self) -> list:
        cat, row, m = self.catalog, self.row, self.motor
        return [iso286_fit(cat, "spigot into flange pilot A", row["pilot_H7_mm"], "g6",
                           f"flange {row['flange_code']} pilot A H7 (seed 003 table "
                           f"{row['table']})", "shaft tolerance for an H7 hole"),
                iso286_fit(cat, "motor pilot recess", m.pilot_diameter_mm, "H7",
                           "motor spigot (j6 per IEC 60072-1)", "motor pilot")]

    def bolt_circles(self) -> list[BoltCircle]:
        row, m = self.row, self.motor
        outer = self.outline[1] if self.outline[0] == "round" else None
        square = self.outline[1] if self.outline[0] == "square" else None
        return [BoltCircle("flange screws", row["bolt_circle_mm"], FLANGE_HOLES,
                           self.flange_hole, row["thread"], "clearance",
                           row["thread_depth_mm"], annulus_inner_mm=self.bore,
                           annulus_outer_mm=outer, outline_square_mm=square,
                           grip_mm=self.grip, start_angle_deg=FLANGE_START_DEG),
                BoltCircle("motor screws", m.bolt_circle_mm, m.bolt_count, self.motor_hole,
                           m.bolt_thread, "tapped" if m.holes == "clearance" else "clearance",
                           self.motor_thread_depth, annulus_inner_mm=m.pilot_diameter_mm,
                           annulus_outer_mm=outer, outline_square_mm=square,
                           start_angle_deg=self.motor_start)]

    def neighbour_screws(self) -> list[Neighbour]:
        length, engaged = self.screw_length()
        if length is None:
            return []
        seat = self.thickness - self.cbore_depth
        dims = {"d": self.d_flange, "l": length, "grip": self.grip, "engaged": engaged,
                "thread_depth": self.row["thread_depth_mm"], "engaged_min": self.d_flange}
        out = []
        for x, y in ring_points(self.row["bolt_circle_mm"], FLANGE_HOLES, FLANGE_START_DEG):
            out.append(Neighbour("screw", f"ISO 4762 {self.row['thread']}×{length}", dims,
                                 seat, xy_mm=(x, y),
                                 body=screw_body(self.row["thread"], seat, length, x, y)))
        return out
