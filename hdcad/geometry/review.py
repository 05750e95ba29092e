"""Review assembly: the generated parts with their neighbours as true-size bodies, and the
probes a design reviewer runs on it (interference, bearing location, seal journals, screw
engagement), measured on the solids.

Works for any family whose parts carry ``Neighbour`` records with bodies.
"""

from __future__ import annotations

import itertools
import weakref
from dataclasses import dataclass

import cadquery as cq

from .features import annulus
from .part import Neighbour, Part

PROBE_MM = 0.05        # thickness of the probe slab laid against a face
TOUCH_MM3 = 1e-4       # a probe slab that overlaps another body by more than this touches it
OVERLAP_MM3 = 1e-2     # two bodies overlapping by more than this interfere (OCCT noise below)


SEAL_KINDS = ("seal", "oring")  # bodies that close a joint between parts that move


@dataclass
class Body:
    label: str
    kind: str          # "part" or the neighbour's kind
    solid: cq.Shape
    neighbour: Neighbour | None = None
    group: str = ""    # rotation group: bodies of different groups move against each other


def _place(part: Part, shape: cq.Shape) -> cq.Shape:
    if part.flip:
        shape = shape.rotate((0, 0, 0), (1, 0, 0), 180)
    return shape.translate((0, 0, part.offset_z_mm))


def review_bodies(parts: list[Part]) -> list[Body]:
    """Every part and every neighbour body, placed in assembly coordinates."""
    bodies = [Body(p.name, "part", p.placed(), group=p.turns_with or p.name) for p in parts]
    for part in parts:
        for i, n in enumerate(n for n in part.neighbours if n.body is not None):
            bodies.append(Body(f"{part.name}/{n.kind}{i}:{n.designation}", n.kind,
                               _place(part, n.body), n,
                               n.turns_with or part.turns_with or part.name))
    return bodies


def reach(bodies: list[Body]) -> float:
    """Largest distance [mm] from the axis that any body's bounding box reaches (corners
    included: a square flange reaches half its diagonal)."""
    import math
    return max(math.hypot(max(abs(b.xmin), abs(b.xmax)), max(abs(b.ymin), abs(b.ymax)))
               for b in (_box(body.solid) for body in bodies))


# bounding boxes by shape: every pair test needs both, and an optimal box costs milliseconds
_BOXES: "weakref.WeakKeyDictionary[cq.Shape, cq.BoundBox]" = weakref.WeakKeyDictionary()


def _box(shape: cq.Shape) -> cq.BoundBox:
    box = _BOXES.get(shape)
    if box is None:
        box = _BOXES[shape] = shape.BoundingBox()
    return box


def _boxes_meet(a: cq.Shape, b: cq.Shape) -> bool:
    ba, bb = _box(a), _box(b)
    return (ba.xmin <= bb.xmax and bb.xmin <= ba.xmax and ba.ymin <= bb.ymax
            and bb.ymin <= ba.ymax and ba.zmin <= bb.zmax and bb.zmin <= ba.zmax)


def overlap_mm3(a: cq.Shape, b: cq.Shape) -> float:
    if not _boxes_meet(a, b):
        return 0.0
    common = a.intersect(b)
    return common.Volume() if common.Solids() else 0.0


def interferences(bodies: list[Body]) -> list[tuple[str, str, float]]:
    """(a, b, volume mm³) for every pair of bodies that overlap by more than OVERLAP_MM3."""
    out = []
    for a, b in itertools.combinations(bodies, 2):
        v = overlap_mm3(a.solid, b.solid)
        if v > OVERLAP_MM3:
            out.append((a.label, b.label, v))
    return out


def _touching(probe: cq.Shape, bodies: list[Body], skip: Body) -> list[str]:
    return [b.label for b in bodies if b is not skip and overlap_mm3(probe, b.solid) > TOUCH_MM3]


def _axis_frame(body: Body) -> tuple[float, float]:
    """(z_min, z_max) of a body on the assembly axis."""
    box = _box(body.solid)
    return box.zmin, box.zmax


def bearing_stops(bodies: list[Body]) -> list[dict]:
    """For each bearing, which bodies touch each face of its inner and outer ring.

    A probe slab PROBE_MM thick lies against each end face over the ring's own radial band
    (inner ring: d … d + (D−d)/4; outer ring: D − (D−d)/4 … D)."""
    rows = []
    for body in (b for b in bodies if b.kind == "bearing"):
        d, big_d = body.neighbour.dims["d"], body.neighbour.dims["D"]
        quarter = (big_d - d) / 4
        z0, z1 = _axis_frame(body)
        bands = {"inner": (d + 0.2, d + 2 * quarter), "outer": (big_d - 2 * quarter,
                                                                big_d - 0.2)}
        row = {"bearing": body.label}
        for ring, (lo, hi) in bands.items():
            for side, (a, b) in (("low", (z0 - PROBE_MM, z0)), ("high", (z1, z1 + PROBE_MM))):
                row[f"{ring}_{side}"] = _touching(annulus(lo, hi, a, b), bodies, body)
        rows.append(row)
    return rows


def seal_journals(bodies: list[Body]) -> list[dict]:
    """For each lip seal: the fraction of its width over which a body fills the shaft
    diameter d1 (a journal of its own diameter), and what that body is."""
    rows = []
    for body in (b for b in bodies if b.kind == "seal"):
        d1 = body.neighbour.dims["d1"]
        z0, z1 = _axis_frame(body)
        probe = annulus(d1 - 0.2, d1, z0, z1)
        full = probe.Volume()
        best = max(((overlap_mm3(probe, b.solid) / full, b.label) for b in bodies
                    if b is not body), default=(0.0, ""))
        rows.append({"seal": body.label, "covered": best[0], "journal": best[1]})
    return rows


def screw_engagements(bodies: list[Body]) -> list[dict]:
    """Engaged length, least engagement and thread depth of each screw (its dims)."""
    return [{"screw": b.label, **{k: b.neighbour.dims[k] for k in
                                 ("engaged", "engaged_min", "thread_depth")}}
            for b in bodies if b.kind == "screw"]


def review_assembly_step(bodies: list[Body], path) -> None:
    """One STEP with every part and neighbour, named and coloured (neighbours grey)."""
    assy = cq.Assembly(name="review_assembly")
    for i, body in enumerate(bodies):
        color = cq.Color(0.8, 0.5, 0.2) if body.kind == "part" else cq.Color(0.5, 0.5, 0.5)
        name = body.label.replace("/", "_").replace(":", "_").replace(" ", "_")
        assy.add(cq.Workplane().add(body.solid), name=f"{i:02d}_{name}", color=color)
    assy.export(str(path), exportType="STEP")


# -- oil tightness: flood fill on axial sections ------------------------------------------------
OPEN_KINDS = ("bearing",)  # oil passes through a bearing: it is not a seal


def section_mask(bodies: list[Body], angle_deg: float, r_max: float, z_range: tuple,
                 step: float, skip_kinds=OPEN_KINDS):
    """Boolean grid [z, r] of the half-plane at ``angle_deg`` through the axis: True where a
    body (other than ``skip_kinds``) is cut; r from 0 to r_max, z over z_range, ``step`` mm.

    Where bodies of different rotation groups touch (a running fit, a running gap drawn at
    zero), one grid cell is opened on each side unless a seal body lies there: bodies that
    move against each other leave a clearance, which only a seal closes. Static joints of
    one group count as closed (O-ring or liquid gasket, as the parts' notes say)."""
    import numpy as np

    from .drawing.measure import _inside, xz_section
    zs = np.arange(z_range[0], z_range[1] + step / 2, step)
    rs = np.arange(step / 2, r_max, step)
    zz, rr = np.meshgrid(zs, rs, indexing="ij")
    points = np.column_stack([zz.ravel(), rr.ravel()])
    groups = {b.group for b in bodies}
    owner = np.full(len(points), -1)          # index of the group that fills the cell
    sealed = np.zeros(len(points), bool)
    index = {g: i for i, g in enumerate(sorted(groups))}
    for body in bodies:
        if body.kind in skip_kinds:
            continue
        turned = body.solid.rotate((0, 0, 0), (0, 0, 1), -angle_deg)
        faces = xz_section(turned, 0.0, r_max)
        if not faces:
            continue
        hit = _inside(faces, points)
        if body.kind in SEAL_KINDS:
            sealed |= hit
        else:
            owner[hit] = index[body.group]
    owner = owner.reshape(zz.shape)
    sealed = sealed.reshape(zz.shape)
    solid = (owner >= 0) | sealed
    return solid & ~_moving_contacts(owner, sealed), zs, rs


def _moving_contacts(owner, sealed):
    """Cells of one group that touch a cell of another group (8-neighbours: a contact that
    runs at a slant, e.g. where a lead-in chamfer meets a bore, touches only diagonally on
    the grid), not at a seal."""
    import numpy as np
    out = np.zeros(owner.shape, bool)
    for dz in (-1, 0, 1):
        for dr in (-1, 0, 1):
            if dz == dr == 0:
                continue
            other = np.roll(owner, (dz, dr), axis=(0, 1))
            other_sealed = np.roll(sealed, (dz, dr), axis=(0, 1))
            out |= (owner >= 0) & (other >= 0) & (other != owner) & ~other_sealed
    return out & ~sealed


def oil_escapes(bodies: list[Body], seed_zr: tuple[float, float], angles: list[float],
                step: float = 0.2, skip_kinds=OPEN_KINDS) -> dict[float, bool]:
    """For each section angle: does the free space that holds the seed point (z, r) reach
    the edge of the section (the outside)? Touching bodies (a seal on its journal, a face
    with liquid gasket) close the path; a gap of one grid step or more opens it."""
    import numpy as np
    from scipy import ndimage
    box = [b.solid.BoundingBox() for b in bodies]
    r_max = reach(bodies) + 2
    z_range = (min(b.zmin for b in box) - 2, max(b.zmax for b in box) + 2)
    out = {}
    for angle in angles:
        solid, zs, rs = section_mask(bodies, angle, r_max, z_range, step, skip_kinds)
        labels, _ = ndimage.label(~solid)
        i, j = int(round((seed_zr[0] - zs[0]) / step)), int(np.argmin(abs(rs - seed_zr[1])))
        seed = labels[i, j]
        if seed == 0:
            raise ValueError(f"the seed point {seed_zr} lies inside a body at {angle:g}°")
        edge = set(labels[0, :]) | set(labels[-1, :]) | set(labels[:, -1])
        out[angle] = bool(seed in edge)
    return out


# -- the whole review ---------------------------------------------------------------------------
def run_review(parts: list[Part], plan: dict, folder=None) -> dict:
    """Probe results of the review assembly (JSON-ready); with ``folder``, also
    ``review_assembly.step`` and ``figures/review_section.png`` there.

    ``plan``: ``seed_zr`` (a point inside the oil cavity, assembly z and radius [mm]) and
    ``angles`` (section angles [°] for the oil flood fill and the render: ports, holes)."""
    from pathlib import Path
    bodies = review_bodies(parts)
    result = {"bodies": len(bodies),
              "interferences": [{"a": a, "b": b, "volume_mm3": v}
                                for a, b, v in interferences(bodies)],
              "bearings": bearing_stops(bodies), "seals": seal_journals(bodies),
              "screws": screw_engagements(bodies),
              "oil_escapes": ({} if plan["seed_zr"] is None else
                              {f"{a:g}": e for a, e in oil_escapes(
                                  bodies, plan["seed_zr"], plan["angles"]).items()}),
              "section_angle_deg": plan["angles"][0], "files": []}
    if folder is not None:
        from .review_render import render_section
        folder = Path(folder)
        review_assembly_step(bodies, folder / "review_assembly.step")
        (folder / "figures").mkdir(exist_ok=True)
        render_section(bodies, plan["angles"][0], folder / "figures" / "review_section.png",
                       plan.get("title", "review assembly, section through the axis"))
        result["files"] = ["review_assembly.step", "figures/review_section.png"]
    return result
