"""Geometry of the re-imported STEP solid: discretisation, measurement, projection and
section (OCCT hidden-line removal and planar sections)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import cadquery as cq
import numpy as np
from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Surface
from OCP.BRepLib import BRepLib
from OCP.BRepTools import BRepTools_WireExplorer
from OCP.GCPnts import GCPnts_QuasiUniformDeflection
from OCP.GeomAbs import GeomAbs_Line
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt
from OCP.HLRAlgo import HLRAlgo_Projector
from OCP.HLRBRep import HLRBRep_Algo, HLRBRep_HLRToShape
from OCP.TopAbs import TopAbs_REVERSED
from .conventions import DEFLECTION_MM, TOLERANCE_MM


def load_step_solid(step_path: Path) -> cq.Solid:
    """The single solid of a STEP file; ValueError if it holds none or several."""
    solids = cq.importers.importStep(str(step_path)).solids().vals()
    if len(solids) != 1:
        raise ValueError(f"{Path(step_path).name}: expected one solid, found {len(solids)}")
    return solids[0]


def edge_points(edge, deflection: float = DEFLECTION_MM) -> np.ndarray:
    """Points [mm] along a TopoDS edge, shape (n, 3), in the edge's own direction."""
    curve = BRepAdaptor_Curve(edge)
    u0, u1 = curve.FirstParameter(), curve.LastParameter()
    if curve.GetType() == GeomAbs_Line:
        params = [u0, u1]
    else:
        sampler = GCPnts_QuasiUniformDeflection(curve, deflection, u0, u1)
        params = [sampler.Parameter(i) for i in range(1, sampler.NbPoints() + 1)]
    pts = np.array([curve.Value(u).Coord() for u in params])
    return pts[::-1] if edge.Orientation() == TopAbs_REVERSED else pts


def wire_ring(wire: cq.Wire) -> np.ndarray:
    """Closed polygon of a wire, shape (n, 3), edges chained in order."""
    explorer, chunks = BRepTools_WireExplorer(wire.wrapped), []
    while explorer.More():
        chunks.append(edge_points(explorer.Current())[:-1])
        explorer.Next()
    return np.vstack(chunks)


@dataclass
class Cylinder:
    """A cylindrical face with its axis along Z: diameter, axis position, z-range [mm]."""

    diameter: float
    x: float
    y: float
    z0: float
    z1: float

    @property
    def on_axis(self) -> bool:
        return math.hypot(self.x, self.y) < TOLERANCE_MM


def cylinder_faces(shape: cq.Shape) -> list[tuple]:
    """(face, radius, axis location (x, y), |axis · Z|) of every cylindrical face [mm]."""
    out = []
    for face in shape.Faces():
        if face.geomType() != "CYLINDER":
            continue
        cyl = BRepAdaptor_Surface(face.wrapped).Cylinder()
        loc, axis = cyl.Axis().Location(), cyl.Axis().Direction()
        out.append((face, cyl.Radius(), (loc.X(), loc.Y()), abs(axis.Z())))
    return out


def z_cylinders(shape: cq.Shape) -> list[Cylinder]:
    """Every cylindrical face of ``shape`` whose axis is parallel to Z."""
    out = []
    for face, radius, (x, y), along_z in cylinder_faces(shape):
        if abs(along_z - 1) < 1e-9:
            box = face.BoundingBox()
            out.append(Cylinder(2 * radius, x, y, box.zmin, box.zmax))
    return out


def axial_features(cylinders: list[Cylinder]) -> list[Cylinder]:
    """On-axis cylinders merged per diameter where their z-ranges touch (faces split by
    seams or cuts are one turned surface), sorted by z."""
    merged: list[Cylinder] = []
    for c in sorted((c for c in cylinders if c.on_axis), key=lambda c: (c.diameter, c.z0)):
        last = merged[-1] if merged else None
        if (last and abs(last.diameter - c.diameter) < TOLERANCE_MM
                and c.z0 <= last.z1 + TOLERANCE_MM):
            last.z1 = max(last.z1, c.z1)
        else:
            merged.append(Cylinder(c.diameter, 0.0, 0.0, c.z0, c.z1))
    return sorted(merged, key=lambda c: c.z0)


def z_planes(shape: cq.Shape) -> list[float]:
    """z [mm] of every planar face normal to Z."""
    out = []
    for face in shape.Faces():
        if face.geomType() == "PLANE" and abs(abs(face.normalAt().z) - 1) < 1e-9:
            out.append(face.Center().z)
    return out


def hlr_polylines(shape: cq.Shape, normal, x_dir) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """Visible and hidden edges seen from ``normal`` (orthographic), as 2-D polylines in the
    projection frame (x along ``x_dir``, y along normal × x_dir)."""
    algo = HLRBRep_Algo()
    algo.Add(shape.wrapped)
    algo.Projector(HLRAlgo_Projector(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(*normal), gp_Dir(*x_dir))))
    algo.Update()
    algo.Hide()
    hlr = HLRBRep_HLRToShape(algo)
    visible = [hlr.VCompound(), hlr.OutLineVCompound()]
    hidden = [hlr.HCompound(), hlr.OutLineHCompound()]
    return _compound_lines(visible), _compound_lines(hidden)


def _compound_lines(compounds) -> list[np.ndarray]:
    lines = []
    for compound in compounds:
        if compound.IsNull():
            continue
        BRepLib.BuildCurves3d_s(compound, 1e-6)  # HLR edges may carry 2-D curves only
        lines += [edge_points(e.wrapped)[:, :2] for e in cq.Shape.cast(compound).Edges()]
    return lines


def xz_section(shape: cq.Shape, x_min: float, x_max: float) -> list[list[np.ndarray]]:
    """Cut faces of ``shape`` in the plane y = 0 between x_min and x_max, each as a list of
    rings (outer first) of (z, x) points [mm]."""
    box = shape.BoundingBox()
    z0, z1 = box.zmin - 1.0, box.zmax + 1.0
    plane = cq.Face.makeFromWires(cq.Wire.makePolygon(
        [(x_min, 0, z0), (x_max, 0, z0), (x_max, 0, z1), (x_min, 0, z1)], close=True))
    faces = []
    for face in shape.intersect(plane).Faces():
        rings = [wire_ring(face.outerWire())] + [wire_ring(w) for w in face.innerWires()]
        faces.append([r[:, [2, 0]] for r in rings])
    return faces


def _inside(faces: list[list[np.ndarray]], points: np.ndarray) -> np.ndarray:
    from matplotlib.path import Path as MplPath
    hit = np.zeros(len(points), bool)
    for outer, *holes in faces:
        inside = MplPath(outer).contains_points(points)
        for hole in holes:
            inside &= ~MplPath(hole).contains_points(points)
        hit |= inside
    return hit


def section_extent(faces: list[list[np.ndarray]]) -> dict[str, list[float]]:
    """Extent [mm] of the section polygons along X (the diameter) and Z (the length)."""
    pts = np.vstack([ring for face in faces for ring in face])
    return {"x": [float(pts[:, 1].min()), float(pts[:, 1].max())],
            "z": [float(pts[:, 0].min()), float(pts[:, 0].max())]}
