"""Dimensions taken from the Part, each verified against the measured solid (a drawing
cannot state a size the STEP file lacks)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import cadquery as cq
import numpy as np

from ..part import BoltCircle, Part
from .conventions import AXIAL_KEYS, BORE_KEYS, DIAMETER_KEYS, OUTER_KEYS, TOLERANCE_MM
from .measure import (_inside, axial_features, Cylinder, section_extent, xz_section, z_cylinders,
                      z_planes)


@dataclass
class Dimension:
    """One dimension to draw; z0, z1 locate it in the side view (model mm)."""

    key: str
    label: str
    value_mm: float
    measured_mm: float
    kind: str          # "diameter" | "length"
    z0: float
    z1: float
    external: bool = True   # diameter: material inside the surface (full dimension line)
    side: str = "top"       # where the dimension line stands: left | right | top

    def as_dict(self) -> dict:
        return {"key": self.key, "label": self.label, "value_mm": self.value_mm,
                "measured_mm": self.measured_mm, "kind": self.kind, "side": self.side}


@dataclass
class Measured:
    """What the drawing checks the Part record against, measured on the STEP solid."""

    box: cq.BoundBox
    features: list[Cylinder]
    holes: list[Cylinder]
    planes: list[float]
    section: list[list[np.ndarray]]   # full XZ section, (z, x) rings
    upper: list[list[np.ndarray]]     # its x ≥ 0 half (the half that is drawn cut)

    @classmethod
    def of(cls, solid: cq.Solid) -> "Measured":
        box = solid.BoundingBox()  # cadquery: BRepBndLib.AddOptimal, exact for these solids
        reach = max(abs(box.xmin), abs(box.xmax)) + 1.0
        cylinders = z_cylinders(solid)
        return cls(box, axial_features(cylinders), [c for c in cylinders if not c.on_axis],
                   z_planes(solid), xz_section(solid, -reach, reach),
                   xz_section(solid, 0.0, reach))


def _mismatch(part: Part, key: str, value: float, what: str, measured: float) -> ValueError:
    return ValueError(f"{part.name}: dimensions[{key!r}] = {value:g} mm but the STEP geometry "
                      f"{what} {measured:.4g} mm; the drawing would not match the part")


def _agree(a: float, b: float) -> bool:
    return abs(a - b) <= TOLERANCE_MM


def outer_dimension(part: Part, m: Measured) -> Dimension:
    """Outer diameter or square size: the bounding box in X and Y and the section in X."""
    keys = [k for k in OUTER_KEYS if k in part.dimensions]
    if not keys:
        raise ValueError(f"{part.name}: dimensions has neither outer_diameter_mm nor square_mm")
    key, value = keys[0], part.dimensions[keys[0]]
    ext = section_extent(m.section)["x"]
    for what, measured in (("bounding box in X is", m.box.xlen), ("bounding box in Y is",
                           m.box.ylen), ("section through the axis is", ext[1] - ext[0])):
        if not _agree(measured, value):
            raise _mismatch(part, key, value, what, measured)
    if key == "outer_diameter_mm" and not any(_agree(f.diameter, value) for f in m.features):
        raise _mismatch(part, key, value, "has no round outer surface; its width is", m.box.xlen)
    z = [p[0] for face in m.upper for ring in face for p in ring if _agree(p[1], value / 2)]
    z = z or [m.box.zmin, m.box.zmax]
    label = f"Ø{value:g}" if key == "outer_diameter_mm" else f"□{value:g}"
    return Dimension(key, label, value, m.box.xlen, "diameter", min(z), max(z))


def diameter_dimensions(part: Part, m: Measured) -> list[Dimension]:
    """Inner and stepped diameters: each must be an on-axis cylinder of the solid. Keys with
    equal values take the features of that diameter in z order."""
    keys = [k for k in DIAMETER_KEYS if k in part.dimensions and k not in OUTER_KEYS]
    used: set[int] = set()
    out = []
    for key in keys:
        value = part.dimensions[key]
        match = [i for i, f in enumerate(m.features) if _agree(f.diameter, value) and i not in used]
        if not match:
            near = min(m.features, key=lambda f: abs(f.diameter - value)).diameter
            raise _mismatch(part, key, value, "has no turned surface of that diameter; the "
                            "nearest is", near)
        used.add(match[0])
        f = m.features[match[0]]
        out.append(Dimension(key, f"Ø{value:g}{_fit_code(part, value)}", value, f.diameter,
                             "diameter", f.z0, f.z1, _is_external(m, f)))
    _check_bore(part, m, out)
    return out


def _fit_code(part: Part, value: float) -> str:
    """' H7' when the part states an ISO 286 fit on this diameter (ISO 129-1: the tolerance
    class follows the size)."""
    codes = [f.code for f in part.fits if _agree(f.nominal_mm, value)]
    return f" {codes[0]}" if codes else ""


def _is_external(m: Measured, f: Cylinder) -> bool:
    probe = np.array([[(f.z0 + f.z1) / 2, f.diameter / 2 - 10 * TOLERANCE_MM]])
    return bool(_inside(m.upper, probe)[0])


def _check_bore(part: Part, m: Measured, dims: list[Dimension]) -> None:
    """The bore is the innermost surface the section meets."""
    inner = section_extent(m.upper)["x"][0] * 2
    for d in dims:
        if d.key in BORE_KEYS and not _agree(d.value_mm, inner):
            raise _mismatch(part, d.key, d.value_mm, "section's innermost diameter is", inner)


def length_dimensions(part: Part, m: Measured) -> list[Dimension]:
    """Overall length (bounding box in Z); a plate thickness shorter than it must be the
    distance from the mating face z = 0 to a face normal to Z."""
    dims, length = part.dimensions, m.box.zlen
    overall = "overall_length_mm" if "overall_length_mm" in dims else "thickness_mm"
    if overall not in dims:
        raise ValueError(f"{part.name}: dimensions has neither overall_length_mm nor "
                         "thickness_mm")
    if not _agree(dims[overall], length):
        raise _mismatch(part, overall, dims[overall], "length along the axis is", length)
    out = [Dimension(overall, f"{dims[overall]:g}", dims[overall], length, "length",
                     m.box.zmin, m.box.zmax)]
    t = dims.get("thickness_mm")
    if overall != "thickness_mm" and t is not None:
        if not any(_agree(z, 0.0) for z in m.planes):
            raise _mismatch(part, "thickness_mm", t, "has no mating face at z = 0; zmin is",
                            m.box.zmin)
        near = min(m.planes, key=lambda z: abs(z - t))
        if not _agree(near, t):
            raise _mismatch(part, "thickness_mm", t, "has its nearest face at z =", near)
        out.insert(0, Dimension("thickness_mm", f"{t:g}", t, near, "length", 0.0, near))
    return out


def axial_dimensions(part: Part, m: Measured) -> list[Dimension]:
    """Positions of the part's functional faces along the axis, dimensioned in parallel
    from the mating face z = 0 (ISO 129-1 parallel dimensioning from a datum): each must be a
    face of the solid normal to Z."""
    out = []
    for key in AXIAL_KEYS:
        z = part.dimensions.get(key)
        if z is None or _agree(z, m.box.zmax) or _agree(z, 0.0):
            continue
        near = min(m.planes, key=lambda p: abs(p - z))
        if not _agree(near, z):
            raise _mismatch(part, key, z, "has its nearest face normal to the axis at z =",
                            near)
        out.append(Dimension(key, f"{z:g}", z, near, "length", 0.0, near))
    return out


def bolt_circle_label(bc: BoltCircle) -> str:
    """ISO 129-1 style callout: tapped holes as thread × depth (``6× M5×8``), clearance
    holes with the screw they pass (``6× Ø4.5 for M4``), then the circle."""
    if bc.kind == "tapped" and bc.depth_mm:
        return (f"{bc.count}× {bc.thread}×{bc.depth_mm:g} (drill Ø{bc.hole_diameter_mm:g}) "
                f"on Ø{bc.diameter_mm:g}")
    return f"{bc.count}× Ø{bc.hole_diameter_mm:g} for {bc.thread} on Ø{bc.diameter_mm:g}"


def bolt_circle_holes(part: Part, bc: BoltCircle, m: Measured) -> list[tuple[float, float]]:
    """Centres (x, y) [mm] of the bolt circle's holes in the solid; ValueError unless there
    are exactly ``count`` holes of the stated diameter on the stated circle."""
    centres: list[tuple[float, float]] = []
    for h in m.holes:  # one hole may have several faces (split by seams or other cuts)
        if (_agree(h.diameter, bc.hole_diameter_mm)
                and _agree(2 * math.hypot(h.x, h.y), bc.diameter_mm)
                and not any(math.dist((h.x, h.y), c) < TOLERANCE_MM for c in centres)):
            centres.append((h.x, h.y))
    if len(centres) != bc.count:
        raise ValueError(f"{part.name}: bolt circle {bc.name!r} states {bc.count} × "
                         f"Ø{bc.hole_diameter_mm:g} on Ø{bc.diameter_mm:g} but the STEP geometry "
                         f"has {len(centres)} such holes; the drawing would not match the part")
    return centres
