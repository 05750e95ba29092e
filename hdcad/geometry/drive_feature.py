"""The driving feature of an FD-0 drive flange: what turns the user's gear or pulley.

Design option ``drive`` (the user chooses; the catalog gives only the hub, seed 001 p.302):
* ``key``: a parallel key on the hub, keyseat b × t1 from JIS B 1301 for the hub diameter
  (the gear's bore gets the matching keyway t2);
* ``bolts``: ``count`` tapped holes ``thread`` on a circle ``circle_mm`` in the hub's end face
  (thread depth 1.5·d, drilled 3·P deeper);
* ``pins``: ``count`` dowel holes Ø ``diameter_mm`` H7 on ``circle_mm``, 2·d deep (ISO 8734
  dowels).
A circle that does not fit between the bore and the hub raises ValueError naming the range.

References
----------
JIS B 1301 (parallel keys), ISO 261/ISO 2306 (threads, tap drills), ISO 8734 (dowel pins).
"""

from __future__ import annotations

import cadquery as cq

from ..catalog import Catalog
from ..checks.input_bore import select_key
from .part import BoltCircle
from .primitives import cylinder, ring_points
from .standards import ISO_261_PITCH_MM, TAP_DRILL_MM, thread_diameter

MARGIN_MM = 1.5     # least ligament from a hole to the bore or the hub's outside
TAP_DEPTH_D = 1.5   # usable thread depth in steel, × d
PIN_DEPTH_D = 2.0   # dowel hole depth, × d


def drive_feature(spec: dict, hub_d: float, bore: float, z_face: float, z_top: float,
                  catalog: Catalog) -> tuple[list, list[BoltCircle], list[str]]:
    """(cutters, bolt circles, notes) of the chosen feature on a hub Ø ``hub_d`` from z_face
    to z_top around a bore Ø ``bore``."""
    kind = spec.get("kind", "none")
    if kind == "key":
        return _key(hub_d, z_face, z_top, catalog)
    if kind in ("bolts", "pins"):
        return _holes(kind, spec, hub_d, bore, z_top)
    return [], [], ["no driving feature chosen (design option drive): the user's gear is "
                    "centred on the hub and fastened by the user"]


def _key(hub_d: float, z_face: float, z_top: float, catalog: Catalog):
    row = select_key(hub_d, catalog.rows("parallel_key_jisb1301"))
    if row is None:
        raise ValueError(f"drive key: no JIS B 1301 key for a Ø{hub_d:g} hub")
    b, t1 = row["b_mm"], row["t1_mm"]
    r = hub_d / 2
    seat = cq.Solid.makeBox(t1 + 1.0, b, z_top - z_face + 1.0,
                            cq.Vector(r - t1, -b / 2, z_face))
    note = (f"drive: parallel key {b:g} × {row['h_mm']:g} (JIS B 1301) on the Ø{hub_d:g} hub, "
            f"keyseat {b:g} wide × {t1:g} deep over the hub length; the gear's bore keyway is "
            f"{row['t2_mm']:g} deep")
    return [seat], [], [note]


def _holes(kind: str, spec: dict, hub_d: float, bore: float, z_top: float):
    count, circle = int(spec["count"]), float(spec["circle_mm"])
    if kind == "bolts":
        thread = spec["thread"]
        d, hole = thread_diameter(thread), TAP_DRILL_MM[thread]
        depth = TAP_DEPTH_D * d
        drill = depth + 3 * ISO_261_PITCH_MM[thread]
    else:
        d = hole = float(spec["diameter_mm"])
        depth = drill = PIN_DEPTH_D * d
    low, high = bore + d + 2 * MARGIN_MM, hub_d - d - 2 * MARGIN_MM
    if not low <= circle <= high:
        raise ValueError(f"drive {kind}: circle_mm {circle:g} must lie in [{low:g}, {high:g}] "
                         f"to fit between the Ø{bore:g} bore and the Ø{hub_d:g} hub")
    cutters = [cylinder(hole, z_top - drill, z_top + 1, x, y)
               for x, y in ring_points(circle, count, 0.0)]
    if kind == "bolts":
        circles = [BoltCircle("gear screws", circle, count, hole, spec["thread"], "tapped",
                              depth, annulus_inner_mm=bore, annulus_outer_mm=hub_d)]
        note = (f"drive: {count} × {spec['thread']} tapped {depth:g} deep (drilled Ø{hole:g} × "
                f"{drill:g}) on Ø{circle:g} in the hub's end face for the user's gear")
    else:
        circles = []
        note = (f"drive: {count} dowel holes Ø{d:g} H7 × {depth:g} deep on Ø{circle:g} in the "
                "hub's end face (ISO 8734 dowels)")
    return cutters, circles, [note]
