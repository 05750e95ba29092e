"""Named housing features built from standard tables: bearing, retaining ring, lip-seal bore,
O-ring gland, oil port, lead-in chamfer.

Each feature reads its row from a catalog table named after its standard (bd_warehouse style:
a ValueError names the sizes the table offers), gives the cutters that make it in a part whose
axis is Z, the body of the bought part for the review assembly, and a one-line description with
its standard for the part notes. Cutters are solids to subtract; nothing here builds a whole
part.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cadquery as cq

from ..catalog import Catalog
from .primitives import cylinder

BEARINGS = "deep_groove_bearing_iso15"
ABUTMENTS = "bearing_abutment_din5418"
RINGS = "retaining_ring_din471_din472"
SEALS = "shaft_seal_iso6194"
GLANDS = "oring_gland_iso3601"
PLUGS = "plug_port_din908_din7603"

LEAD_IN_DEG = 20.0      # lead-in chamfer angle on seats and seal bores (HOUSING_RULES §4: 15-30°)
SEAL_DEPTH_ALLOWANCE_MM = 0.3  # seal bore b + 0.3 deep (HOUSING_RULES §2)


def _row(catalog: Catalog, table: str, what: str, key: str, **match) -> dict:
    row = catalog.find(table, **match)
    if row is None:
        known = ", ".join(f"{r[key]:g}" if isinstance(r[key], float) else str(r[key])
                          for r in catalog.rows(table))
        raise ValueError(f"{what} is not in catalog table {table}; known: {known}")
    return row


def annulus(inner_d: float, outer_d: float, z0: float, z1: float) -> cq.Solid:
    """A ring between Ø inner_d and Ø outer_d [mm] from z0 to z1 on the Z axis."""
    return cylinder(outer_d, z0, z1).cut(cylinder(inner_d, z0 - 1, z1 + 1)).Solids()[0]


@dataclass(frozen=True)
class TurnedRelief:
    """A lightening groove turned into an outer cylinder Ø ``outer_d`` down to Ø ``floor_d``
    between z0 and z1 [mm]: material that carries nothing (HOUSING_RULES §4: pocket where
    material is not needed). The floor keeps the holes under it inside a wall."""

    outer_d: float
    floor_d: float
    z0: float
    z1: float
    corner_r: float = 1.0   # floor corners: the turning tool's nose radius

    def cutter(self) -> cq.Solid:
        ring = annulus(self.floor_d, self.outer_d + 2, self.z0, self.z1)
        edges = cq.Workplane().add(ring).edges(
            cq.selectors.RadiusNthSelector(0)).vals()
        return ring.fillet(self.corner_r, edges) if self.corner_r > 0 else ring

    def text(self) -> str:
        return (f"lightening groove Ø{self.floor_d:g} from z {self.z0:g} to {self.z1:g} in the "
                f"Ø{self.outer_d:g} body, floor corners r {self.corner_r:g}")


def lead_in(diameter: float, z_face: float, length: float, inward: bool,
            angle_deg: float = LEAD_IN_DEG) -> cq.Solid:
    """Cone cutter for a lead-in chamfer on a bore Ø ``diameter`` whose open face is at
    ``z_face``; the bore runs towards +z (``inward``) or −z from there."""
    slope = math.tan(math.radians(angle_deg))
    sign = 1.0 if inward else -1.0
    base = z_face - sign * 0.5  # start 0.5 mm beyond the face so the cut is clean
    return cq.Solid.makeCone(diameter / 2 + (length + 0.5) * slope, diameter / 2,
                             length + 0.5, cq.Vector(0, 0, base), cq.Vector(0, 0, sign))


DRILL_POINT_DEG = 118.0    # drill point angle of a blind hole (HOUSING_RULES §4)


def drill_point(diameter: float) -> float:
    """Axial length [mm] of the 118° point below a drilled hole's full diameter: a floor
    under a blind hole is measured from its tip."""
    return diameter / 2 / math.tan(math.radians(DRILL_POINT_DEG / 2))


def blind_hole(diameter: float, z_face: float, depth: float, x: float = 0.0, y: float = 0.0,
               into: int = -1) -> cq.Solid:
    """Cutter of a blind drilled hole Ø ``diameter`` from the face at ``z_face``, ``depth``
    deep (full diameter) towards ``into`` (−1: −z, +1: +z), with its 118° drill point
    beyond; it starts 1 mm outside the face so the cut is clean."""
    tip = drill_point(diameter)
    bottom = z_face + into * depth
    bore = cylinder(diameter, min(z_face - into, bottom), max(z_face - into, bottom), x, y)
    point = cq.Solid.makeCone(diameter / 2, 0.0, tip, cq.Vector(x, y, bottom),
                              cq.Vector(0, 0, into))
    return bore.fuse(point).Solids()[0]


COUNTERSINK_FACTOR = 1.05  # countersink Ø at a tapped hole's entry / thread Ø (DIN 76-1 practice)


def countersink(d_thread: float, z_face: float, x: float = 0.0, y: float = 0.0,
                into: int = -1) -> cq.Solid:
    """90° countersink cutter at the entry of a tapped hole whose face is at ``z_face`` and
    whose hole runs towards ``into`` (−1: −z, +1: +z): Ø 1.05·d at the face, so the first
    thread does not raise a burr on the face and the screw starts cleanly."""
    r = COUNTERSINK_FACTOR * d_thread / 2
    extra = 0.5
    return cq.Solid.makeCone(r + extra, 0.0, r + extra,
                             cq.Vector(x, y, z_face - into * extra), cq.Vector(0, 0, into))


def countersink_depth(d_thread: float, hole_d: float) -> float:
    """Depth [mm] of the 90° entry countersink down to a hole Ø ``hole_d``: no full thread
    there, so it does not count as engagement."""
    return max(COUNTERSINK_FACTOR * d_thread - hole_d, 0.0) / 2


def shaft_lead_in(d: float, z_end: float, length: float, angle_deg: float = LEAD_IN_DEG,
                  towards: int = 1) -> cq.Solid:
    """Cutter for a lead-in chamfer on the end of a shaft or spigot Ø ``d`` whose end face is
    at ``z_end`` and which ends towards +z (``towards`` 1) or −z (−1): ``angle_deg`` to the
    axis over ``length`` [mm], so that a seal lip or an O-ring slides on without being cut
    (ISO 6194-1, ISO 3601-2: 15-25°)."""
    drop = (length + 1) * math.tan(math.radians(angle_deg))
    base = z_end - towards * length
    kept = cq.Solid.makeCone(d / 2, d / 2 - drop, length + 1, cq.Vector(0, 0, base),
                             cq.Vector(0, 0, towards))
    lo, hi = sorted((base, z_end + towards))
    return cylinder(d + 2, lo, hi).cut(kept).Solids()[0]


@dataclass(frozen=True)
class Bearing:
    """A 60xx deep groove ball bearing (ISO 15) with its DIN 5418 abutment limits."""

    designation: str
    d: float
    D: float
    B: float
    r_s: float
    h: float                   # least shoulder height (DIN 5418) for r_s
    land_d1: float | None      # inner-ring land (makers' d1), where known

    @classmethod
    def from_catalog(cls, catalog: Catalog, designation: str) -> "Bearing":
        row = _row(catalog, BEARINGS, f"bearing {designation!r}", "model",
                   model=str(designation))
        abut = [r for r in catalog.rows(ABUTMENTS) if r["r_s_min_mm"] >= row["r_s_min_mm"]]
        if not abut:
            raise ValueError(f"bearing {designation}: chamfer r {row['r_s_min_mm']:g} is beyond "
                             f"catalog table {ABUTMENTS}")
        h = min(abut, key=lambda r: r["r_s_min_mm"])["h_min_mm"]
        return cls(str(designation), row["d_mm"], row["D_mm"], row["B_mm"],
                   row["r_s_min_mm"], h, row.get("d1_approx_mm"))

    @property
    def shaft_shoulder_min(self) -> float:
        """d_a,min = d + 2h [mm]: least shaft-shoulder Ø that carries the inner ring."""
        return self.d + 2 * self.h

    @property
    def housing_shoulder_max(self) -> float:
        """D_a,max = D − 2h [mm]: largest housing-shoulder bore that still carries the outer
        ring (and, being above the inner-ring land, touches only the outer ring)."""
        return self.D - 2 * self.h

    def body(self, z0: float) -> cq.Solid:
        """True-size ring body d × D × B from z0 (review assembly)."""
        return annulus(self.d, self.D, z0, z0 + self.B)

    def text(self) -> str:
        return f"{self.designation} (ISO 15, {self.d:g}×{self.D:g}×{self.B:g})"

    def neighbour(self, z0: float, turns_with: str = ""):
        """The bearing as a review-assembly neighbour at z0."""
        from .part import Neighbour
        return Neighbour("bearing", self.designation, {"d": self.d, "D": self.D, "B": self.B},
                         z0, body=self.body(z0), turns_with=turns_with)


@dataclass(frozen=True)
class RetainingRing:
    """A DIN 471 (shaft) or DIN 472 (bore) retaining ring and its groove."""

    kind: str     # "shaft" | "bore"
    d1: float     # shaft or bore diameter it sits on
    s: float      # ring thickness
    d2: float     # groove diameter
    m: float      # groove width
    n: float      # least edge distance of the groove

    @classmethod
    def from_catalog(cls, catalog: Catalog, kind: str, d1: float) -> "RetainingRing":
        std = "DIN 471" if kind == "shaft" else "DIN 472"
        row = _row(catalog, RINGS, f"{std} ring for Ø{d1:g}", "d1_mm", kind=kind,
                   d1_mm=float(d1))
        return cls(kind, d1, row["s_mm"], row["d2_mm"], row["m_mm"], row["n_mm"])

    @property
    def standard(self) -> str:
        return "DIN 471" if self.kind == "shaft" else "DIN 472"

    @property
    def radial(self) -> float:
        """Radial section of the modelled ring body [mm]: the groove depth plus 1.5 × the
        groove depth standing proud as the abutment (a simplified body; the real ring's
        section tapers, see the standard's figure)."""
        return 2.5 * abs(self.d1 - self.d2) / 2

    def groove(self, z0: float) -> cq.Solid:
        """Groove cutter of width m from z0 towards +z."""
        if self.kind == "bore":
            return cylinder(self.d2, z0, z0 + self.m)
        return annulus(self.d2, self.d1 + 2, z0, z0 + self.m)

    def body(self, z0: float) -> cq.Solid:
        """The ring (thickness s, seated in the groove) from z0 (review assembly)."""
        if self.kind == "bore":
            return annulus(self.d2 - 2 * self.radial, self.d2, z0, z0 + self.s)
        return annulus(self.d2, self.d2 + 2 * self.radial, z0, z0 + self.s)

    def neighbour(self, z0: float, turns_with: str = ""):
        """The ring as a review-assembly neighbour, seated from z0."""
        from .part import Neighbour
        return Neighbour("ring", f"{self.standard} {self.d1:g}×{self.s:g}",
                         {"d1": self.d1, "s": self.s}, z0, body=self.body(z0),
                         turns_with=turns_with)

    def text(self) -> str:
        return (f"{self.standard} {self.d1:g}×{self.s:g}: groove Ø{self.d2:g} × {self.m:g} "
                f"(H13), edge distance ≥ {self.n:g}")


@dataclass(frozen=True)
class LipSeal:
    """A rotary shaft lip seal (ISO 6194-1 / DIN 3760) and its housing bore."""

    d1: float  # shaft
    d2: float  # housing bore
    b: float   # width

    @classmethod
    def from_catalog(cls, catalog: Catalog, shaft_d: float) -> "LipSeal":
        row = _row(catalog, SEALS, f"a lip seal for a Ø{shaft_d:g} shaft", "d1_mm",
                   d1_mm=float(shaft_d))
        return cls(row["d1_mm"], row["d2_mm"], row["b_mm"])

    @property
    def bore_depth(self) -> float:
        return self.b + SEAL_DEPTH_ALLOWANCE_MM

    def bore(self, z_inner: float, z_open: float) -> list[cq.Solid]:
        """Seal bore from its shoulder at ``z_inner`` to the open face ``z_open`` with a
        lead-in chamfer of about 0.1·b (HOUSING_RULES §2)."""
        lo, hi = sorted((z_inner, z_open))
        return [cylinder(self.d2, lo, hi),
                lead_in(self.d2, z_open, 0.1 * self.b + 0.5, inward=z_open < z_inner)]

    def body(self, z0: float) -> cq.Solid:
        return annulus(self.d1, self.d2, z0, z0 + self.b)

    def neighbour(self, z0: float):
        """The seal as a review-assembly neighbour, its inner face at z0."""
        from .part import Neighbour
        return Neighbour("seal", f"lip seal {self.d1:g}×{self.d2:g}×{self.b:g}",
                         {"d1": self.d1, "d2": self.d2, "b": self.b}, z0, body=self.body(z0))

    def text(self) -> str:
        return (f"lip seal {self.d1:g}×{self.d2:g}×{self.b:g} (ISO 6194-1 / DIN 3760): bore "
                f"Ø{self.d2:g} H8 × {self.bore_depth:g}, Ra 1.6-3.2; shaft Ø{self.d1:g} h11, "
                "Ra 0.2-0.8 plunge-ground, ≥ 45 HRC")


@dataclass(frozen=True)
class OringGland:
    """An O-ring gland for cross-section d2 (ISO 3601-1 sizes, ISO 3601-2 proportions)."""

    d2: float
    radial_depth: float
    radial_width: float
    face_depth: float
    face_width: float

    @classmethod
    def from_catalog(cls, catalog: Catalog, d2: float) -> "OringGland":
        row = _row(catalog, GLANDS, f"O-ring cross-section {d2:g}", "d2_mm", d2_mm=float(d2))
        return cls(row["d2_mm"], row["radial_depth_mm"], row["radial_width_mm"],
                   row["face_depth_mm"], row["face_width_mm"])

    @classmethod
    def for_room(cls, catalog: Catalog, radial_room: float) -> "OringGland":
        """The largest cross-section whose radial gland (depth + 2 mm wall under it) fits in
        ``radial_room`` [mm]; ValueError if none does."""
        fits = [r for r in catalog.rows(GLANDS) if r["radial_depth_mm"] + 2.0 <= radial_room]
        if not fits:
            raise ValueError(f"no O-ring gland fits in {radial_room:.2f} mm of radial room")
        return cls.from_catalog(catalog, max(r["d2_mm"] for r in fits))

    def groove_in_shaft(self, shaft_d: float, z_mid: float) -> cq.Solid:
        """Radial groove cut into a spigot/shaft surface Ø shaft_d (piston-type gland)."""
        half = self.radial_width / 2
        return annulus(shaft_d - 2 * self.radial_depth, shaft_d + 2, z_mid - half, z_mid + half)

    def groove_in_bore(self, bore_d: float, z_mid: float) -> cq.Solid:
        """Radial groove cut into a bore Ø bore_d (rod-type gland)."""
        half = self.radial_width / 2
        return cylinder(bore_d + 2 * self.radial_depth, z_mid - half, z_mid + half)

    def ring_in_shaft(self, shaft_d: float, z_mid: float) -> cq.Solid:
        """The O-ring body squeezed in a shaft groove: groove bottom to the mating bore."""
        half = self.radial_width * 0.4
        return annulus(shaft_d - 2 * self.radial_depth, shaft_d, z_mid - half, z_mid + half)

    def ring_in_bore(self, bore_d: float, z_mid: float) -> cq.Solid:
        half = self.radial_width * 0.4
        return annulus(bore_d, bore_d + 2 * self.radial_depth, z_mid - half, z_mid + half)

    def groove_in_face(self, inner_d: float, z_face: float, into: int) -> cq.Solid:
        """Face groove (static, ISO 3601-2 proportions) from Ø inner_d outwards in a face at
        ``z_face`` whose material lies towards ``into`` (+1: +z, −1: −z)."""
        z1 = z_face + into * self.face_depth
        lo, hi = sorted((z_face - into, z1))
        return annulus(inner_d, inner_d + 2 * self.face_width, lo, hi)

    def ring_in_face(self, inner_d: float, z_face: float, into: int) -> cq.Solid:
        """The O-ring squeezed in that groove: groove bottom to the mating face."""
        lo, hi = sorted((z_face, z_face + into * self.face_depth))
        w = self.face_width
        return annulus(inner_d + 0.2 * w, inner_d + 1.8 * w, lo, hi)

    def text(self, where: str, diameter: float) -> str:
        squeeze = 100 * (1 - self.radial_depth / self.d2)
        return (f"O-ring cross-section {self.d2:g} (ISO 3601-1) {where} Ø{diameter:g}: radial "
                f"gland depth {self.radial_depth:g}, width {self.radial_width:g} "
                f"({squeeze:.0f} % squeeze, ISO 3601-2 proportions), groove edges r 0.1-0.2")


@dataclass(frozen=True)
class PlugPort:
    """A radial oil port: DIN 908 screw plug with collar and a DIN 7603 sealing ring."""

    thread: str
    d: float
    tap_drill: float
    collar: float
    collar_height: float
    thread_length: float
    ring: str

    @classmethod
    def from_catalog(cls, catalog: Catalog, thread: str) -> "PlugPort":
        row = _row(catalog, PLUGS, f"plug thread {thread!r}", "thread", thread=thread)
        return cls(thread, row["d_mm"], row["tap_drill_mm"], row["collar_mm"],
                   row["collar_height_mm"], row["thread_length_mm"],
                   f"DIN 7603 {row['ring']}×{row['ring_thickness_mm']:g}")

    @property
    def spot_face(self) -> float:
        return self.collar + 1.0

    @property
    def thread_depth(self) -> float:
        return 1.5 * self.d

    @property
    def ligament_min(self) -> float:
        """Least ligament to any other bore or seat: max(3 mm, 0.5·d) (HOUSING_RULES §3)."""
        return max(3.0, 0.5 * self.d)

    def spot_face_depth(self, outer_r: float) -> float:
        """Depth below the outer cylinder R at which the Ø spot face is flat all round."""
        half = self.spot_face / 2
        return outer_r - math.sqrt(outer_r ** 2 - half ** 2) + 0.2

    def cutters(self, outer_r: float, inner_r: float, z: float, angle_deg: float
                ) -> list[cq.Solid]:
        """Spot face, thread (tap drill) and the drilling through to radius ``inner_r``."""
        direction = cq.Vector(math.cos(math.radians(angle_deg)),
                              math.sin(math.radians(angle_deg)), 0)
        face_r = outer_r - self.spot_face_depth(outer_r)

        def radial(diameter: float, r0: float, r1: float) -> cq.Solid:
            return cq.Solid.makeCylinder(diameter / 2, r1 - r0,
                                         cq.Vector(0, 0, z) + direction * r0, direction)
        return [radial(self.spot_face, face_r, outer_r + 1),
                radial(self.tap_drill, inner_r - 1, face_r + 0.1)]

    def body(self, outer_r: float, z: float, angle_deg: float) -> cq.Solid:
        """Plug (collar outside the spot face, thread inside) for the review assembly."""
        direction = cq.Vector(math.cos(math.radians(angle_deg)),
                              math.sin(math.radians(angle_deg)), 0)
        face_r = outer_r - self.spot_face_depth(outer_r)
        base = cq.Vector(0, 0, z)
        thread = cq.Solid.makeCylinder(self.tap_drill / 2, self.thread_length,
                                       base + direction * (face_r - self.thread_length),
                                       direction)
        collar = cq.Solid.makeCylinder(self.collar / 2, self.collar_height,
                                       base + direction * face_r, direction)
        return thread.fuse(collar).Solids()[0]

    def text(self) -> str:
        return (f"oil port {self.thread} (ISO 261 fine), thread {self.thread_depth:g} deep, "
                f"spot face Ø{self.spot_face:g} square to the hole; plug DIN 908 {self.thread} "
                f"with sealing ring {self.ring}")


# -- screws -----------------------------------------------------------------------------------
def screw_for_grip(thread: str, grip: float, depth: float, least: float
                   ) -> tuple[int | None, float]:
    """(ISO 4762 length, engagement) for a fixed grip [mm]: the longest existing length that
    engages at least ``least`` and does not bottom in a ``depth`` deep thread; (None, 0)."""
    from .standards import preferred_lengths
    fits = [l for l in preferred_lengths(thread) if least <= l - grip <= depth]
    length = max(fits, default=None)
    return length, (length - grip if length else 0.0)


def screw_and_grip(thread: str, grip_max: float, depth: float, least: float
                   ) -> tuple[int | None, float]:
    """(ISO 4762 length, grip) when the counterbore may be sunk: the longest existing length
    that does not bottom with the largest grip, and the grip that leaves it ``least``
    engagement at most (the counterbore is then sunk to that grip)."""
    from .standards import preferred_lengths
    fits = [l for l in preferred_lengths(thread) if l - depth <= grip_max]
    if not fits:
        return None, grip_max
    length = max(fits)
    return length, min(grip_max, length - least)


def screw_body(thread: str, seat_z: float, length: float, x: float, y: float) -> cq.Solid:
    """An ISO 4762 screw for the review assembly: head true size (dk × k) above ``seat_z``,
    the shank at the thread's minor (tap-drill) Ø below it, so that a screw in its tapped
    hole does not count as interference."""
    from .standards import ISO_4762_HEAD_MM, review_minor_diameter
    dk, k = ISO_4762_HEAD_MM[thread]
    minor = review_minor_diameter(thread)
    return cylinder(dk, seat_z, seat_z + k, x, y).fuse(
        cylinder(minor, seat_z - length, seat_z + 0.01, x, y)).Solids()[0]
