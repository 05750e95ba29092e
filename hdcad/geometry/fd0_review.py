"""Neighbour bodies of the FD-0 drive flanges for the review assembly: the FD-0 unit as its
catalog outline (table 311-1: φA × D, the φB recess and the L tapped holes M on φK at each
face, the WG hub φC standing out to the flange bores) and the ISO 4762 casing screws."""

from __future__ import annotations

from ..checks.bolts import MIN_ENGAGEMENT
from .features import screw_body, screw_for_grip
from .part import Neighbour
from .primitives import cylinder, ring_points
from .standards import review_minor_diameter, thread_diameter

RECESS_MM = 2.0   # φB recess depth: not in table 311-1 (figure lost); the smallest FD-0 H


def flange_neighbours(flange, with_unit: bool) -> list[Neighbour]:
    """Screws of one drive flange; the unit outline once (``with_unit``), in the flange's
    frame (mating face z = 0, the unit towards −z)."""
    row, thread = flange.row, flange.thread
    grip = flange.thickness - flange.cbore_depth
    least = MIN_ENGAGEMENT["steel"] * thread_diameter(thread)
    length, engaged = screw_for_grip(thread, grip, row["M_depth_mm"], least)
    out = []
    if length is not None:
        seat = grip
        dims = {"d": thread_diameter(thread), "l": length, "grip": grip, "engaged": engaged,
                "thread_depth": row["M_depth_mm"],
                "engaged_min": MIN_ENGAGEMENT["steel"] * thread_diameter(thread)}
        for x, y in ring_points(flange.ring, flange.count, 0.0):
            out.append(Neighbour("screw", f"ISO 4762 {thread}×{length}", dims, seat,
                                 xy_mm=(x, y), body=screw_body(thread, seat, length, x, y)))
    if with_unit:
        out.append(_unit(flange))
    return out


def _unit(flange) -> Neighbour:
    row = flange.row
    width, minor = row["D_mm"], review_minor_diameter(flange.thread)
    body = cylinder(row["A_mm"], -width, 0.0)
    cuts = [cylinder(row["B_H7_mm"], -RECESS_MM, 0.5),
            cylinder(row["B_H7_mm"], -width - 0.5, -width + RECESS_MM),
            cylinder(row["N_H7_mm"], -width - 1, 1)]
    for x, y in ring_points(flange.ring, flange.count, 0.0):
        cuts += [cylinder(minor, -row["M_depth_mm"], 0.5, x, y),
                 cylinder(minor, -width - 0.5, -width + row["M_depth_mm"], x, y)]
    # the WG hub φC (= bearing bore) stands in the recess at each face, inside the flange bore
    hub = [cylinder(row["C_mm"], -RECESS_MM, 0.0), cylinder(row["C_mm"], -width,
                                                               -width + RECESS_MM)]
    body = body.cut(*cuts).fuse(*[h.cut(cylinder(row["N_H7_mm"], -width - 1, 1)) for h in hub])
    return Neighbour("gear", f"FD-{flange.size}-0 unit (catalog outline, table 311-1)",
                     {"A": row["A_mm"], "D": width}, -width, body=body.Solids()[0],
                     turns_with="unit")
