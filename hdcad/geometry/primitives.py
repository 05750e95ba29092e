"""Shape helpers every part family uses: cylinders on Z, hole rings, one clean solid."""

from __future__ import annotations

import math

import cadquery as cq


def cylinder(diameter: float, z0: float, z1: float, x: float = 0.0, y: float = 0.0) -> cq.Solid:
    """A cylinder of ``diameter`` [mm] parallel to Z from z0 to z1, centred on (x, y)."""
    return cq.Solid.makeCylinder(diameter / 2, z1 - z0, cq.Vector(x, y, z0))


def polar(radius: float, angle_deg: float) -> tuple[float, float]:
    a = math.radians(angle_deg)
    return radius * math.cos(a), radius * math.sin(a)


def ring_points(ring_d: float, count: int, start_deg: float) -> list[tuple[float, float]]:
    """Centres of ``count`` evenly spaced holes on Ø ring_d, the first at start_deg."""
    return [polar(ring_d / 2, start_deg + 360.0 * i / count) for i in range(count)]


def single_solid(body: cq.Shape, cutters: list[cq.Shape], label: str) -> cq.Workplane:
    """body minus cutters as one clean solid; ValueError if the cut split or emptied it."""
    solids = body.cut(*cutters).clean().Solids()
    if len(solids) != 1:
        raise ValueError(f"{label}: the cut left {len(solids)} solids instead of one")
    return cq.Workplane("XY").add(solids[0])


# ISO 13715 edge break on outer edges: 0.5 × 45° (HOUSING_RULES §4), a design choice
EDGE_BREAK_MM = 0.5


def break_outer_edges(part: cq.Workplane, outer_d: float | None = None,
                      square: float | None = None, size: float = EDGE_BREAK_MM
                      ) -> cq.Workplane:
    """Chamfer ``size`` × 45° on the edges of the outer outline (round Ø ``outer_d`` or
    square ``square`` centred on Z): the sharp outer corners a machinist breaks anyway."""
    def on_outline(edge) -> bool:
        # a round outline's breaks are its full circles (cuts through the rim, such as a
        # port's spot face, leave other edges on the cylinder that are not broken)
        if square is None and edge.geomType() != "CIRCLE":
            return False
        for t in (0.0, 0.5, 1.0):
            p = edge.positionAt(t)
            if square is not None:
                dist = max(abs(p.x), abs(p.y)) - square / 2
            else:
                dist = math.hypot(p.x, p.y) - outer_d / 2
            if abs(dist) > 1e-6:
                return False
        return True

    return _chamfer_where(part, on_outline, size)


def _chamfer_where(part: cq.Workplane, wanted, size: float) -> cq.Workplane:
    """Chamfer ``size`` × 45° on the edges for which ``wanted(edge)`` holds (none: as is)."""
    solid = part.val()
    edges = [e for e in solid.Edges() if wanted(e)]
    return cq.Workplane("XY").add(solid.chamfer(size, None, edges)) if edges else part


def chamfer_circles(part: cq.Workplane, circles: list[tuple[float, float]],
                    size: float = EDGE_BREAK_MM) -> cq.Workplane:
    """Chamfer ``size`` × 45° on the circular edges of diameter d at axial position z, for
    each (d, z) [mm] in ``circles`` (edges on the Z axis); circles not found are skipped."""
    def wanted(edge) -> bool:
        if edge.geomType() != "CIRCLE":
            return False
        c, r = edge.Center(), edge.radius()
        return any(abs(2 * r - d) < 1e-6 and abs(c.z - z) < 1e-6 and math.hypot(c.x, c.y) < 1e-6
                   for d, z in circles)

    return _chamfer_where(part, wanted, size)
