"""Clearance between the gear envelope and the case inner wall (check ``inner_wall_clearance``).

Seed 000 p.024, guideline 4: the flexspline (FS) deforms elastically, so the case inner wall
must keep the recommended dimensions; guideline 7: the hook of the C-ring that holds the
wave-generator (WG) hub must not touch the case. This module builds the envelope of what
moves inside the case, meshes it and the placed case parts with trimesh and measures the
smallest distance between the meshes.

Gear envelope (CSF/CSG-2A-GR, coordinates of :mod:`hdcad.geometry.component_housing`)::

    FS:      cylinder of radius d_FS/2 + w0 from the CS face (z = 0) to the diaphragm face
             (z = FS length). The WG holds the FS elliptical with its major semi-axis
             d_FS/2 + w0; the ellipse turns with the WG, so it sweeps this cylinder. The
             deflection tapers to zero at the diaphragm; using w0 over the whole length is
             conservative.
    w0:      the overlay's fs_radial_deflection_mm, else w0 = κ·m with κ = 1 (standard
             deflection) and m = d/Z_F, Z_F = 2R (two teeth fewer than the CS, ratio R = Z_F/2),
             d ≈ FS outside diameter: w0 = d/(2R) (assumption, stated in the note).
    C-ring:  disc of the hook radius from the CS input face to the hook's protrusion (it
             turns with the WG).

Recommended clearances: FS: min((D_wall − d_FS)/2 − w0, diaphragm-side depth), the gap the
recommended wall diameter leaves around the deformed FS and the recommended axial room
beyond the diaphragm; C-ring: the overlay's minimum clearance.

Distance: exact point-to-triangle distances (vertices and surface samples of each mesh to
the triangles of the other, both ways); triangles are culled by bounding boxes against the
nearest-vertex bound, so no spatial-index package is needed. The tessellation's linear
deflection is kept at least ``MESH_RATIO`` times below the measured clearance (remeshed
finer once if not); facets of a concave wall lie up to one deflection inside it, so the
measured value errs low by at most about twice the deflection.

References
----------
Seed 000 p.024 (design guidelines 4 and 7), p.027 (ratio and WG).
Harmonic Drive strain wave gearing: Z_F = Z_C − 2, R = Z_F/2 for the cup type with fixed CS.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import cadquery as cq
import numpy as np
from OCP.BRepMesh import BRepMesh_IncrementalMesh

from ..catalog import Catalog
from ..checks.record import CheckResult, Quantity, compared, not_evaluated
from ..design_options import DesignOptions
from ..models import GearModel
from .component_housing import CASE_PARTS, HOUSING, OUTLINE
from .part import Part

if TYPE_CHECKING:  # trimesh (0.7 s to import) is loaded by the functions that mesh
    import trimesh

ID, FAMILY = "inner_wall_clearance", "geometry"
TITLE = "Inner wall clearance (gear envelope to case)"
FORMULA = ("min distance(envelope, case) ≥ c_rec; FS: c_rec = min((D_wall − d_FS)/2 − w0, "
           "diaphragm-side depth), w0 = d_FS/(2R) unless given; C-ring: c_rec = c_min")
MESH_TOLERANCE_MM = 0.02     # linear deflection of the tessellation (≤ clearance/10)
ANGULAR_TOLERANCE_RAD = 0.5   # loose: the linear deflection governs
MESH_RATIO = 10.0            # deflection ≤ measured clearance / 10
SAMPLES_PER_MESH = 4000      # surface samples added to the vertices
CHUNK = 256                  # points per vectorised batch


# -- envelope ------------------------------------------------------------------------------------
def fs_deflection_mm(fs_outer_mm: float, ratio: int) -> float:
    """Standard radial deflection w0 = κ·m = d/(2R) [mm] (κ = 1, Z_F = 2R, d ≈ FS φ)."""
    return fs_outer_mm / (2.0 * ratio)


def gear_envelopes(outline: dict, w0_mm: float) -> dict[str, cq.Shape]:
    """Solids swept by the deformed FS and by the C-ring hook, in assembly coordinates."""
    r_fs = outline["fs_outer_diameter_mm"] / 2 + w0_mm
    cs_w, hook = outline["cs_width_mm"], outline["cring_protrusion_mm"]
    return {"fs": cq.Solid.makeCylinder(r_fs, outline["fs_length_mm"]),
            "cring": cq.Solid.makeCylinder(outline["cring_hook_radius_mm"], hook,
                                           cq.Vector(0, 0, -cs_w - hook))}


# -- meshes and distances -----------------------------------------------------------------------
def mesh_of(shapes: list[cq.Shape], tolerance_mm: float) -> trimesh.Trimesh:
    """One triangle mesh of ``shapes`` (OCCT tessellation, linear deflection tolerance_mm)."""
    import trimesh

    parts = []
    for shape in shapes:
        # absolute deflection (cadquery's own tessellate meshes with a relative one)
        BRepMesh_IncrementalMesh(shape.wrapped, tolerance_mm, False, ANGULAR_TOLERANCE_RAD)
        vertices, faces = shape.tessellate(tolerance_mm, ANGULAR_TOLERANCE_RAD)
        parts.append(trimesh.Trimesh([v.toTuple() for v in vertices], faces, process=False))
    return trimesh.util.concatenate(parts)


def _query_points(mesh: trimesh.Trimesh, seed: int) -> np.ndarray:
    import trimesh

    samples, _ = trimesh.sample.sample_surface(mesh, SAMPLES_PER_MESH, seed=seed)
    return np.vstack([mesh.vertices, samples])


def points_to_mesh_mm(points: np.ndarray, mesh: trimesh.Trimesh) -> float:
    """Smallest exact distance [mm] from ``points`` to the triangles of ``mesh``."""
    import trimesh
    from scipy.spatial import cKDTree

    triangles = mesh.triangles
    low, high = triangles.min(axis=1), triangles.max(axis=1)
    bound, _ = cKDTree(mesh.vertices).query(points)  # nearest vertex: an upper bound
    best = float(bound.min())
    order = np.lexsort((np.arctan2(points[:, 1], points[:, 0]), points[:, 2]))
    for start in range(0, len(order), CHUNK):
        chunk = points[order[start:start + CHUNK]]
        # triangles whose box lies within the best distance so far of the chunk's box
        box_gap = (np.maximum(low - chunk.max(axis=0), 0) + np.maximum(chunk.min(axis=0) - high, 0))
        near = np.nonzero(np.linalg.norm(box_gap, axis=1) <= best)[0]
        if near.size == 0:
            continue
        gap = (np.maximum(low[near][None] - chunk[:, None], 0)
               + np.maximum(chunk[:, None] - high[near][None], 0))
        pi, ti = np.nonzero(np.linalg.norm(gap, axis=2) <= best)
        if pi.size == 0:
            continue
        closest = trimesh.triangles.closest_point(triangles[near[ti]], chunk[pi])
        best = min(best, float(np.linalg.norm(closest - chunk[pi], axis=1).min()))
    return best


def mesh_distance_mm(a: trimesh.Trimesh, b: trimesh.Trimesh) -> float:
    """Smallest distance [mm] between two triangle meshes (points of each to the other)."""
    return min(points_to_mesh_mm(_query_points(a, 1), b),
               points_to_mesh_mm(_query_points(b, 2), a))


def clearance_mm(envelope: cq.Shape, walls: list[cq.Shape],
                 tolerance_mm: float = MESH_TOLERANCE_MM,
                 walls_mesh: trimesh.Trimesh | None = None) -> tuple[float, float]:
    """(smallest distance [mm] between envelope and walls, mesh deflection used [mm]).

    0 when the envelope overlaps a wall (OCCT boolean common). The mesh is refined once so
    that its deflection is at least MESH_RATIO times below the distance found.
    ``walls_mesh``: the walls already meshed with ``tolerance_mm`` (saves meshing twice).
    """
    if any(envelope.intersect(w).Volume() > 1e-6 for w in walls):
        return 0.0, tolerance_mm
    walls_mesh = walls_mesh if walls_mesh is not None else mesh_of(walls, tolerance_mm)
    distance = mesh_distance_mm(mesh_of([envelope], tolerance_mm), walls_mesh)
    if 0 < distance < MESH_RATIO * tolerance_mm:
        tolerance_mm = distance / (2 * MESH_RATIO)
        distance = mesh_distance_mm(mesh_of([envelope], tolerance_mm),
                                    mesh_of(walls, tolerance_mm))
    return distance, tolerance_mm


# -- the check ---------------------------------------------------------------------------------
NOT_APPLICABLE = {
    "FD-2": "the FD tables (311-1, 312-1) give no flexspline outline and no recommended inner "
            "wall; the casing halves bolt face-to-face to the circular splines",
    "FD-0": "the FD tables (311-1, 312-1) give no flexspline outline and no recommended inner "
            "wall; the unit is closed and the drive flanges bolt to its casing halves",
    "GH": "the gear head is a closed unit; the motor adapter flange has no wall near the "
          "flexspline",
}


def inner_wall_clearance(model: GearModel, parts: list[Part], catalog: Catalog,
                         options: DesignOptions | None = None) -> CheckResult:
    """Smallest distance between the gear envelope and the case parts against the
    recommended clearance (2A-GR); not evaluated for the other families."""
    if model.family in NOT_APPLICABLE:
        return not_evaluated(ID, TITLE, FAMILY, FORMULA, NOT_APPLICABLE[model.family])
    outline = catalog.find(OUTLINE, series=model.series, size=model.size)
    rec = catalog.find(HOUSING, series=model.series, size=model.size)
    missing = [t for t, row in ((OUTLINE, outline), (HOUSING, rec)) if row is None]
    if missing:
        return not_evaluated(ID, TITLE, FAMILY, FORMULA,
                             f"{model.series} size {model.size} rows in the overlay tables "
                             f"{', '.join(missing)}")
    walls = [p.placed() for p in parts if p.name in CASE_PARTS]
    if not walls:
        return not_evaluated(ID, TITLE, FAMILY, FORMULA, "case parts "
                             f"({', '.join(CASE_PARTS)}) among the generated parts")
    w0, w0_rule = _deflection(outline, rec, model.ratio)
    required = _required(outline, rec, w0)
    envelopes = gear_envelopes(outline, w0)
    items, walls_mesh = {}, mesh_of(walls, MESH_TOLERANCE_MM)
    for name, envelope in envelopes.items():
        measured, tolerance = clearance_mm(envelope, walls, walls_mesh=walls_mesh)
        items[name] = {"measured_mm": measured, "required_mm": required[name][0],
                       "rule": required[name][1], "mesh_tolerance_mm": tolerance}
    return _record(model, catalog, outline, rec, w0, w0_rule, items)


def _deflection(outline: dict, rec: dict, ratio: int) -> tuple[float, str]:
    if rec.get("fs_radial_deflection_mm") is not None:
        return rec["fs_radial_deflection_mm"], "fs_radial_deflection_mm from the overlay"
    w0 = fs_deflection_mm(outline["fs_outer_diameter_mm"], ratio)
    return w0, (f"assumption: w0 = κ·m = d/(2R) = {outline['fs_outer_diameter_mm']:g}/(2·"
                f"{ratio}) = {w0:.3f} mm (κ = 1, Z_F = 2R, d ≈ FS outside diameter; the overlay "
                "gives no fs_radial_deflection_mm)")


def _required(outline: dict, rec: dict, w0: float) -> dict[str, tuple[float, str]]:
    radial = (rec["fs_wall_diameter_mm"] - outline["fs_outer_diameter_mm"]) / 2 - w0
    axial = rec["diaphragm_side_depth_mm"]
    return {"fs": (min(radial, axial),
                   f"min((D_wall − d_FS)/2 − w0 = ({rec['fs_wall_diameter_mm']:g} − "
                   f"{outline['fs_outer_diameter_mm']:g})/2 − {w0:.3f} = {radial:.3f}, "
                   f"diaphragm-side depth {axial:g}) mm"),
            "cring": (rec["cring_clearance_min_mm"], "cring_clearance_min_mm")}


def _record(model, catalog, outline, rec, w0, w0_rule, items) -> CheckResult:
    def ratio(item):
        req = item["required_mm"]
        return item["measured_mm"] / req if req > 0 else math.inf
    name, worst = min(items.items(), key=lambda kv: ratio(kv[1]))
    source = (f"overlay tables {OUTLINE} and {HOUSING} ({catalog.table(HOUSING).source}); "
              "seed 000 p.024 guidelines 4 and 7")
    inputs = {"d_FS": Quantity(outline["fs_outer_diameter_mm"], "mm", OUTLINE),
              "R": Quantity(model.ratio, ""), "w0": Quantity(w0, "mm", w0_rule),
              "D_wall (recommended)": Quantity(rec["fs_wall_diameter_mm"], "mm", HOUSING),
              "diaphragm-side depth": Quantity(rec["diaphragm_side_depth_mm"], "mm", HOUSING),
              "C-ring hook radius": Quantity(outline["cring_hook_radius_mm"], "mm", OUTLINE),
              "c_min C-ring": Quantity(rec["cring_clearance_min_mm"], "mm", HOUSING)}
    worst_tol = max(i["mesh_tolerance_mm"] for i in items.values())
    note = (f"governing: {name} ({worst['measured_mm']:.3f} mm measured vs "
            f"{worst['required_mm']:.3f} mm recommended); " +
            "; ".join(f"{k}: {v['measured_mm']:.3f} ≥ {v['required_mm']:.3f} mm ({v['rule']})"
                      for k, v in items.items()) +
            f"; w0: {w0_rule}; trimesh on OCCT meshes, deflection ≤ {worst_tol:.3g} mm "
            "(measured values err low by at most about twice that)")
    details = {"items": items, "w0_mm": w0, "w0_rule": w0_rule,
               "mesh_tolerance_mm": worst_tol, "angular_tolerance_rad": ANGULAR_TOLERANCE_RAD,
               "mesh_ratio_min": MESH_RATIO, "case_parts": list(CASE_PARTS)}
    return compared(ID, TITLE, FAMILY, FORMULA, inputs, worst["measured_mm"],
                    worst["required_mm"], "mm", ">=", source, note, details)
