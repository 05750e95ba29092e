"""Journal sleeve of an FD-…-2 casing half: carries the bearing pair's inner rings and the lip
seal's running track on the user's wave-generator shaft.

Built in the casing half's own frame (z = 0 at the half's face towards the other half), from
the WG hub end to just inside the lip seal's outer face; see ``fd_layout.py``.
"""

from __future__ import annotations

from ..catalog import Catalog
from ..design_options import DesignOptions
from .fd_casing import COLORS, FDCasingHalf
from .fd_notes import sleeve_notes
from .iso286 import iso286_fit
from .part import GeometricTolerance, Part
from .features import shaft_lead_in
from .primitives import chamfer_circles, cylinder, single_solid

MATERIAL = "C45 (EN ISO 683-1), seal track induction-hardened ≥ 45 HRC"


class FDSleeve:
    """Sleeve for side S or D; takes the casing half's layout."""

    def __init__(self, size: int, catalog: Catalog, options: DesignOptions | None = None,
                 side: str = "S"):
        half = FDCasingHalf(size, catalog, options, side)
        self.half, self.lay, self.fd2, self.side = half, half.lay, half.fd2, side
        self.catalog = catalog
        lay = self.lay
        self.z0, self.z1 = lay.hub_end, lay.sleeve_end
        self.oring_z = (lay.hub_end + lay.bearing_z) / 2
        room = (lay.collar_d - lay.shaft_d) / 2
        if room < lay.shaft_gland.radial_depth + 2.0:
            raise ValueError(f"FD-{size}-2 sleeve: {room:.1f} mm wall under the collar is too "
                             "thin for the shaft O-ring gland")

    def build(self) -> Part:
        lay = self.lay
        b = lay.bearing
        body = cylinder(lay.collar_d, self.z0, lay.bearing_z).fuse(
            cylinder(b.d, lay.bearing_z - 0.01, self.z1))
        cuts = [cylinder(lay.shaft_d, self.z0 - 1, self.z1 + 1),
                lay.shaft_ring.groove(lay.shoulder_z),
                lay.shaft_gland.groove_in_bore(lay.shaft_d, self.oring_z),
                shaft_lead_in(b.d, self.z1, 1.5, 20.0)]
        shape = single_solid(body, cuts, f"FD sleeve {self.side}")
        # edge breaks: both bore ends (the sleeve slides onto the shaft) and the collar's
        # hub-side edge; the collar's bearing face keeps its full Ø ≥ d_a,min
        shape = chamfer_circles(shape, [(lay.shaft_d, self.z0), (lay.shaft_d, self.z1),
                                        (lay.collar_d, self.z0)])
        return Part(name=f"sleeve_{self.side}", shape=shape, color=_lighter(COLORS[self.side]),
                    dimensions=self._dimensions(), notes=sleeve_notes(self),
                    purchased=self._purchased(), fits=self._fits(),
                    tolerances=[GeometricTolerance("bore", "datum", None, "A", "ISO 5459"),
                                GeometricTolerance("bearing journal", "runout", 0.01, "A",
                                                   "HOUSING_RULES §4"),
                                GeometricTolerance("collar face", "axial runout", 0.01, "A",
                                                   "HOUSING_RULES §4")],
                    neighbours=self._neighbours(), material=MATERIAL, turns_with="shaft")

    def _dimensions(self) -> dict[str, float]:
        lay = self.lay
        return {"outer_diameter_mm": lay.collar_d, "journal_diameter_mm": lay.bearing.d,
                "bore_mm": lay.shaft_d, "sleeve_start_mm": self.z0, "sleeve_end_mm": self.z1,
                "thickness_mm": self.z1 - self.z0, "collar_length_mm": lay.bearing_z - self.z0,
                "ring_groove_z_mm": lay.shoulder_z, "shaft_oring_z_mm": self.oring_z}

    def _fits(self) -> list:
        lay, cat = self.lay, self.catalog
        b = lay.bearing
        return [iso286_fit(cat, f"bearing journal {b.designation} ×2 (inner rings)", b.d, "k5",
                           f"{b.designation} inner ring (ISO 492 Normal)",
                           "rotating inner ring, normal load (HOUSING_RULES §1)"),
                iso286_fit(cat, "seal track", b.d, "h11", "lip seal (ISO 6194-1)",
                           "HOUSING_RULES §2"),
                iso286_fit(cat, "bore", lay.shaft_d, "H7", "user's shaft g6",
                           "slide fit, clamped axially against the WG hub")]

    def _purchased(self) -> list[dict]:
        lay = self.lay
        return [{"item": "retaining ring", "designation": f"DIN 471 {lay.shaft_ring.d1:g}×"
                 f"{lay.shaft_ring.s:g}", "quantity": 1, "note": "holds the inner rings"},
                {"item": "O-ring", "designation": f"O-ring {lay.shaft_d:g}×"
                 f"{lay.shaft_gland.d2:g} (ISO 3601-1)", "quantity": 1,
                 "note": "seals the sleeve bore on the shaft"}]

    def _neighbours(self) -> list:
        from .fd_review import sleeve_neighbours
        return sleeve_neighbours(self)


def _lighter(color):
    return tuple(min(1.0, c + 0.15) for c in color)
