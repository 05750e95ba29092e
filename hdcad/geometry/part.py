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
    annulus_outer_mm: float | None = None  # round outline; None with a square outline
    outline_square_mm: float | None = None  # square outline (side), centred on the circle
    grip_mm: float | None = None  # clamped length under the head (clearance holes): screw length
    start_angle_deg: float = 0.0  # angle of the first hole from +X; the others evenly spaced
    in_bom: bool = True  # False: the screws are listed with the mating clearance circle


@dataclass
class Fit:
    """An ISO 286 fit on one mating diameter of a part.

    ``deviations_um`` are the (upper, lower) deviations of this feature from ISO 286-2 for
    ``nominal_mm`` and ``code`` (e.g. ``"M7"`` for a hole, ``"k5"`` for a shaft).
    """

    feature: str                 # e.g. "bearing seat 6006 (outer ring)"
    nominal_mm: float
    code: str                    # ISO 286 tolerance class: capital = hole, small = shaft
    kind: str                    # "hole" | "shaft"
    deviations_um: tuple[float, float]
    mate: str = ""               # what it mates with, e.g. "6006 outer ring (ISO 492 Normal)"
    reason: str = ""             # why this fit (load case, rule)
    source: str = ""             # standard / table


@dataclass
class GeometricTolerance:
    """An ISO 1101 geometric tolerance or datum on a feature."""

    feature: str                 # e.g. "bearing seats"
    characteristic: str          # flatness | coaxiality | perpendicularity | runout | position | datum
    value_mm: float | None       # None for a datum feature
    datums: str = ""             # e.g. "A-B"; for a datum feature its letter
    source: str = ""


@dataclass
class Neighbour:
    """A bought or adjoining body the part mates with, as a simple true-size body for the
    review assembly (bearing, seal, O-ring, screw, plug, gear outline, motor envelope).

    ``dims`` holds the body's defining dimensions [mm] (e.g. d, D, B for a bearing); the body
    sits on the part's own axis frame (Z axis, part coordinates before placement) at
    ``z_mm`` with its reference face there, facing +z unless ``flip``; ``xy_mm`` moves
    off-axis bodies (screws, plugs), ``direction`` gives an off-axis body's axis.
    """

    kind: str                    # bearing | seal | oring | screw | plug | gear | motor | ring | other
    designation: str             # e.g. "6006", "ISO 4762 M5×16-12.9", "DIN 471 30×1.5"
    dims: dict[str, float]
    z_mm: float = 0.0
    flip: bool = False
    xy_mm: tuple[float, float] = (0.0, 0.0)
    direction: tuple[float, float, float] = (0.0, 0.0, 1.0)
    note: str = ""
    body: object = None          # the true-size solid in part coordinates, when built
    turns_with: str = ""         # rotation group if not its part's (e.g. "shaft")


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
    fits: list[Fit] = field(default_factory=list)                   # ISO 286 fits on mating Ø
    tolerances: list[GeometricTolerance] = field(default_factory=list)  # ISO 1101 datums/GD&T
    neighbours: list[Neighbour] = field(default_factory=list)       # bodies for the review assembly
    material: str = ""          # EN designation for the drawing title block, e.g. "S355J2 (EN 10025-2)"
    turns_with: str = ""        # rotation group in the machine (parts of one group do not move
    #                             against each other); "" = its own
    pockets_mm3: float = 0.0    # material the lightening pockets removed (mass before/after)

    def solid(self) -> cq.Shape:
        return self.shape.val()

    def placed(self) -> cq.Shape:
        shape = self.solid()
        if self.flip:
            shape = shape.rotate((0, 0, 0), (1, 0, 0), 180)
        return shape.translate((0, 0, self.offset_z_mm))


def export_step(part: Part, path: Path) -> None:
    """One solid whose STEP product carries the part's name and colour (a plain shape export
    would name it after the translator, "Open CASCADE STEP translator …")."""
    single = cq.Assembly(part.shape, name=part.name, color=cq.Color(*part.color))
    single.export(str(path), exportType="STEP", mode="fused")


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
