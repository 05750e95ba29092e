"""The Part record every part family builds, and STEP/STL export."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import cadquery as cq


@dataclass
class BoltCircle:
    """A ring of holes: clearance holes (``kind='clearance'``) or tapped holes."""

    name: str
    diameter_mm: float
    count: int
    hole_diameter_mm: float  # clearance-hole or tap-drill diameter
    thread: str              # e.g. "M5"
    kind: str                # "clearance" | "tapped"
    depth_mm: float | None = None  # tapped depth (thread engagement available)
    annulus_inner_mm: float | None = None  # material ring the holes sit in (diameters)
    annulus_outer_mm: float | None = None
    grip_mm: float | None = None  # clamped length under the head (clearance holes): screw length
    start_angle_deg: float = 0.0  # angle of the first hole from +X; the others evenly spaced
    in_bom: bool = True  # False: the screws are listed with the mating clearance circle


@dataclass
class Part:
    """One generated part, modelled with its axis on Z and its mating face at z = 0."""

    name: str
    shape: cq.Workplane
    color: tuple[float, float, float]
    offset_z_mm: float = 0.0   # placement along the axis in the assembly
    flip: bool = False         # rotate 180° about X before placing (part faces the other way)
    dimensions: dict[str, float] = field(default_factory=dict)
    bolt_circles: list[BoltCircle] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    purchased: list[dict] = field(default_factory=list)  # bought parts it holds: bearings, seals…

    def solid(self) -> cq.Shape:
        return self.shape.val()

    def placed(self) -> cq.Shape:
        shape = self.solid()
        if self.flip:
            shape = shape.rotate((0, 0, 0), (1, 0, 0), 180)
        return shape.translate((0, 0, self.offset_z_mm))


def export_step(part: Part, path: Path) -> None:
    cq.exporters.export(part.shape, str(path), exportType="STEP")


def export_stl(part: Part, path: Path, tolerance_mm: float = 0.05) -> None:
    cq.exporters.export(part.shape, str(path), exportType="STL", tolerance=tolerance_mm,
                        angularTolerance=0.2)


def export_svg(part: Part, path: Path) -> None:
    """An isometric hidden-line view of the part (for the calculation sheet)."""
    cq.exporters.export(part.shape, str(path), exportType="SVG",
                        opt={"width": 480, "height": 360, "marginLeft": 20, "marginTop": 20,
                             "showAxes": False, "projectionDir": (1.0, -1.2, 0.8),
                             "strokeWidth": 0.4, "showHidden": False})


def export_assembly(parts: list[Part], path: Path) -> cq.Assembly:
    assembly = cq.Assembly(name="assembly")
    for part in parts:
        assembly.add(cq.Workplane().add(part.placed()), name=part.name,
                     color=cq.Color(*part.color))
    assembly.export(str(path), exportType="STEP")
    return assembly
