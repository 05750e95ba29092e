"""Casing half of an FD-…-2 component set (harmonic differential gear).

Each casing half is bolted to one circular spline (S or D) and turns with it, carries the
user's gear or pulley on its outer face, and holds a pair of support bearings Q (table 311-1)
on the wave-generator shaft's journal sleeve. The layout (where every feature sits and why) is
in ``fd_layout.py``; this module cuts the solid from named features and writes the record:
fits, geometric tolerances, bought parts and the neighbour bodies of the review assembly.

cq_warehouse style: ``FDCasingHalf.sizes(catalog)`` lists the sizes with an FD-0 (311-1) and
an FD-2 (312-1) row; ``FDCasingHalf(size, catalog, options, side)`` checks the request and
raises ValueError naming what is allowed; ``build()`` returns a :class:`Part` with the axis on
Z, the face towards the other half at z = 0 and the body towards +z.
"""

from __future__ import annotations

from ..catalog import Catalog
from ..checks.bolts import MIN_ENGAGEMENT
from ..design_options import DesignOptions
from .fd_layout import RECESS_LEAD_IN_MM, SPIGOT_DEPTH_MM, WALL_MIN_MM, FDLayout
from .fd_notes import casing_notes
from .features import (TurnedRelief, annulus, blind_hole, countersink, lead_in, screw_and_grip,
                       shaft_lead_in)
from .housing_common import (CBORE_SINK_MM, EDGE_FACTOR, EDGE_MARGIN_MM, TAP_RUNOUT_PITCHES,
                             check_ring, slack, table_value)
from .iso286 import iso286_fit
from .part import BoltCircle, GeometricTolerance, Neighbour, Part
from .primitives import break_outer_edges, cylinder, ring_points, single_solid
from .standards import (DIN_974_1_CBORE_MM, ISO_261_PITCH_MM, ISO_273_MEDIUM_MM,
                        ISO_4762_HEAD_MM, TAP_DRILL_MM, thread_diameter)

RELIEF_MIN_MM = 5.0          # a lightening groove shorter than this saves too little to turn
RELIEF_MIN_DEPTH_MM = 2.0    # ... or shallower than this
COLORS = {"S": (0.62, 0.66, 0.72), "D": (0.52, 0.58, 0.68)}
MATERIAL = "S355J2 (EN 10025-2), or C45 (EN ISO 683-1) for the running spigot"


class FDCasingHalf:
    """One casing half (side S or D) of an FD-…-2 used as a differential; see module doc."""

    SIDES = ("S", "D")

    def __init__(self, size: int, catalog: Catalog, options: DesignOptions | None = None,
                 side: str = "S"):
        self.options = options or DesignOptions()
        if side not in self.SIDES:
            raise ValueError(f"side {side!r} is not a circular spline; allowed: S, D")
        if size not in self.sizes(catalog):
            raise ValueError(f"FD size {size!r} needs a row in tables 311-1 "
                             f"({FDLayout.FD0}) and 312-1 ({FDLayout.FD2}); allowed sizes: "
                             f"{', '.join(map(str, self.sizes(catalog)))}")
        self.size, self.side, self.catalog = size, side, catalog
        self.label = f"FD-{size}-2 casing half {side}"
        self.lay = FDLayout(size, catalog, self.options, self.label)
        self.fd0, self.fd2 = self.lay.fd0, self.lay.fd2
        self._screws()
        self._check_rings()
        self.port_angles = self._port_angles()
        self.relief = self._relief()

    @staticmethod
    def sizes(catalog: Catalog) -> list[int]:
        fd0 = {r["size"] for r in catalog.rows(FDLayout.FD0)}
        return sorted(fd0 & {r["size"] for r in catalog.rows(FDLayout.FD2)})

    # -- screws and holes ------------------------------------------------------------------------
    def _screws(self) -> None:
        self.screw, self.gear_thread = self.fd2["K_thread"], self.fd0["M_thread"]
        self.clearance = table_value(ISO_273_MEDIUM_MM, self.screw, f"{self.label}: screw")
        self.cbore = DIN_974_1_CBORE_MM[self.screw]
        self.tap_drill = table_value(TAP_DRILL_MM, self.gear_thread, f"{self.label}: thread")
        self.screw_length, self.grip = self._screw_length()
        self.cbore_depth = self.lay.floor - self.grip

    def _screw_length(self) -> tuple[int, float]:
        """The longest ISO 4762 length that exists for the spline screw, engages ≥ k_m·d in
        the steel spline and does not bottom in its K-deep thread; the counterbore is sunk to
        the grip that length leaves (head at least CBORE_SINK below the gear face)."""
        m_min = MIN_ENGAGEMENT["steel"] * thread_diameter(self.screw)
        depth = self.fd2["K_depth_mm"]
        grip_max = self.lay.floor - (ISO_4762_HEAD_MM[self.screw][1] + CBORE_SINK_MM)
        length, grip = screw_and_grip(self.screw, grip_max, depth, m_min)
        if length is None:
            raise ValueError(f"{self.label}: no ISO 4762 {self.screw} length fits a "
                             f"{grip_max:.1f} mm grip")
        return length, grip

    def _check_rings(self) -> None:
        fd0, fd2, lay, label = self.fd0, self.fd2, self.lay, self.label
        check_ring(f"{label} spline_screws", fd2["I_mm"], fd2["J_count"], self.clearance,
                   lay.relief_d, fd2["A_g7_mm"])
        check_ring(f"{label} spline_screws counterbore", fd2["I_mm"], fd2["J_count"],
                   self.cbore, lay.gear_recess_d, lay.body_d, WALL_MIN_MM)
        check_ring(f"{label} gear_mount", fd0["K_mm"], fd0["L_count"],
                   thread_diameter(self.gear_thread), lay.gear_recess_d, lay.body_d)
        worst = min(slack(x, y, self.cbore / 2, self._gear_holes())
                    for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0))
        if worst < EDGE_MARGIN_MM:
            raise ValueError(f"{label}: the gear_mount holes on Ø{fd0['K_mm']:g} cut the "
                             f"spline-screw counterbores on Ø{fd2['I_mm']:g}")
        hole_bottom = lay.thickness - self.gear_drill_depth - self.tap_drill / 2
        port_top = lay.port_z + lay.port.tap_drill / 2
        if hole_bottom - port_top < lay.port.ligament_min:
            raise ValueError(f"{label}: the gear_mount holes reach within "
                             f"{hole_bottom - port_top:.1f} mm of the oil ports")

    @property
    def gear_drill_depth(self) -> float:
        """Drilled depth of the gear_mount holes [mm]: the catalog's thread depth M plus the
        tap's run-out (HOUSING_RULES §4: blind tapped depth = engagement + 3·P)."""
        return self.fd0["M_depth_mm"] + TAP_RUNOUT_PITCHES * ISO_261_PITCH_MM[self.gear_thread]

    def _gear_start_deg(self) -> float:
        return 180.0 / self.fd0["L_count"]  # half a pitch off the spline screws

    def _gear_holes(self) -> list[tuple[float, float, float]]:
        r = thread_diameter(self.gear_thread) / 2
        return [(x, y, r) for x, y in ring_points(self.fd0["K_mm"], self.fd0["L_count"],
                                                  self._gear_start_deg())]

    def _port_angles(self) -> tuple[float, float]:
        """Two ports half a turn apart (fill with one, vent with the other; balanced), half a
        pitch off the spline screws so the radial drilling passes between them. The S half is
        built facing the other way (turned about X in the assembly): its angles are mirrored
        so that both halves' ports line up."""
        start = 180.0 / self.fd2["J_count"]
        if self.side == "S":
            start = -start % 360.0
        return start, (start + 180.0) % 360.0

    def _relief(self) -> TurnedRelief | None:
        """Lightening groove in the body between the port spot faces and the holes from the
        outer face, down to a wall over the spline-screw clearance holes; none when shorter
        than RELIEF_MIN_MM."""
        lay = self.lay
        d = thread_diameter(self.screw)  # a wall over the holes, their centres 1.5·d deep
        floor_d = self.fd2["I_mm"] + max(self.clearance + 2 * WALL_MIN_MM, 2 * EDGE_FACTOR * d)
        z0 = max(lay.front_length + WALL_MIN_MM,
                 lay.port_z + lay.port.spot_face / 2 + lay.port.ligament_min)
        z1 = min(lay.thickness - self.cbore_depth,
                 lay.thickness - self.gear_drill_depth - self.tap_drill) - WALL_MIN_MM
        if z1 - z0 < RELIEF_MIN_MM or lay.body_d - floor_d < 2 * RELIEF_MIN_DEPTH_MM:
            return None
        return TurnedRelief(lay.body_d, floor_d, z0, z1)

    # -- solid -----------------------------------------------------------------------------------
    def build(self) -> Part:
        raw = single_solid(self._blank(), self._cutters(), self.label)
        shape, pockets = self._finished(raw), 0.0
        if self.relief is not None:  # mass before and after: the same half without it
            plain = shape.val().Volume()
            shape = self._finished(single_solid(raw.val(), [self.relief.cutter()], self.label))
            pockets = plain - shape.val().Volume()
        return Part(pockets_mm3=pockets, name=f"casing_half_{self.side}", shape=shape, color=COLORS[self.side],
                    dimensions=self._dimensions(), bolt_circles=self._bolt_circles(),
                    notes=casing_notes(self), purchased=self._purchased(),
                    fits=self._fits(), tolerances=self._tolerances(),
                    neighbours=self._neighbours(), material=MATERIAL)

    def _finished(self, shape):
        for outline in {self.lay.outer_d, self.lay.body_d}:
            shape = break_outer_edges(shape, outer_d=outline)
        return shape

    def _blank(self):
        lay, gap = self.lay, self.options.running_gap_mm
        body = cylinder(lay.outer_d, 0, lay.front_length).fuse(
            cylinder(lay.body_d, lay.front_length - 0.01, lay.thickness))
        if self.side == "D":  # the running spigot reaches into the S half past the gap
            body = body.fuse(annulus(lay.spigot_id - 2, lay.gap_journal,
                                     -(gap + lay.gap_seal_length), 0.001))
        return body

    def _cutters(self) -> list:
        lay, fd2 = self.lay, self.fd2
        p, t, gap = lay.pilot_depth, lay.thickness, self.options.running_gap_mm
        cuts = [cylinder(fd2["A_g7_mm"], -1, p),
                cylinder(lay.relief_d, p - 0.1, lay.relief_end),
                cylinder(lay.bearing.D, p - 0.1, lay.shoulder_z),
                self._seat_lead_in(),
                lay.bore_ring.groove(lay.bearing_z - lay.bore_ring.m),
                *lay.seal.bore(lay.shoulder_z, lay.seal_z),
                cylinder(lay.gear_recess_d, lay.seal_z, t + 1),
                lead_in(lay.gear_recess_d, t, RECESS_LEAD_IN_MM, inward=False)]
        if self.side == "S":
            cuts += [cylinder(lay.gap_journal, -1, lay.s_bore_depth),
                     lead_in(fd2["A_g7_mm"], lay.s_bore_depth, 0.8, inward=True),
                     lay.gap_gland.groove_in_bore(lay.gap_journal, lay.gap_groove_z),
                     lead_in(lay.gap_journal, 0.0, 1.0, inward=True)]
        else:
            end = -(gap + lay.gap_seal_length)  # the spigot enters the S half's O-ring
            cuts += [cylinder(lay.spigot_id, end - 1, 0.5),
                     shaft_lead_in(lay.gap_journal, end, lay.gap_gland.d2 / 2, towards=-1),
                     lead_in(fd2["A_g7_mm"], 0.0, 0.8, inward=True)]
        for angle in self.port_angles:
            cuts += lay.port.cutters(lay.body_d / 2, lay.port_radius, lay.port_z, angle)
        for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0):
            cuts += [cylinder(self.clearance, p - 1, t + 1, x, y),
                     cylinder(self.cbore, t - self.cbore_depth, t + 1, x, y)]
        for x, y, _ in self._gear_holes():
            cuts += [blind_hole(self.tap_drill, t, self.gear_drill_depth, x, y),
                     countersink(thread_diameter(self.gear_thread), t, x, y)]
        return cuts

    def _seat_lead_in(self):
        """Lead-in where the bearings enter their seat from the spline side: at the recess
        floor, or at the end of a wider relief (short of the DIN 472 groove's land n)."""
        lay = self.lay
        b, ring = lay.bearing, lay.bore_ring
        if lay.relief_d > b.D:
            return lead_in(b.D, lay.relief_end, min(1.0, 0.5 * ring.n), inward=True)
        return lead_in(b.D, lay.pilot_depth, 1.0, inward=True)

    # -- record ----------------------------------------------------------------------------------
    def _bolt_circles(self) -> list[BoltCircle]:
        fd0, fd2, lay = self.fd0, self.fd2, self.lay
        return [BoltCircle("spline_screws", fd2["I_mm"], fd2["J_count"], self.clearance,
                           self.screw, "clearance", fd2["K_depth_mm"],
                           annulus_inner_mm=lay.relief_d, annulus_outer_mm=lay.body_d,
                           grip_mm=self.grip),
                BoltCircle("gear_mount", fd0["K_mm"], fd0["L_count"], self.tap_drill,
                           self.gear_thread, "tapped", fd0["M_depth_mm"],
                           annulus_inner_mm=lay.gear_recess_d, annulus_outer_mm=lay.body_d,
                           start_angle_deg=self._gear_start_deg())]

    def _dimensions(self) -> dict[str, float]:
        lay, fd2 = self.lay, self.fd2
        dims = {"outer_diameter_mm": lay.outer_d, "body_diameter_mm": lay.body_d,
                "front_length_mm": lay.front_length,
                "pilot_floor_z_mm": lay.pilot_depth, "pilot_recess_mm": fd2["A_g7_mm"],
                "pilot_depth_mm": lay.pilot_depth, "spigot_recess_mm": lay.gear_recess_d,
                "spigot_depth_mm": SPIGOT_DEPTH_MM, "bearing_seat_mm": lay.bearing.D,
                "bearing_seat_z_mm": lay.bearing_z, "bearing_pair_width_mm": 2 * lay.bearing.B,
                "shoulder_z_mm": lay.shoulder_z, "seal_recess_mm": lay.seal.d2,
                "seal_z_mm": lay.seal_z, "relief_diameter_mm": lay.relief_d,
                "relief_end_mm": lay.relief_end,
                "floor_mm": lay.floor,
                "shaft_mm": lay.shaft_d, "seal_shaft_mm": lay.seal.d1,
                "thickness_mm": lay.thickness, "oil_plug_radius_mm": lay.port_radius,
                "oil_port_z_mm": lay.port_z, "oil_port_angles_deg": self.port_angles[0],
                "oil_level_A_mm": lay.level, "level_turn_deg": lay.level_turn_deg,
                "gap_seal_journal_mm": lay.gap_journal, "gap_seal_groove_mm": lay.gap_groove_d,
                "gap_seal_length_mm":
                lay.gap_seal_length, "unit_width_mm": lay.unit_width,
                "counterbore_diameter_mm": self.cbore, "counterbore_depth_mm": self.cbore_depth}
        if lay.outer_d > lay.body_d:  # the step behind the running-gap seal is a face
            dims["front_z_mm"] = lay.front_length
        if self.relief is not None:
            dims.update(relief_groove_floor_mm=self.relief.floor_d,
                        relief_groove_z0_mm=self.relief.z0, relief_groove_z1_mm=self.relief.z1)
        # a point in the cavity between the WG hub and the splines, on the mid-plane
        dims["oil_probe_r_mm"] = (fd2["H_mm"] + fd2["S_mm"]) / 4
        dims["gear_start_deg"] = self._gear_start_deg()
        if self.side == "D":
            dims["spigot_inner_mm"] = lay.spigot_id
            dims["overall_length_mm"] = (lay.thickness + self.options.running_gap_mm
                                         + lay.gap_seal_length)
        return dims

    def _fits(self) -> list:
        lay, fd0, fd2, cat = self.lay, self.fd0, self.fd2, self.catalog
        b = lay.bearing
        fits = [iso286_fit(cat, f"bearing seat {b.designation} ×2 (outer rings)", b.D, "M7",
                           f"{b.designation} outer ring (ISO 492 Normal)",
                           "the casing turns while the gear load stays fixed in space: the "
                           "outer ring turns relative to its load (HOUSING_RULES §1)"),
                iso286_fit(cat, "spline pilot recess", fd2["A_g7_mm"], "H7",
                           f"circular spline {self.side} φA g7 (table 312-1)", "catalog pilot"),
                iso286_fit(cat, "gear/pulley spigot recess", lay.gear_recess_d, "H7",
                           "user's gear or pulley spigot g6", "FD-0 φB H7 (table 311-1)"
                           if lay.gear_recess_d == fd0["B_H7_mm"] else
                           "below FD-0 φB: a 3 mm wall to the spline-screw counterbores"),
                iso286_fit(cat, "lip-seal bore", lay.seal.d2, "H8",
                           f"lip seal outer Ø{lay.seal.d2:g}", "ISO 6194-1 housing bore")]
        if self.side == "S":
            fits.append(iso286_fit(cat, "running-gap seal bore", lay.gap_journal, "H8",
                                   "D half's running spigot f7", "slow rotary O-ring seal"))
        else:
            fits.append(iso286_fit(cat, "running spigot", lay.gap_journal, "f7",
                                   "S half's bore H8", "clearance: the halves turn"))
        return fits

    def _tolerances(self) -> list[GeometricTolerance]:
        rules = "HOUSING_RULES §4 (ISO 1101 / ISO 5459)"
        return [GeometricTolerance("spline pilot recess Ø" + f"{self.fd2['A_g7_mm']:g}",
                                   "datum", None, "A", rules),
                GeometricTolerance("spline face (recess floor)", "datum", None, "B", rules),
                GeometricTolerance("bearing seat", "coaxiality", 0.02, "A", rules),
                GeometricTolerance("bearing shoulder", "axial runout", 0.02, "A", rules),
                GeometricTolerance("gear/pulley spigot recess", "runout", 0.03, "A", rules),
                GeometricTolerance("running-gap seal diameter", "coaxiality", 0.03, "A", rules),
                GeometricTolerance("outer face", "parallelism", 0.02, "B", rules),
                GeometricTolerance("hole circles", "position", 0.1, "B|A", rules)]

    def _purchased(self) -> list[dict]:
        lay = self.lay
        items = [{"item": "bearing", "designation": lay.bearing.text(), "quantity": 2,
                  "note": "support bearing pair Q of table 311-1 (313-2 row IV: 4 per unit)"},
                 {"item": "retaining ring", "designation": f"{lay.bore_ring.standard} "
                  f"{lay.bore_ring.d1:g}×{lay.bore_ring.s:g}", "quantity": 1,
                  "note": "holds the outer rings on the spline side"},
                 {"item": "seal", "designation": f"rotary shaft lip seal {lay.seal.d1:g}×"
                  f"{lay.seal.d2:g}×{lay.seal.b:g} (ISO 6194-1 / DIN 3760)", "quantity": 1,
                  "note": "lip towards the oil"},
                 {"item": "plug", "designation": f"screw plug DIN 908 {lay.port.thread} with "
                  f"{lay.port.ring}", "quantity": 2, "note": "oil fill / level / drain"}]
        if self.side == "S":
            items.append({"item": "O-ring", "designation": f"O-ring ×{lay.gap_gland.d2:g} "
                          f"(ISO 3601-1, ID ≈ {lay.gap_journal:.0f})",
                          "quantity": 1, "note": "running-gap seal between the halves"})
        return items

    def _neighbours(self) -> list[Neighbour]:
        from .fd_review import casing_neighbours
        return casing_neighbours(self)
