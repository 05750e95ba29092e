"""The oil cavity of a generated housing and the oil volume below a level.

The axis is Z; "horizontal axis" means gravity along −Y, so the oil surface at level A is
the plane y = −A. Volumes come from OCCT booleans on the cavity solid.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import cadquery as cq

from .part import Part
from .primitives import cylinder


@dataclass
class OilCavity:
    solid: cq.Shape
    depth_mm: float          # how far the cavity reaches below the axis
    seal_shaft_mm: float | None
    note: str                # what the cavity volume includes and leaves out
    openings: list[str] = field(default_factory=list)  # gaps in its wall below the axis


def fd_casing_cavity(parts: list[Part]) -> OilCavity:
    """The space the two FD casing halves enclose, in assembly coordinates.

    The pilot recesses between the two spline faces and each half's port window (seat bore
    or relief from the spline face to the bearings), less the user's shaft and the journal
    sleeves. The component
    set itself sits in it; its own volume is not in the catalog, so the oil volume from this
    cavity is an upper bound. The running gap is closed by the O-ring on the D half's spigot.
    """
    halves = [p for p in parts if "pilot_recess_mm" in p.dimensions]
    pilot = min(p.dimensions["pilot_recess_mm"] for p in halves)
    pieces = []
    for half in halves:
        d = half.dimensions
        sign = -1.0 if half.flip else 1.0
        z_face = half.offset_z_mm + sign * d["pilot_depth_mm"]
        z_relief = half.offset_z_mm + sign * d["relief_end_mm"]
        z_bearing = half.offset_z_mm + sign * d["bearing_seat_z_mm"]
        pieces += [cylinder(d["relief_diameter_mm"], *sorted((z_face, z_relief))),
                   cylinder(d["bearing_seat_mm"], *sorted((z_relief, z_bearing)))]
    ends = [half.offset_z_mm + (-1.0 if half.flip else 1.0) * half.dimensions["pilot_depth_mm"]
            for half in halves]
    z0, z1 = min(ends), max(ends)
    shaft = min(p.dimensions["shaft_mm"] for p in halves)
    sleeves = [p.placed() for p in parts if p.name.startswith("sleeve")]
    solid = cylinder(pilot, z0, z1).fuse(*pieces).cut(
        cylinder(shaft, z0 - 200, z1 + 200), *sleeves).clean()
    seal_shaft = min(p.dimensions["seal_shaft_mm"] for p in halves)
    return OilCavity(solid, pilot / 2, seal_shaft,
                     " at most: the pilot recesses and the port windows less the shaft and sleeves; the "
                     "component set's own volume below the level is not in the catalog and is "
                     "not subtracted", [])


def volume_below_mL(solid: cq.Shape, level_mm: float) -> float:
    """Volume [mL] of ``solid`` below the plane y = −level_mm."""
    box = solid.BoundingBox()
    if box.ymin >= -level_mm:
        return 0.0
    height = -level_mm - box.ymin
    cutter = cq.Solid.makeBox(box.xlen + 2, height, box.zlen + 2,
                              cq.Vector(box.xmin - 1, box.ymin, box.zmin - 1))
    return solid.intersect(cutter).Volume() / 1000.0


def component_set_cavity(parts: list[Part]) -> OilCavity:
    """The space inside a 2A-GR housing and input cover, in assembly coordinates.

    Housing cavity + cover cavity + the circular spline's bore between them (taken at the
    smaller of the two cavity diameters), less the output flange and the input shaft. The
    gear's own volume (FS, WG, CS teeth) is not in the overlay tables: the oil volume from
    this cavity is an upper bound.
    """
    by_name = {p.name: p for p in parts}
    housing, cover = by_name["housing"].dimensions, by_name["input_cover"]
    cs_face = cover.offset_z_mm  # the cover is flipped: its mating face sits on the CS face
    d_cover, depth = cover.dimensions["cavity_diameter_mm"], cover.dimensions["cavity_depth_mm"]
    d_housing = housing["cavity_diameter_mm"]
    pieces = [cylinder(d_housing, housing["cavity_z0_mm"], housing["cavity_z1_mm"]),
              cylinder(d_cover, cs_face - depth, cs_face),
              cylinder(min(d_housing, d_cover), cs_face, 0.0)]
    shaft = cover.dimensions["seal_shaft_mm"]
    solid = pieces[0].fuse(*pieces[1:]).cut(
        by_name["output_flange"].placed(),
        cylinder(shaft, cs_face - depth, housing["cavity_z1_mm"])).clean()
    seal_shaft = max(shaft, housing["seal_shaft_mm"])
    return OilCavity(solid, max(d_housing, d_cover) / 2, seal_shaft,
                     " at most: housing and cover cavities and the circular-spline bore less "
                     "the output flange and the input shaft; the gear's own volume below the "
                     "level is not in the overlay tables and is not subtracted")
