"""Mounting plate of a GH gear head on the machine, from the overlay ``gh_mounting_interface``.

The seeds do not give the gear head's mounting face (its outline figures 050/058 are lost), so
the plate is built only when the user supplies it by overlay, in the columns of
``gh_input_interface`` (series, size, pilot Ø and kind, pilot depth, bolt circle, count,
thread, optional clearance hole, start angle, outline, O-ring or sealant) plus an optional
``bore_mm`` (the through bore for the output shaft or flange).

  z = 0            gear-head face: the gear head's pilot in an H7 recess (or the plate's g6
                   spigot into the gear head), its screws in ISO 273 clearance holes,
                   counterbored (DIN 974-1) from the machine face: fit the plate to the gear
                   head first, then the plate to the machine
  z = 0 … T        plate, □ side; through bore for the output
  corners          four ISO 273 clearance holes for the same screw size into the machine frame,
                   outside the gear head's outline so the heads can be reached from the gear
                   side with the gear head fitted

References
----------
HOUSING_RULES §4 (edge distance 1.5·d, ligaments, walls), §5 (GH gear heads); ISO 273,
ISO 4762, DIN 974-1, ISO 286.
"""

from __future__ import annotations

import math

import cadquery as cq

from ..catalog import Catalog
from .features import screw_body, screw_for_grip
from .gh_interface import GearHeadFace
from .housing_common import EDGE_FACTOR, whole_mm
from .iso286 import iso286_fit
from .part import BoltCircle, GeometricTolerance, Neighbour, Part
from .primitives import break_outer_edges, cylinder, ring_points, single_solid
from .standards import ISO_4762_HEAD_MM, review_minor_diameter, thread_diameter

TABLE = "gh_mounting_interface"
FLOOR_MM = 3.0              # least material under a counterbore or the recess
HEAD_CLEARANCE_MM = 1.0     # corner screw heads clear of the gear head's outline
WALL_MM = 3.0               # bore inside a spigot: a 3 mm steel wall (HOUSING_RULES §4)
FRAME_MM = 20.0             # modelled machine frame behind the plate (an envelope)
FRAME_THREAD_FACTOR = 2.0   # its tapped depth / thread Ø (assumed: 1·d in steel + run-out)
MATERIAL = "S235JR (EN 10025-2)"
COLOR = (0.60, 0.64, 0.58)


class GHMountingPlate:
    """The plate for one gear head (series, size) from its overlay row."""

    def __init__(self, row: dict, catalog: Catalog, label: str):
        self.row, self.catalog, self.label = row, catalog, label
        self.face = GearHeadFace(row, catalog)
        self.thread = row["bolt_thread"]
        self.d = thread_diameter(self.thread)
        self.clearance = self.face.clearance_mm
        self.thickness = whole_mm(max(self.face.least_thickness_mm(FLOOR_MM), 1.5 * self.d,
                                      10.0))
        self.bore = row.get("bore_mm") or (
            row["pilot_diameter_mm"] - 2 * WALL_MM if self.face.spigot
            else row["pilot_diameter_mm"])
        self.head = ISO_4762_HEAD_MM[self.thread][0]
        self.outline = self.face.outline_mm
        self.side, self.corner = self._square()

    def _square(self) -> tuple[float, float]:
        """(□ side, corner-hole offset a): the corner heads clear the outline circle, the
        holes keep 1.5·d to the edges."""
        a = (self.outline / 2 + HEAD_CLEARANCE_MM + self.head / 2) / math.sqrt(2)
        side = max(2 * (a + EDGE_FACTOR * self.d),
                   self.row["bolt_circle_mm"] + 2 * EDGE_FACTOR * self.d)
        return math.ceil(side), math.ceil(side) / 2 - EDGE_FACTOR * self.d

    def build(self) -> Part:
        t = self.thickness
        add, cut = self.face.solids(t, self.bore)
        plate = cq.Solid.makeBox(self.side, self.side, t,
                                 cq.Vector(-self.side / 2, -self.side / 2, 0))
        body = plate.fuse(*add) if add else plate
        cut.append(cylinder(self.bore, -50, t + 1))
        for x, y in ring_points(2 * math.sqrt(2) * self.corner, 4, 45.0):
            cut.append(cylinder(self.clearance, -1, t + 1, x, y))
        shape = break_outer_edges(single_solid(body, cut, self.label), square=self.side)
        return Part(name="mounting_plate", shape=shape, color=COLOR,
                    dimensions=self._dimensions(), bolt_circles=self._bolt_circles(),
                    notes=self._notes(), fits=self._fits(), tolerances=self._tolerances(),
                    material=MATERIAL, neighbours=self._neighbours())

    def _neighbours(self) -> list[Neighbour]:
        """Gear-head housing and its screws (when the overlay gives the thread depth), the
        corner screws with their heads on the gear side and the machine frame's envelope."""
        gear = self.face.neighbours(self.thickness)
        if not gear:
            return []
        t, d = self.thickness, self.d
        depth = FRAME_THREAD_FACTOR * d
        length, engaged = screw_for_grip(self.thread, t, depth, d)
        if length is None:
            return gear
        dims = {"d": d, "l": length, "grip": t, "engaged": engaged, "thread_depth": depth,
                "engaged_min": d}
        points = ring_points(2 * math.sqrt(2) * self.corner, 4, 45.0)
        screws = [Neighbour("screw", f"ISO 4762 {self.thread}×{length}", dims, 0.0,
                            xy_mm=(x, y), flip=True,
                            body=screw_body(self.thread, 0.0, length, x, y).mirror("XY"))
                  for x, y in points]
        minor = review_minor_diameter(self.thread)
        frame = cq.Solid.makeBox(self.side, self.side, FRAME_MM,
                                 cq.Vector(-self.side / 2, -self.side / 2, t)).cut(
            cylinder(self.bore, t - 1, t + FRAME_MM + 1),
            *[cylinder(minor, t - 0.5, t + depth, x, y) for x, y in points])
        return gear + screws + [Neighbour("other", "machine frame (envelope, tapped "
                                          f"{depth:g} deep)", {}, t,
                                          body=frame.Solids()[0], turns_with="frame")]

    def _dimensions(self) -> dict[str, float]:
        r = self.row
        dims = {"square_mm": self.side, "thickness_mm": self.thickness, "bore_mm": self.bore,
                "corner_hole_offset_mm": self.corner, "gear_head_outline_mm": self.outline,
                "head_diameter_mm": self.head}
        key = "spigot_diameter_mm" if self.face.spigot else "pilot_recess_mm"
        dims[key] = r["pilot_diameter_mm"]
        if not self.face.spigot:
            dims["pilot_floor_z_mm"] = r["pilot_depth_mm"]
        if self.bore == r["pilot_diameter_mm"] and not self.face.spigot:
            del dims["bore_mm"]  # the recess runs through: one diameter
        return dims

    def _bolt_circles(self) -> list[BoltCircle]:
        machine = BoltCircle("machine screws", 2 * math.sqrt(2) * self.corner, 4,
                             self.clearance, self.thread, "clearance", None,
                             annulus_inner_mm=self.outline, outline_square_mm=self.side,
                             grip_mm=self.thickness, start_angle_deg=45.0)
        return [self.face.bolt_circle(self.thickness, self.bore, None, self.side), machine]

    def _fits(self) -> list:
        r = self.row
        return [iso286_fit(self.catalog, "gear-head pilot", r["pilot_diameter_mm"],
                           self.face.pilot_fit(), "gear head's output-side pilot (overlay "
                           f"{TABLE})", "locates the gear head on the machine")]

    def _tolerances(self) -> list[GeometricTolerance]:
        rules = "HOUSING_RULES §4 (ISO 1101 / ISO 5459)"
        return [GeometricTolerance("machine face", "datum", None, "A", rules),
                GeometricTolerance("gear-head pilot", "datum", None, "B", rules),
                GeometricTolerance("gear-head face", "parallelism", 0.02, "A", rules),
                GeometricTolerance("gear-head pilot", "perpendicularity", 0.02, "A", rules),
                GeometricTolerance("hole circles", "position", 0.1, "A|B", rules)]

    def _screw_note(self) -> str:
        length, engaged = self.face.screw_length(self.thickness)
        depth = self.row.get("thread_depth_mm")
        if not depth:
            return ("the overlay has no thread_depth_mm for the gear head's tapped holes: the "
                    "gear-head screws' length and engagement and the plate's review assembly "
                    "are not evaluated")
        if length is None:
            return (f"no ISO 4762 {self.thread} length engages ≥ 1·d without bottoming in the "
                    f"gear head's {depth:g} mm thread: choose the screws by hand")
        return (f"gear-head screws ISO 4762 {self.thread}×{length}: engage {engaged:g} mm of the "
                f"gear head's {depth:g} mm thread (overlay); review assembly with the gear-head "
                f"housing, the corner screws and a machine frame tapped "
                f"{FRAME_THREAD_FACTOR:g}·d deep (an envelope)")

    def _notes(self) -> list[str]:
        r = self.row
        outline = ("from the overlay" if r.get("outline_mm") else
                   "not in the overlay: taken as the bolt circle + 1.5·d (check the gear "
                   "head's flange)")
        return self.face.notes(TABLE, "machine face", "the plate") + [
            f"plate □{self.side:g} × {self.thickness:g} ({MATERIAL}); thickness: counterbore "
            f"+ {FLOOR_MM:g} mm floor, ≥ 1.5·d and ≥ 10 mm",
            f"through bore Ø{self.bore:g} for the output "
            + ("(overlay bore_mm)" if r.get("bore_mm") else
               "(overlay has no bore_mm: the pilot Ø" + (f" less a {WALL_MM:g} mm wall)"
                                                         if self.face.spigot else ")")),
            self._screw_note(),
            f"4 × Ø{self.clearance:g} for {self.thread} into the machine frame at the corners "
            f"(□{2 * self.corner:g} pattern), heads {HEAD_CLEARANCE_MM:g} mm clear of the gear "
            f"head outline Ø{self.outline:.1f} ({outline}): reachable with the gear head fitted",
        ]


def mounting_plate(catalog: Catalog, series: str, size: int) -> GHMountingPlate | None:
    row = catalog.find(TABLE, series=series, size=size) if catalog.has(TABLE) else None
    return None if row is None else GHMountingPlate(row, catalog,
                                                    f"{series}-{size} mounting plate")


__all__ = ["GHMountingPlate", "mounting_plate"]
