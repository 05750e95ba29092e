"""The gear-head side of a GH motor flange: pilot, screws and O-ring from an overlay table.

Seed 003 gives only the motor side of each flange code; the gear-head housing face the flange
bolts onto (pilot, bolt circle, screws, outline) is in the lost figures 053-1 … 064-1 and the
maker's delivery drawings. It comes from the overlay table ``gh_input_interface`` (keyed by
series and size); without it the flange is written with a flat gear-head face and marked
NOT FOR MANUFACTURE. The pilot fit is H7/g6 (ISO 286), the screws are ISO 4762 in ISO 273
medium clearance holes with DIN 974-1 counterbores from the motor face, the O-ring sits in a
face gland of the ISO 3601-2 gland table (:class:`.features.OringGland`).

References
----------
HOUSING_RULES §5 (1) and §4; seed 000 table 028-1 (p.028: O-ring on the input-side flange
face); ISO 286-1/-2, ISO 273, ISO 4762, DIN 974-1, ISO 3601-2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..catalog import Catalog
from .features import OringGland, screw_body, screw_for_grip
from .housing_common import EDGE_FACTOR
from .part import BoltCircle, Neighbour
from .primitives import cylinder, ring_points
from .standards import (DIN_974_1_CBORE_MM, ISO_273_MEDIUM_MM, ISO_4762_HEAD_MM,
                        review_minor_diameter, thread_diameter)

TABLE = "gh_input_interface"
CBORE_SINK_MM = 0.5          # head below the motor face (DIN 974-1: depth k + 0.5)
HOUSING_STUB_MM = 20.0       # modelled depth of the gear-head housing behind its face
SPIGOT_SHORT_MM = 0.5        # a gear-head spigot stops short of the recess floor
HOUSING_WALL_MM = 5.0        # modelled wall of the housing stub inside its pilot
NOT_FOR_MANUFACTURE = ("NOT FOR MANUFACTURE: the gear-head housing face (pilot, bolt circle, "
                       "screws) is not in the seeds (lost figures 053-1 … 064-1); add the "
                       "overlay table gh_input_interface for this series and size")


@dataclass(frozen=True)
class GearHeadFace:
    """The gear-head housing face from ``gh_input_interface`` (one row)."""

    row: dict
    catalog: Catalog

    @property
    def spigot(self) -> bool:
        return self.row["pilot_kind"] == "spigot"

    @property
    def clearance_mm(self) -> float:
        return self.row.get("clearance_hole_mm") or ISO_273_MEDIUM_MM[self.row["bolt_thread"]]

    @property
    def counterbore(self) -> tuple[float, float]:
        """(Ø, depth) of the DIN 974-1 counterbore for the ISO 4762 head."""
        thread = self.row["bolt_thread"]
        return DIN_974_1_CBORE_MM[thread], ISO_4762_HEAD_MM[thread][1] + CBORE_SINK_MM

    @property
    def outline_mm(self) -> float:
        """The gear head's outline [mm, Ø; a □ as its diagonal's circle]: from the overlay,
        else the bolt circle plus a 1.5·d rim (said in the plate's notes)."""
        text = str(self.row.get("outline_mm") or "")
        if text:
            value = float(text.lstrip("□Ø"))
            return value * math.sqrt(2) if text.startswith("□") else value
        return self.row["bolt_circle_mm"] + 2 * EDGE_FACTOR * thread_diameter(
            self.row["bolt_thread"])

    def least_thickness_mm(self, floor_mm: float) -> float:
        """Plate thickness that leaves ``floor_mm`` under the counterbore (and the recess)."""
        recess = 0.0 if self.spigot else self.row["pilot_depth_mm"]
        return self.counterbore[1] + max(floor_mm, thread_diameter(self.row["bolt_thread"]) / 2) \
            + recess

    def solids(self, thickness: float, bore: float) -> tuple[list, list]:
        """(bodies to add, bodies to cut) on a plate from z = 0 (gear-head face) to
        z = thickness (motor face)."""
        r = self.row
        add, cut = [], []
        if self.spigot:
            add.append(cylinder(r["pilot_diameter_mm"], -r["pilot_depth_mm"], 0.0))
            cut.append(cylinder(bore, -r["pilot_depth_mm"] - 1, 1.0))
        else:
            cut.append(cylinder(r["pilot_diameter_mm"], -1.0, r["pilot_depth_mm"]))
        cb_d, cb_depth = self.counterbore
        low = -r["pilot_depth_mm"] - 1 if self.spigot else -1.0
        for x, y in ring_points(r["bolt_circle_mm"], r["bolt_count"],
                                r.get("bolt_start_angle_deg") or 0.0):
            cut.append(cylinder(self.clearance_mm, low, thickness + 1, x, y))
            cut.append(cylinder(cb_d, thickness - cb_depth, thickness + 1, x, y))
        gland = self.gland()
        if gland:
            d1 = self.oring()[0]
            inner = d1 if self.spigot else max(d1, r["pilot_diameter_mm"])
            cut.append(gland.groove_in_face(inner, 0.0, +1))
        return add, cut

    def oring(self) -> tuple[float, float] | None:
        text = self.row.get("oring_d1_d2_mm")
        if not text:
            return None
        d1, d2 = (float(v) for v in str(text).lower().replace("×", "x").split("x"))
        return d1, d2

    def gland(self) -> OringGland | None:
        """The face gland of the overlay's O-ring cross-section (ValueError naming the
        cross-sections of the gland table when d2 is not one of them)."""
        ring = self.oring()
        return None if ring is None else OringGland.from_catalog(self.catalog, ring[1])

    def bolt_circle(self, thickness: float, bore: float, outer: float | None,
                    square: float | None) -> BoltCircle:
        r = self.row
        inner = bore if self.spigot else r["pilot_diameter_mm"]
        return BoltCircle("gear-head screws", r["bolt_circle_mm"], r["bolt_count"],
                          self.clearance_mm, r["bolt_thread"], "clearance",
                          r.get("thread_depth_mm"),
                          annulus_inner_mm=inner, annulus_outer_mm=outer,
                          outline_square_mm=square, grip_mm=thickness - self.counterbore[1],
                          start_angle_deg=r.get("bolt_start_angle_deg") or 0.0)

    def notes(self, table: str = TABLE, far_face: str = "motor face",
              part: str = "the flange") -> list[str]:
        r = self.row
        kind = "spigot into the gear head" if self.spigot else "recess over the gear-head spigot"
        text = [f"gear-head side from overlay table {table} ({r.get('source') or 'overlay'}): "
                f"pilot Ø{r['pilot_diameter_mm']:g} {self.pilot_fit()} ({kind}, "
                f"{r['pilot_depth_mm']:g} mm), {r['bolt_count']} × {r['bolt_thread']} ISO 4762 "
                f"on Ø{r['bolt_circle_mm']:g} in Ø{self.clearance_mm:g} holes, counterbored "
                f"Ø{self.counterbore[0]:g} × {self.counterbore[1]:g} from the {far_face} "
                f"(fit {part} to the gear head first)"]
        ring, gland = self.oring(), self.gland()
        text.append(f"O-ring {ring[0]:g} × {ring[1]:g} in a face gland (depth "
                    f"{gland.face_depth:g}, width {gland.face_width:g}, ISO 3601-2; seed 000 "
                    "table 028-1)" if gland else
                    f"no O-ring size in {table}: seal the face with {r.get('sealant') or 'a liquid gasket'} "
                    "(seed 000 table 028-1 asks for a seal on the input-side flange face)")
        return text

    def screw_length(self, thickness: float) -> tuple[int | None, float]:
        """(ISO 4762 length, engagement) of the gear-head screws seated in the counterbores
        of a plate ``thickness`` thick: the longest length that engages ≥ 1·d (steel, VDI
        2230) without bottoming in the overlay's ``thread_depth_mm``; (None, 0) without it."""
        depth = self.row.get("thread_depth_mm")
        if not depth:
            return None, 0.0
        thread = self.row["bolt_thread"]
        return screw_for_grip(thread, thickness - self.counterbore[1], depth,
                              thread_diameter(thread))

    def neighbours(self, thickness: float) -> list[Neighbour]:
        """The gear-head housing behind the face (z < 0: outline, pilot, tapped holes) and
        its screws, for the review assembly; none without the overlay's thread_depth_mm."""
        length, engaged = self.screw_length(thickness)
        if length is None:
            return []
        r, thread = self.row, self.row["bolt_thread"]
        d = thread_diameter(thread)
        seat = thickness - self.counterbore[1]
        points = ring_points(r["bolt_circle_mm"], r["bolt_count"],
                             r.get("bolt_start_angle_deg") or 0.0)
        dims = {"d": d, "l": length, "grip": seat, "engaged": engaged,
                "thread_depth": r["thread_depth_mm"], "engaged_min": d}
        screws = [Neighbour("screw", f"ISO 4762 {thread}×{length}", dims, seat, xy_mm=(x, y),
                            body=screw_body(thread, seat, length, x, y)) for x, y in points]
        return [self._housing(points)] + screws

    def _housing(self, points) -> Neighbour:
        r = self.row
        pilot, depth = r["pilot_diameter_mm"], r["pilot_depth_mm"]
        body = cylinder(self.outline_mm, -HOUSING_STUB_MM, 0.0)
        if self.spigot:      # the plate's spigot enters the gear head's pilot bore
            body = body.cut(cylinder(pilot, -depth - SPIGOT_SHORT_MM, 0.5))
        else:                # the gear head's spigot enters the plate's recess
            body = body.fuse(cylinder(pilot, -0.5, depth - SPIGOT_SHORT_MM))
        minor = review_minor_diameter(r["bolt_thread"])
        body = body.cut(cylinder(pilot - 2 * HOUSING_WALL_MM, -HOUSING_STUB_MM - 1, depth + 1),
                        *[cylinder(minor, -r["thread_depth_mm"], 0.5, x, y) for x, y in points])
        return Neighbour("gear", "gear-head housing (overlay face)", {"pilot": pilot}, 0.0,
                         body=body.Solids()[0], turns_with="frame")

    def pilot_fit(self) -> str:
        return self.row.get("pilot_fit") or ("g6" if self.spigot else "H7")


def gear_head_face(catalog: Catalog, series: str, size: int) -> GearHeadFace | None:
    row = catalog.find(TABLE, series=series, size=size) if catalog.has(TABLE) else None
    return None if row is None else GearHeadFace(row, catalog)
