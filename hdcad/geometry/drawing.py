"""Part drawings from the STEP geometry: a view along the axis and a half section.

``part_drawing(step_path, part, svg_path, png_path)`` re-imports the STEP file and draws what it
contains, never the in-memory shape: on the left the view along the axis (from +Z, hidden
edges thin dashed, bolt circles as chain lines with their labels), on the right a half section
through the axis (upper half cut in the XZ plane and hatched, lower half the outside view), in
first-angle projection (the view from +Y stands to the right of the view from +Z) on one
250 × 150 mm sheet with a title strip.

The dimensions come from ``part.dimensions`` and ``part.bolt_circles`` but each one is measured
on the re-imported solid first; a value that differs from the geometry by more than
``TOLERANCE_MM`` raises ValueError, so the drawing cannot state a size the STEP file lacks.
Diameters of internal features use half dimension lines (one arrow, the line running a little
past the axis), as ISO 129-1 allows for half sections.

Text is written as glyph paths (as in ``hdcad.report.plots``) so WeasyPrint needs no font;
matplotlib puts each string in an SVG comment before its glyphs, which is how tests read them.

References
----------
ISO 128-2 (line types: continuous wide for visible outlines, thin dashed for hidden edges,
thin chain for centre lines and pitch circles), ISO 128-50 (section hatching at 45°),
ISO 128-44/ISO 129-1 (half sections; dimension, extension and half dimension lines, closed
filled arrowheads), ISO 5456-2 (first-angle projection, also JIS B 0001), ISO 5455 (scales).
"""

from __future__ import annotations

import itertools
import math
import time
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

from .part import BoltCircle, Part

# ---------------------------------------------------------------------------------------------
# Design choices for the sheet (drawing conventions, not catalog data).
# ---------------------------------------------------------------------------------------------
TOLERANCE_MM = 0.01        # a drawn dimension may differ from the STEP solid by at most this
DEFLECTION_MM = 0.01       # chord error when curves are drawn as polylines (invisible in print)
SHEET_MM = (250.0, 150.0)  # A4-landscape-like sheet the calculation sheet scales to its width
MARGIN_MM = 5.0            # sheet edge to frame
TITLE_H_MM = 10.0          # title strip along the bottom of the frame
GAP_MM = 4.0               # free space around a view (centre lines overshoot 3 mm into it)
VIEW_GAP_MM = 10.0         # between the front view and the side view's left dimension stack
DIM_SPACING_MM = 7.0       # between stacked parallel dimension lines: text height + clearance
EXT_GAP_MM, EXT_OVER_MM = 1.0, 2.0  # extension line: gap to the outline, overshoot of the line
HALF_DIM_PAST_AXIS_MM = 4.0  # a half dimension line runs this far past the axis (ISO 129-1)
ARROW_MM, ARROW_DEG = 2.5, 15.0     # closed filled arrowhead, 30° included angle
HATCH_MM, HATCH_DEG = 2.0, 45.0     # section hatching spacing on paper and angle
CENTRE_OVER_MM = 3.0       # centre lines run past the outline by this much
LANDING_MM = 3.0           # horizontal landing of a leader beyond its text
PT_PER_MM = 72.0 / 25.4
LINE_MM = {"visible": 0.7, "thin": 0.35, "hatch": 0.18}  # ISO 128-2 line group 0.7
TEXT_PT, TITLE_PT = 8.0, 9.0  # 8 pt ≈ 2.8 mm capitals: above the 2.5 mm ISO 3098 minimum
CHAIN_MM = (8.0, 1.0, 0.5, 1.0)  # long dash, gap, dot, gap (thin chain line, ISO 128-2 type 04)
DASH_MM = (3.0, 1.0)             # thin dashed line (ISO 128-2 type 02)
SCALES = (5.0, 2.0, 1.0, 1 / 2, 1 / 5, 1 / 10, 1 / 20)  # ISO 5455 preferred scales
PNG_DPI = 150
INK, HATCH_FILL = "#000000", "#E6E6E6"

DIAMETER_KEYS = ("outer_diameter_mm", "square_mm", "pilot_recess_mm", "pilot_boss_diameter_mm",
                 "pilot_diameter_mm", "spigot_recess_mm", "spigot_diameter_mm",
                 "hub_diameter_mm", "journal_diameter_mm", "bearing_seat_mm", "seal_recess_mm",
                 "bore_mm", "shaft_hole_mm")
"""Part.dimensions keys drawn as diameters in the side view (those a part has)."""
OUTER_KEYS = ("outer_diameter_mm", "square_mm")
BORE_KEYS = ("bore_mm", "shaft_hole_mm")


# ---------------------------------------------------------------------------------------------
# Geometry: discretisation, measurement, projection and section of the re-imported solid.
# ---------------------------------------------------------------------------------------------
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


def z_cylinders(shape: cq.Shape) -> list[Cylinder]:
    """Every cylindrical face of ``shape`` whose axis is parallel to Z."""
    out = []
    for face in shape.Faces():
        if face.geomType() != "CYLINDER":
            continue
        cyl = BRepAdaptor_Surface(face.wrapped).Cylinder()
        loc, axis = cyl.Axis().Location(), cyl.Axis().Direction()
        if abs(abs(axis.Z()) - 1) < 1e-9:
            box = face.BoundingBox()
            out.append(Cylinder(2 * cyl.Radius(), loc.X(), loc.Y(), box.zmin, box.zmax))
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


# ---------------------------------------------------------------------------------------------
# Dimensions from the Part, each verified against the measured solid.
# ---------------------------------------------------------------------------------------------
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
        out.append(Dimension(key, f"Ø{value:g}", value, f.diameter, "diameter", f.z0, f.z1,
                             _is_external(m, f)))
    _check_bore(part, m, out)
    return out


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


def bolt_circle_label(bc: BoltCircle) -> str:
    return f"{bc.count} × Ø{bc.hole_diameter_mm:g} on Ø{bc.diameter_mm:g} ({bc.thread})"


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


# ---------------------------------------------------------------------------------------------
# Paper: a matplotlib axes in sheet millimetres with drawing primitives.
# ---------------------------------------------------------------------------------------------
def _line_kw(kind: str, pattern: tuple[float, ...] | None = None) -> dict:
    width = LINE_MM[kind] * PT_PER_MM
    kw = {"color": INK, "linewidth": width, "capstyle": "butt"}
    if pattern:  # matplotlib scales dash lengths by the line width
        kw["linestyle"] = (0, tuple(p * PT_PER_MM / width for p in pattern))
    return kw


class Sheet:
    """One drawing sheet: Figure + axes whose data units are millimetres on paper."""

    def __init__(self):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        w, h = SHEET_MM
        self.fig = Figure(figsize=(w / 25.4, h / 25.4))
        self.canvas = FigureCanvasAgg(self.fig)
        self.ax = self.fig.add_axes((0, 0, 1, 1))
        self.ax.set_xlim(0, w)
        self.ax.set_ylim(0, h)
        self.ax.set_axis_off()
        self.texts: list = []

    def text_size(self, s: str, size: float = TEXT_PT, weight: str = "normal"
                  ) -> tuple[float, float]:
        """Width and height [mm] of ``s`` set horizontally."""
        from matplotlib.font_manager import FontProperties
        renderer = self.canvas.get_renderer()
        font = FontProperties(size=size, weight=weight)
        w, h, _ = renderer.get_text_width_height_descent(s, font, False)
        return w / self.fig.dpi * 25.4, h / self.fig.dpi * 25.4

    def lines(self, polylines, kind="visible", pattern=None) -> None:
        from matplotlib.collections import LineCollection
        if polylines:
            self.ax.add_collection(LineCollection(polylines, **_line_kw(kind, pattern)))

    def arrow(self, tip, towards) -> None:
        """Closed filled arrowhead with its tip at ``tip``, pointing away from ``towards``."""
        from matplotlib.patches import Polygon
        tip, back = np.asarray(tip, float), np.asarray(towards, float)
        d = (tip - back) / np.linalg.norm(tip - back)
        n = np.array([-d[1], d[0]]) * ARROW_MM * math.tan(math.radians(ARROW_DEG))
        base = tip - d * ARROW_MM
        self.ax.add_patch(Polygon([tip, base + n, base - n], closed=True, facecolor=INK,
                                  edgecolor="none"))

    def text(self, x, y, s, size=TEXT_PT, rotation=0.0, ha="center", va="center", **kw):
        t = self.ax.text(x, y, s, fontsize=size, rotation=rotation, ha=ha, va=va,
                         rotation_mode="anchor", color=INK, **kw)
        self.texts.append(t)
        return t

    def hatch(self, rings_paper: list[np.ndarray]) -> None:
        """Fill one section face light grey and hatch it at HATCH_DEG."""
        from matplotlib.patches import PathPatch
        from matplotlib.path import Path as MplPath
        path = MplPath.make_compound_path(*[MplPath(r, closed=True) for r in
                                            [np.vstack([r, r[:1]]) for r in rings_paper]])
        self.ax.add_patch(PathPatch(path, facecolor=HATCH_FILL, edgecolor="none"))
        self.lines(hatch_segments(rings_paper, HATCH_MM, HATCH_DEG), "hatch")

    def text_boxes(self) -> list[list[float]]:
        """Final text boxes [x0, y0, x1, y1] in sheet mm."""
        renderer, k = self.canvas.get_renderer(), 25.4 / self.fig.dpi
        return [[b.x0 * k, b.y0 * k, b.x1 * k, b.y1 * k]
                for b in (t.get_window_extent(renderer) for t in self.texts)]

    def save(self, svg_path: Path, png_path: Path | None) -> None:
        self.fig.savefig(svg_path, format="svg", metadata={"Date": None})
        if png_path is not None:
            self.fig.savefig(png_path, format="png", dpi=PNG_DPI, facecolor="white")


def hatch_segments(rings: list[np.ndarray], spacing: float, angle_deg: float
                   ) -> list[np.ndarray]:
    """Hatch lines inside the polygon ``rings`` (even-odd rule) on a fixed grid, so faces of
    one part hatch in step."""
    a = math.radians(angle_deg)
    rot = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])  # to hatch frame
    edges = [(r @ rot.T, np.roll(r @ rot.T, -1, axis=0)) for r in rings]
    ys = np.concatenate([p[:, 1] for p, _ in edges])
    out = []
    for c in np.arange(math.ceil(ys.min() / spacing), math.floor(ys.max() / spacing) + 1):
        y = c * spacing
        xs = []
        for p, q in edges:
            cross = (p[:, 1] <= y) != (q[:, 1] <= y)
            t = (y - p[cross, 1]) / (q[cross, 1] - p[cross, 1])
            xs += list(p[cross, 0] + t * (q[cross, 0] - p[cross, 0]))
        xs.sort()
        out += [np.array([[x0, y], [x1, y]]) @ rot for x0, x1 in zip(xs[::2], xs[1::2])]
    return out


def clip_half(polyline: np.ndarray, upper: bool) -> list[np.ndarray]:
    """Parts of a 2-D polyline with y ≥ 0 (upper) or y ≤ 0, cut exactly at y = 0."""
    side = polyline[:, 1] * (1.0 if upper else -1.0)
    pieces, current = [], []
    for i, (p, h) in enumerate(zip(polyline, side)):
        if i and (h < 0) != (side[i - 1] < 0):  # the segment crosses or touches the axis
            prev = polyline[i - 1]
            current.append(prev + (p - prev) * (side[i - 1] / (side[i - 1] - h)))
            if h < 0:
                pieces.append(current)
                current = []
        if h >= 0:
            current.append(p)
    pieces.append(current)
    return [np.array(piece) for piece in pieces if len(piece) > 1]


# ---------------------------------------------------------------------------------------------
# Layout: the scale and where each view, dimension stack and label goes.
# ---------------------------------------------------------------------------------------------
@dataclass
class Layout:
    scale: float
    front: tuple[float, float]   # paper position of the axis in the front view
    side_x0: float               # paper x of z = zmin in the side view
    cy: float                    # paper y of the axis in both views (first-angle alignment)
    row_mm: float                # pitch of the bolt-circle label rows
    label_x0: float              # paper x where the bolt-circle labels start


def label_rows(n: int) -> list[tuple[int, int]]:
    """(side, row) of each bolt-circle label: alternately above (+1) and below (−1) the
    front view, stacked away from it."""
    return [(1 if i % 2 == 0 else -1, i // 2) for i in range(n)]


def _extents(sheet: Sheet, m: Measured, dims: list[Dimension], labels: list[str], s: float
             ) -> tuple[float, float, float, float]:
    """Width of the front block and of the side block, height above and below the axis
    [mm] at scale ``s``."""
    half_u, half_v = m.box.ylen / 2 * s, m.box.xlen / 2 * s
    row = sheet.text_size("Ø0")[1] + 2.0
    label_w = max((sheet.text_size(t)[0] for t in labels), default=0.0)
    front_w = max(2 * half_u, label_w + LANDING_MM + row * len(labels))
    stacks = DIM_SPACING_MM * (_count(dims, "left") + _count(dims, "right"))
    side_w = stacks + m.box.zlen * s
    sides = [side for side, _ in label_rows(len(labels))]
    above = max(half_v + GAP_MM + row * sides.count(1),
                half_v + DIM_SPACING_MM * _count(dims, "top") + row)
    below = half_v + (GAP_MM + row * sides.count(-1) if -1 in sides else CENTRE_OVER_MM + 1)
    return front_w, side_w, above, below


def _count(dims: list[Dimension], side: str) -> int:
    return sum(d.side == side for d in dims)


def layout(sheet: Sheet, m: Measured, dims: list[Dimension], labels: list[str]) -> Layout:
    """Largest ISO 5455 scale that fits; the drawing centred in the frame above the title."""
    w, h = SHEET_MM
    room_w = w - 2 * MARGIN_MM - 2 * GAP_MM
    room_h = h - 2 * MARGIN_MM - TITLE_H_MM - 2.0
    for s in SCALES:
        front_w, side_w, above, below = _extents(sheet, m, dims, labels, s)
        if front_w + VIEW_GAP_MM + side_w <= room_w and above + below <= room_h:
            break
    else:
        raise ValueError(f"part {m.box.xlen:g} × {m.box.zlen:g} mm does not fit the sheet at "
                         f"scale 1:{1 / SCALES[-1]:g}")
    left = MARGIN_MM + GAP_MM + (room_w - front_w - VIEW_GAP_MM - side_w) / 2
    cx = left + max(front_w, m.box.ylen * s) / 2
    cy = MARGIN_MM + TITLE_H_MM + 1.0 + (room_h - above - below) / 2 + below
    side_x0 = left + front_w + VIEW_GAP_MM + DIM_SPACING_MM * _count(dims, "left")
    return Layout(s, (cx, cy), side_x0, cy, sheet.text_size("Ø0")[1] + 2.0, left)


def assign_sides(dims: list[Dimension], m: Measured) -> None:
    """Put each diameter left or right of the side view, where its extension line runs
    through no material; ties go to the nearer end, then to the shorter stack."""
    ties = []
    for d in (d for d in dims if d.kind == "diameter"):
        left = _clear(m, d.measured_mm / 2, m.box.zmin - 1, d.z0)
        right = _clear(m, d.measured_mm / 2, d.z1, m.box.zmax + 1)
        if left and right and _agree(d.z0 - m.box.zmin, m.box.zmax - d.z1):
            ties.append(d)
        elif left and right:
            d.side = "left" if d.z0 - m.box.zmin < m.box.zmax - d.z1 else "right"
        else:
            d.side = "right" if right else "left"
    for d in sorted(ties, key=lambda d: d.measured_mm):
        d.side = "left" if _count(dims, "left") <= _count(dims, "right") else "right"


def _clear(m: Measured, r: float, z0: float, z1: float) -> bool:
    """True when the line x = r, z0 < z < z1 passes through no material (it may run along
    a surface)."""
    z = np.linspace(z0, z1, 64)[1:-1]
    eps = 10 * TOLERANCE_MM
    above = _inside(m.upper, np.column_stack([z, np.full_like(z, r + eps)]))
    below = _inside(m.upper, np.column_stack([z, np.full_like(z, r - eps)]))
    return not np.any(above & below)


# ---------------------------------------------------------------------------------------------
# Views and annotations.
# ---------------------------------------------------------------------------------------------
def _to_paper(lines: list[np.ndarray], origin, s: float) -> list[np.ndarray]:
    return [np.asarray(origin) + s * ln for ln in lines]


def draw_front(sheet: Sheet, solid: cq.Solid, m: Measured, lay: Layout,
               circles: list[tuple[BoltCircle, list]]) -> list[float]:
    """View from +Z (paper right = −Y, up = +X): outline, hidden edges, centre lines, bolt
    circles. Returns the view's paper box."""
    s, (cx, cy) = lay.scale, lay.front
    visible, hidden = hlr_polylines(solid, (0, 0, 1), (0, -1, 0))
    sheet.lines(_to_paper(hidden, lay.front, s), "thin", DASH_MM)
    sheet.lines(_to_paper(visible, lay.front, s), "visible")
    hu, hv = m.box.ylen / 2 * s, m.box.xlen / 2 * s
    o = CENTRE_OVER_MM
    sheet.lines([np.array([[cx - hu - o, cy], [cx + hu + o, cy]]),
                 np.array([[cx, cy - hv - o], [cx, cy + hv + o]])], "thin", CHAIN_MM)
    t = np.linspace(0, 2 * math.pi, 361)
    for bc, _ in circles:
        r = bc.diameter_mm / 2 * s
        sheet.lines([np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])], "thin",
                    CHAIN_MM)
    return [cx - hu, cy - hv, cx + hu, cy + hv]


def draw_side(sheet: Sheet, solid: cq.Solid, m: Measured, lay: Layout,
              circles: list[tuple[BoltCircle, list]]) -> list[float]:
    """Half section seen from +Y (paper right = +Z, up = +X): upper half cut at y = 0 and
    hatched, lower half the outside view; the axis as a chain line."""
    s, origin = lay.scale, (lay.side_x0 - m.box.zmin * lay.scale, lay.cy)
    reach = max(abs(m.box.xmin), abs(m.box.xmax), abs(m.box.ymin), abs(m.box.ymax)) + 1.0
    kept = solid.intersect(cq.Solid.makeBox(2 * reach, reach, m.box.zlen + 2,
                                            cq.Vector(-reach, -reach, m.box.zmin - 1)))
    for face in m.upper:
        sheet.hatch(_to_paper(face, origin, s))
    cut_view, _ = hlr_polylines(kept, (0, 1, 0), (0, 0, 1))
    outside, _ = hlr_polylines(solid, (0, 1, 0), (0, 0, 1))
    upper = [p for ln in cut_view for p in clip_half(ln, True)]
    lower = [p for ln in outside for p in clip_half(ln, False)]
    sheet.lines(_to_paper(upper + lower, origin, s), "visible")
    x0, x1 = lay.side_x0, lay.side_x0 + m.box.zlen * s
    o = CENTRE_OVER_MM
    sheet.lines([np.array([[x0 - o, lay.cy], [x1 + o, lay.cy]])], "thin", CHAIN_MM)
    _cut_hole_axes(sheet, m, lay, circles)
    r = m.box.xlen / 2 * s
    return [x0, lay.cy - r, x1, lay.cy + r]


def _cut_hole_axes(sheet: Sheet, m: Measured, lay: Layout, circles) -> None:
    """Centre lines of bolt holes the section plane cuts (hole centre on +X)."""
    s = lay.scale
    for bc, centres in circles:
        for x, y in centres:
            if abs(y) > TOLERANCE_MM or x <= 0:
                continue
            zs = [(h.z0, h.z1) for h in m.holes if _agree(h.x, x) and _agree(h.y, y)]
            z0, z1 = min(z for z, _ in zs), max(z for _, z in zs)
            px = lay.side_x0 + (np.array([z0, z1]) - m.box.zmin) * s
            py = lay.cy + x * s
            sheet.lines([np.array([[px[0] - CENTRE_OVER_MM, py], [px[1] + CENTRE_OVER_MM, py]])],
                        "thin", CHAIN_MM)


def _top_at(m: Measured, z: float) -> float:
    """Largest x [mm] of the section at axial position z (where an extension line starts)."""
    xs = [p[1] for face in m.upper for ring in face for p in ring if abs(p[0] - z) < 1e-6]
    return max(xs, default=m.box.xmax)


def dimension_side_view(sheet: Sheet, m: Measured, lay: Layout, dims: list[Dimension]) -> None:
    """Stack the diameters left and right of the side view (smallest nearest) and the
    lengths above it (shortest nearest)."""
    s = lay.scale
    x_left, x_right = lay.side_x0, lay.side_x0 + m.box.zlen * s
    for side, sign, edge in (("left", -1, x_left), ("right", 1, x_right)):
        stack = sorted((d for d in dims if d.side == side), key=lambda d: d.measured_mm)
        for k, d in enumerate(stack, start=1):
            end_z = d.z0 if side == "left" else d.z1
            start = lay.side_x0 + (end_z - m.box.zmin) * s
            _diameter(sheet, d, lay, start, edge + sign * k * DIM_SPACING_MM)
    top = lay.cy + m.box.xmax * s
    for k, d in enumerate(sorted((d for d in dims if d.kind == "length"),
                                 key=lambda d: d.measured_mm), start=1):
        _length(sheet, d, m, lay, top + k * DIM_SPACING_MM)


def _diameter(sheet: Sheet, d: Dimension, lay: Layout, start_x: float, x: float) -> None:
    """Vertical dimension line at paper x: full (two arrows) for external diameters, a half
    dimension line past the axis for internal ones; text left of the line, read from the
    right (ISO 129-1)."""
    r = d.measured_mm / 2 * lay.scale
    ends = [1, -1] if d.external else [1]
    towards = 1 if x > start_x else -1
    for e in ends:
        y = lay.cy + e * r
        start = start_x + towards * EXT_GAP_MM
        sheet.lines([np.array([[start, y], [x + towards * EXT_OVER_MM, y]])], "thin")
    y_low = lay.cy - r if d.external else lay.cy - HALF_DIM_PAST_AXIS_MM
    sheet.lines([np.array([[x, y_low], [x, lay.cy + r]])], "thin")
    sheet.arrow((x, lay.cy + r), (x, lay.cy))
    if d.external:
        sheet.arrow((x, lay.cy - r), (x, lay.cy))
    # internal: centred on the half line, but kept below its arrow so the text stays
    # clear of the extension lines of larger diameters further out
    width = sheet.text_size(d.label)[0]
    y_text = lay.cy if d.external else min(lay.cy + r / 2, lay.cy + r - ARROW_MM - width / 2)
    sheet.text(x - 0.8, y_text, d.label, rotation=90, ha="center", va="bottom")


def _length(sheet: Sheet, d: Dimension, m: Measured, lay: Layout, y: float) -> None:
    """Horizontal dimension line above the side view; extension lines from the outline."""
    s = lay.scale
    xs = [lay.side_x0 + (z - m.box.zmin) * s for z in (d.z0, d.z1)]
    for z, x in zip((d.z0, d.z1), xs):
        y0 = lay.cy + _top_at(m, z) * s + EXT_GAP_MM
        sheet.lines([np.array([[x, y0], [x, y + EXT_OVER_MM]])], "thin")
    room = xs[1] - xs[0]
    width = sheet.text_size(d.label)[0]
    if room >= 2 * ARROW_MM + 1.0:  # arrows inside, pointing out
        sheet.lines([np.array([[xs[0], y], [xs[1], y]])], "thin")
        sheet.arrow((xs[0], y), (xs[1], y))
        sheet.arrow((xs[1], y), (xs[0], y))
    else:  # too short: arrows outside, pointing in (ISO 129-1)
        reach = ARROW_MM + 2.0
        sheet.lines([np.array([[xs[0] - reach, y], [xs[1] + reach, y]])], "thin")
        sheet.arrow((xs[0], y), (xs[0] - reach, y))
        sheet.arrow((xs[1], y), (xs[1] + reach, y))
    if width + 2.0 <= room:
        sheet.text((xs[0] + xs[1]) / 2, y + 0.8, d.label, va="bottom")
    else:  # text beyond the right end of the line
        sheet.text(xs[1] + ARROW_MM + 3.0, y + 0.8, d.label, ha="left", va="bottom")


def label_bolt_circles(sheet: Sheet, m: Measured, lay: Layout,
                       circles: list[tuple[BoltCircle, list]]) -> None:
    """Labels on landings above and below the front view (outer rows' landings reach further
    right so their leaders pass the inner rows), each with a leader to the hole of its circle
    nearest the landing's end; circles go to rows by least total leader length."""
    if not circles:
        return
    s, (cx, cy) = lay.scale, lay.front
    hv = m.box.xlen / 2 * s
    labels = [bolt_circle_label(bc) for bc, _ in circles]
    width = max(sheet.text_size(t)[0] for t in labels)
    text_h = lay.row_mm - 2.0
    ends = []
    for side, row in label_rows(len(circles)):
        y = (cy + hv + GAP_MM + row * lay.row_mm if side > 0
             else cy - hv - GAP_MM - text_h - 1.0 - row * lay.row_mm)
        ends.append((lay.label_x0 + width + LANDING_MM + row * lay.row_mm, y))
    holes = [[(cx - y * s, cy + x * s) for x, y in centres] for _, centres in circles]

    def nearest(i, end):
        return min(holes[i], key=lambda p: math.dist(p, end))

    order = min(itertools.permutations(range(len(circles))),
                key=lambda o: sum(math.dist(nearest(i, e), e) for i, e in zip(o, ends)))
    for i, end in zip(order, ends):
        bc = circles[i][0]
        sheet.lines([np.array([[lay.label_x0, end[1]], end])], "thin")
        hole = np.array(nearest(i, end))
        d = hole - end
        tip = hole - d / np.linalg.norm(d) * bc.hole_diameter_mm / 2 * s
        sheet.lines([np.array([end, tip])], "thin")
        sheet.arrow(tip, end)
        sheet.text(lay.label_x0, end[1] + 0.6, labels[i], ha="left", va="bottom")


def title_strip(sheet: Sheet, part: Part, step_path: Path, scale: float) -> None:
    """Frame and title strip: part, scale, units, projection, source file (cells as wide as
    their text; the file name is shortened from the left if the strip is full)."""
    w, h = SHEET_MM
    m, th, pad = MARGIN_MM, TITLE_H_MM, 2.0
    frame = np.array([[m, m], [w - m, m], [w - m, h - m], [m, h - m], [m, m]])
    sheet.lines([frame, np.array([[m, m + th], [w - m, m + th]])], "thin")
    ratio = f"{scale:g}:1" if scale >= 1 else f"1:{1 / scale:g}"
    cells = [part.name, f"scale {ratio} at {w:g} × {h:g} mm", "dimensions in mm",
             "first-angle projection"]
    x = m
    for i, txt in enumerate(cells):
        weight = "bold" if i == 0 else "normal"
        sheet.text(x + pad, m + th / 2, txt, size=TITLE_PT, ha="left", fontweight=weight)
        x += sheet.text_size(txt, TITLE_PT, weight)[0] + 2 * pad
        sheet.lines([np.array([[x, m], [x, m + th]])], "thin")
    name = f"from {Path(step_path).name}"
    while sheet.text_size(name, TITLE_PT)[0] > w - m - x - 2 * pad and len(name) > 8:
        name = "from …" + name[7:]
    sheet.text(x + pad, m + th / 2, name, size=TITLE_PT, ha="left")


# ---------------------------------------------------------------------------------------------
# Public API
# ---------------------------------------------------------------------------------------------
def verified_dimensions(part: Part, m: Measured) -> list[Dimension]:
    """The part's main dimensions, each checked against the measured solid."""
    return ([outer_dimension(part, m)] + diameter_dimensions(part, m)
            + length_dimensions(part, m))


def part_drawing(step_path: Path, part: Part, svg_path: Path, png_path: Path | None = None
                 ) -> dict:
    """Draw ``part`` as its STEP file holds it: view along the axis and half section with the
    main dimensions and bolt circles, to SVG (and PNG when ``png_path`` is given).

    Parameters
    ----------
    step_path : the part's STEP file [mm], axis on Z, mating face at z = 0
    part : the Part record whose ``dimensions`` [mm] and ``bolt_circles`` are drawn
    svg_path, png_path : output files (PNG at PNG_DPI)

    Returns
    -------
    dict with ``svg``, ``png`` (paths or None), ``views`` (name, paper box [mm]),
    ``dimensions`` (label, stated and measured value [mm]), ``bolt_circles`` (label, count
    found), ``section_extent_mm`` ({"x": [min, max], "z": [min, max]} of the cut through the
    axis), ``scale``, ``text_boxes_mm`` and ``time_s``.

    Raises
    ------
    ValueError when a stated dimension or bolt circle differs from the STEP geometry by more
    than TOLERANCE_MM [mm], or the file holds other than one solid.
    """
    started = time.perf_counter()
    solid = load_step_solid(step_path)
    m = Measured.of(solid)
    dims = verified_dimensions(part, m)
    circles = [(bc, bolt_circle_holes(part, bc, m)) for bc in part.bolt_circles]
    assign_sides(dims, m)
    sheet = Sheet()
    lay = layout(sheet, m, dims, [bolt_circle_label(bc) for bc in part.bolt_circles])
    views = [{"name": "front (from +Z)", "box_mm": draw_front(sheet, solid, m, lay, circles)},
             {"name": "side (half section in XZ, from +Y)",
              "box_mm": draw_side(sheet, solid, m, lay, circles)}]
    dimension_side_view(sheet, m, lay, dims)
    label_bolt_circles(sheet, m, lay, circles)
    title_strip(sheet, part, step_path, lay.scale)
    boxes = sheet.text_boxes()
    sheet.save(Path(svg_path), None if png_path is None else Path(png_path))
    return {"svg": str(svg_path), "png": None if png_path is None else str(png_path),
            "views": views, "dimensions": [d.as_dict() for d in dims],
            "bolt_circles": [{"name": bc.name, "label": bolt_circle_label(bc),
                              "count_found": len(c)} for bc, c in circles],
            "section_extent_mm": section_extent(m.section), "scale": lay.scale,
            "text_boxes_mm": boxes, "time_s": time.perf_counter() - started}
