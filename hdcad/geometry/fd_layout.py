"""Where everything sits in an FD-…-2 casing half: the numbers, no solids.

Seed 001 p.315: the casings and bearings of an FD-2 used as a differential follow the FD-0
unit. Table 313-2 row IV counts four support bearings Q (table 311-1) per unit, so each casing
half carries a pair on the wave-generator (WG) shaft: a two-point support. The FD-2 WG hub φH
(= the bearing bore) stands out only (E − D)/2 past the spline face, less than one bearing
width, so the bearings sit on a journal sleeve that butts against the hub end.

Axial layout of one half, z from the face towards the other half (z = 0) outwards:

  0 … p            circular spline in the pilot recess Ø FD-2 φA (H7); p = B + C/2 − gap/2.
                   S half: the first ``gap_seal_length`` is a bore for the D half's spigot
                   (running-gap O-ring); D half: the spigot stands out towards −z.
  p … zb           port window: seat bore continued (or a wider relief down to oil level A),
                   the radial oil ports, the DIN 472 groove m wide just below zb
  zb … zb + 2B     bearing pair, outer rings in Ø D M7 against the shoulder at zb + 2B
  … zs             lip-seal bore Ø d2 (the step from D to d2 is the outer-ring shoulder)
  zs … T           gear/pulley spigot recess Ø FD-0 φB (H7)

The sleeve (``fd_sleeve.py``) carries the inner rings between a collar (≥ d_a,min, DIN 5418)
at zb and a DIN 471 ring at zb + 2B, and its journal Ø d runs in the lip seal.
"""

from __future__ import annotations

import math

from ..catalog import Catalog
from ..design_options import DesignOptions
from .features import Bearing, LipSeal, OringGland, PlugPort, RetainingRing
from .housing_common import EDGE_FACTOR

WALL_MIN_MM = 3.0           # machined steel wall (HOUSING_RULES §4)
SPIGOT_CLEARANCE_MM = 0.5   # radial: the D half's spigot over the S spline (they turn)
SPIGOT_END_CLEARANCE_MM = 0.5  # axial: spigot end to the bottom of the S half's bore
GLAND_LAND_MM = 2.0         # land between the running-gap O-ring groove and the bore bottom
# the land on the open-face side is a steel wall (WALL_MIN_MM) at the S half's face
PILOT_MIN_MM = 3.0          # least pilot length left for the S spline beside the gap seal
LEVEL_MARGIN_MM = 2.0       # the port opening reaches this far below level A
SEAL_CLEARANCE_MM = 0.5     # between the DIN 471 ring and the lip seal
SPIGOT_DEPTH_MM = 3.0       # gear/pulley centring recess; no standard depth exists
SEAL_SET_BACK_MM = 2.0      # lip seal pressed this far below the recess floor: the sleeve's
#                             seal track (with its lead-in) then covers the whole seal width
#                             and still ends below the floor the user's gear centres on
GAP_ORING_MAX_MM = 5.33     # largest O-ring cross-section considered for the running gap
PORT_THREAD = "M10×1"
RECESS_LEAD_IN_MM = 0.8     # axial length of the gear recess's 20° lead-in chamfer
# room kept for that chamfer (radius): 0.8·tan 20° = 0.29 mm, rounded up to 0.5
RECESS_LEAD_IN_WIDENING_MM = 0.5


def ceil_to(value: float, step: float) -> float:
    return math.ceil(value / step - 1e-9) * step


class FDLayout:
    """Diameters and axial positions of one casing half and its sleeve (see module doc)."""

    FD0, FD2, OIL = "fd0_dimensions", "fd2_dimensions", "fd_oil_level"
    NEEDED = {FD0: ("A_mm", "B_H7_mm", "D_mm", "K_mm", "L_count", "M_thread", "M_depth_mm",
                    "Q_bearing"),
              FD2: ("A_g7_mm", "B_mm", "C_mm", "D_mm", "E_mm", "H_mm", "I_mm", "J_count",
                    "K_thread", "K_depth_mm", "L_H7_mm")}

    def __init__(self, size: int, catalog: Catalog, options: DesignOptions, label: str):
        self.size, self.label, self.options = size, label, options
        self.fd0 = self._row(catalog, self.FD0)
        self.fd2 = self._row(catalog, self.FD2)
        oil = catalog.find(self.OIL, size=size)
        if oil is None or oil.get("A_mm") is None:
            raise ValueError(f"{label}: oil level A (table 315-1, {self.OIL}) is missing")
        self.level = float(oil["A_mm"])
        try:
            self._parts(catalog)
        except ValueError as exc:
            raise ValueError(f"{label}: {exc}") from None
        self._radial()
        self._axial()

    def _row(self, catalog: Catalog, table: str) -> dict:
        row = catalog.find(table, size=self.size)
        missing = [c for c in self.NEEDED[table] if row.get(c) is None]
        if missing:
            raise ValueError(f"{self.label}: the {table} row lacks {', '.join(missing)}")
        return row

    def _parts(self, catalog: Catalog) -> None:
        self.bearing = Bearing.from_catalog(catalog, str(self.fd0["Q_bearing"]).lstrip("#"))
        b = self.bearing
        self.bore_ring = RetainingRing.from_catalog(catalog, "bore", b.D)
        self.shaft_ring = RetainingRing.from_catalog(catalog, "shaft", b.d)
        self.seal = LipSeal.from_catalog(catalog, b.d)
        self.port = PlugPort.from_catalog(catalog, PORT_THREAD)
        self.shaft_d = self.fd2["L_H7_mm"]       # the user's shaft = the WG hub bore φL
        self.shaft_gland = OringGland.from_catalog(catalog, 1.78)
        self.gap_gland = self._gap_gland(catalog)

    def _gap_gland(self, catalog: Catalog) -> OringGland:
        """Cross-section by diameter (ISO 3601-1 practice: thin sections on small rings)."""
        d = self.fd2["A_g7_mm"]
        d2 = 2.62 if d <= 120 else 3.53 if d <= 250 else GAP_ORING_MAX_MM
        return OringGland.from_catalog(catalog, d2)

    # -- radial ---------------------------------------------------------------------------------
    def _radial(self) -> None:
        b, seal, fd2 = self.bearing, self.seal, self.fd2
        if not (b.land_d1 or b.d) + 1.0 < seal.d2 <= b.housing_shoulder_max:
            raise ValueError(f"{self.label}: the seal bore Ø{seal.d2:g} is the outer-ring "
                             f"shoulder and must lie in ({(b.land_d1 or b.d) + 1:g}, "
                             f"{b.housing_shoulder_max:g}] (DIN 5418)")
        self.collar_d = ceil_to(b.shaft_shoulder_min, 0.5)
        ring_inner = self.bore_ring.d2 - 2 * self.bore_ring.radial
        if ring_inner <= self.collar_d + 1.0:
            raise ValueError(f"{self.label}: the DIN 472 ring (inner Ø{ring_inner:.1f}) would "
                             f"touch the sleeve collar Ø{self.collar_d:g}")
        # the port opening: in the seat bore, or a relief reaching LEVEL_MARGIN below level A
        self.relief_d = max(b.D, 2 * (self.level + LEVEL_MARGIN_MM))
        screw_clear = fd2["I_mm"] / 2 - self._clearance_hole() / 2 - WALL_MIN_MM
        if self.relief_d / 2 > screw_clear:
            raise ValueError(f"{self.label}: a relief down to level A ({self.relief_d / 2:g} mm "
                             f"radius) cuts the spline screws on φI {fd2['I_mm']:g}")
        self.spigot_id = fd2["A_g7_mm"] + 2 * SPIGOT_CLEARANCE_MM
        # rod-type gland: the groove is in the S half's bore, the O-ring seals on the D
        # half's plain spigot (a piston-type gland is not advised for rotation)
        self.gap_journal = self.spigot_id + 2 * WALL_MIN_MM
        self.gap_groove_d = self.gap_journal + 2 * self.gap_gland.radial_depth
        self.gear_recess_d = self._gear_recess()
        self.outer_d = max(self.fd0["A_mm"], ceil_to(self.gap_groove_d + 2 * WALL_MIN_MM, 1.0))
        # behind the running-gap seal the body steps down to the FD-0 outline where it can
        self.body_d = min(self.outer_d, max(self.fd0["A_mm"], self._least_body_d()))

    def _gear_recess(self) -> float:
        """Ø of the user's gear/pulley centring recess: FD-0 φB where the spline-screw
        counterbores on FD-2 φI leave a WALL_MIN wall to it, else the largest whole mm that
        does (sizes 20-32: φB and φI are too close for a machined wall)."""
        from .standards import DIN_974_1_CBORE_MM
        room = (self.fd2["I_mm"] - DIN_974_1_CBORE_MM[self.fd2["K_thread"]] - 2 * WALL_MIN_MM
                - 2 * RECESS_LEAD_IN_WIDENING_MM)
        recess = min(self.fd0["B_H7_mm"], math.floor(room))
        if recess < self.seal.d2 + 2 * WALL_MIN_MM:
            raise ValueError(f"the gear recess Ø{recess:g} leaves no floor around the seal "
                             f"bore Ø{self.seal.d2:g}")
        return recess

    def _least_body_d(self) -> float:
        """Least body Ø behind the seal: the gear holes and the spline-screw counterbores
        keep a wall, and the body carries the port spot faces."""
        from .standards import DIN_974_1_CBORE_MM, thread_diameter
        d = thread_diameter(self.fd0["M_thread"])
        # the gear holes keep a wall and their centres 1.5·d from the outside (HOUSING_RULES §4)
        gear = self.fd0["K_mm"] + max(d + 2 * WALL_MIN_MM, 2 * EDGE_FACTOR * d)
        cbore = self.fd2["I_mm"] + DIN_974_1_CBORE_MM[self.fd2["K_thread"]] + 2 * WALL_MIN_MM
        return max(gear, cbore)

    def _clearance_hole(self) -> float:
        from .standards import ISO_273_MEDIUM_MM
        return ISO_273_MEDIUM_MM[self.fd2["K_thread"]]

    # -- axial ----------------------------------------------------------------------------------
    def _axial(self) -> None:
        fd2, b, gap = self.fd2, self.bearing, self.options.running_gap_mm
        self.pilot_depth = fd2["B_mm"] + fd2["C_mm"] / 2 - gap / 2
        if self.pilot_depth <= 0:
            raise ValueError(f"{self.label}: running_gap_mm {gap:g} leaves no pilot recess "
                             f"(FD-2 B {fd2['B_mm']:g}, C {fd2['C_mm']:g})")
        self.gap_seal_length = self.gap_gland.radial_width + WALL_MIN_MM + GLAND_LAND_MM
        self.gap_groove_z = WALL_MIN_MM + self.gap_gland.radial_width / 2  # groove centre
        self.s_bore_depth = self.gap_seal_length + SPIGOT_END_CLEARANCE_MM
        self.front_length = self.s_bore_depth + WALL_MIN_MM  # full Ø ring at the gap seal
        if self.pilot_depth - self.s_bore_depth < PILOT_MIN_MM:
            raise ValueError(f"{self.label}: the running-gap seal leaves "
                             f"{self.pilot_depth - self.s_bore_depth:.1f} mm of pilot for the "
                             f"S spline (least {PILOT_MIN_MM:g})")
        self.hub_end = fd2["E_mm"] / 2 - gap / 2
        port, ring = self.port, self.bore_ring
        window = port.d + 2 * port.ligament_min  # ligaments from the thread's major Ø
        self.port_z = self.pilot_depth + window / 2
        # a relief wider than the seat ends n (DIN 472 edge distance) below the groove
        seat_end = ring.n if self.relief_d > self.bearing.D else 0.0
        self.relief_end = self.pilot_depth + window
        self.bearing_z = self.pilot_depth + max(window + ring.m + seat_end, ring.m + ring.n)
        if self.bearing_z - self.hub_end < WALL_MIN_MM:
            self.bearing_z = self.hub_end + WALL_MIN_MM  # the collar needs some length
        self.shoulder_z = self.bearing_z + 2 * b.B
        self.seal_z = (self.shoulder_z + self.shaft_ring.s + SEAL_CLEARANCE_MM + self.seal.b
                       + SEAL_SET_BACK_MM)
        self.seal_outer_z = self.seal_z - SEAL_SET_BACK_MM
        self.thickness = self.seal_z + SPIGOT_DEPTH_MM
        self.sleeve_end = self.seal_z - 0.2  # the seal track covers the lip with its lead-in

    # -- derived --------------------------------------------------------------------------------
    @property
    def port_radius(self) -> float:
        """Radius [mm] where the ports open into the cavity."""
        return self.relief_d / 2

    @property
    def level_turn_deg(self) -> float:
        """Angle from the bottom to turn a port to so that its opening stands A below the
        axis (oil runs out down to the opening: the level is then A)."""
        return math.degrees(math.acos(min(1.0, self.level / self.port_radius)))

    @property
    def floor(self) -> float:
        return self.thickness - self.pilot_depth

    @property
    def unit_width(self) -> float:
        return 2 * self.thickness + self.options.running_gap_mm
