"""Measuring helpers for the STEP round-trip tests: export a part, re-import it with
cadquery's STEP reader and read diameters and hole positions from its cylindrical faces.

Same approach as tests/test_geometry_fd_casing.py (which keeps its own copies).
"""

import math

import cadquery as cq
from OCP.BRepAdaptor import BRepAdaptor_Surface

from hdcad.geometry.part import export_step

TOL = 0.01  # mm: STEP stores the exact B-rep, so a re-imported diameter agrees to rounding


def step_round_trip(part, folder) -> cq.Shape:
    """Write ``part`` as STEP into ``folder`` and read it back (one shape)."""
    path = folder / f"{part.name}.step"
    export_step(part, path)
    return cq.importers.importStep(str(path)).val()


def z_cylinders(shape) -> set[tuple[float, float, float]]:
    """(x, y, radius) of every cylindrical face whose axis is parallel to Z, deduplicated."""
    found = set()
    for face in shape.Faces():
        if face.geomType() != "CYLINDER":
            continue
        cyl = BRepAdaptor_Surface(face.wrapped).Cylinder()
        if abs(abs(cyl.Axis().Direction().Z()) - 1.0) > 1e-9:
            continue
        loc = cyl.Location()
        found.add((round(loc.X(), 4), round(loc.Y(), 4), round(cyl.Radius(), 4)))
    return found


def holes_on_circle(cylinders, circle_d: float, hole_d: float) -> set[tuple[float, float]]:
    """Centres of holes Ø hole_d whose centre lies on the circle Ø circle_d (± TOL)."""
    return {(x, y) for x, y, r in cylinders
            if abs(r - hole_d / 2) <= TOL and abs(math.hypot(x, y) - circle_d / 2) <= TOL}


def measured_circle_diameter(centres) -> float:
    """Mean bolt-circle diameter of hole centres on a circle about the Z axis."""
    return 2 * sum(math.hypot(x, y) for x, y in centres) / len(centres)


def central_diameters(cylinders) -> set[float]:
    """Diameters of the cylindrical faces on the Z axis."""
    return {2 * r for x, y, r in cylinders if math.hypot(x, y) <= TOL}


def torus_minor_radii(shape) -> set[float]:
    """Minor radii of the toroidal faces (edge fillets on round edges)."""
    return {round(BRepAdaptor_Surface(f.wrapped).Torus().MinorRadius(), 4)
            for f in shape.Faces() if f.geomType() == "TORUS"}
