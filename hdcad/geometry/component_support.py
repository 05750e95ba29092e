"""Bearing pairs of the CSF/CSG-2A-GR housing and cover: retention to DIN 5418 / DIN 471 /
DIN 472, the seal bore that doubles as the outer-ring shoulder, and the ISO 286 fits."""

from __future__ import annotations

from .features import Bearing, LipSeal, RetainingRing, lead_in
from .fd_layout import ceil_to
from .iso286 import iso286_fit
from .primitives import cylinder

SHOULDER_RING_MM = 3.0   # a separate shoulder ring when the seal bore cannot be the shoulder
SEAL_GAP_MM = 0.5        # DIN 471 ring to the seal


class Retention:
    """A 60xx pair in one bore: DIN 472 ring on the inner side, spacer, shoulder outside;
    inner rings between a collar (≥ d_a,min) and a DIN 471 ring; lip seal outboard."""

    def __init__(self, catalog, designation: str):
        self.bearing = b = Bearing.from_catalog(catalog, designation)
        self.ring_bore = RetainingRing.from_catalog(catalog, "bore", b.D)
        self.ring_shaft = RetainingRing.from_catalog(catalog, "shaft", b.d)
        self.seal = LipSeal.from_catalog(catalog, b.d)
        land = (b.land_d1 or b.d) + 1.0
        self.shoulder_len = (0.0 if land < self.seal.d2 <= b.housing_shoulder_max
                             else SHOULDER_RING_MM)
        self.collar_d = ceil_to(b.shaft_shoulder_min, 0.5)
        ring_inner = self.ring_bore.d2 - 2 * self.ring_bore.radial
        if ring_inner <= self.collar_d + 1.0:
            raise ValueError(f"the DIN 472 ring of {designation} (inner Ø{ring_inner:.1f}) "
                             f"would touch the collar Ø{self.collar_d:g}")

    @property
    def seal_stack(self) -> float:
        """Bore length outboard of the shoulder: DIN 471 ring, a gap, the seal."""
        return self.ring_shaft.s + SEAL_GAP_MM + self.seal.b

    def seal_bore(self, z_shoulder: float, z_open: float) -> list:
        """Shoulder ring (when needed) and seal bore from the pair's outer face to the open
        face, with the seal's lead-in."""
        b, cuts = self.bearing, []
        z = z_shoulder
        if self.shoulder_len:
            cuts.append(cylinder(b.housing_shoulder_max, z - 0.01, z + self.shoulder_len))
            z += self.shoulder_len
        cuts += [cylinder(self.seal.d2, z - 0.01, z_open + 1),
                 lead_in(self.seal.d2, z_open, 0.1 * self.seal.b + 0.5, inward=False)]
        return cuts

    def text(self, where: str) -> str:
        b = self.bearing
        shoulder = (f"the step to the seal bore Ø{self.seal.d2:g}" if not self.shoulder_len
                    else f"a {self.shoulder_len:g} mm shoulder ring Ø{b.housing_shoulder_max:g}")
        return (f"{where}: 2 × {b.text()} with outer and inner spacers of width B; outer rings "
                f"in Ø{b.D:g} H7 between a {self.ring_bore.text()} on the inner side and "
                f"{shoulder} (DIN 5418: ≤ D_a,max {b.housing_shoulder_max:g}); inner rings "
                f"between a collar Ø{self.collar_d:g} (≥ d_a,min {b.shaft_shoulder_min:g}) "
                f"and a {self.ring_shaft.text()}; {self.seal.text()}")


def pair_fits(catalog, r: Retention, where: str, shaft_part: bool) -> list:
    b = r.bearing
    if shaft_part:
        return [iso286_fit(catalog, f"bearing journal {b.designation} ×2", b.d, "k5",
                           f"{b.designation} inner rings", "rotating inner ring, normal "
                           "load (HOUSING_RULES §1)"),
                iso286_fit(catalog, "seal track", b.d, "h11", "lip seal (ISO 6194-1)",
                           "HOUSING_RULES §2")]
    return [iso286_fit(catalog, f"{where} bearing seat {b.designation} ×2", b.D, "H7",
                       f"{b.designation} outer rings", "standing outer ring, the load turns "
                       "with the shaft (HOUSING_RULES §1)"),
            iso286_fit(catalog, f"{where} lip-seal bore", r.seal.d2, "H8", "lip seal",
                       "ISO 6194-1 housing bore")]
