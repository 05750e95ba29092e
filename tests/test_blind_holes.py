"""Blind tapped holes are drilled with a 118° point and leave a floor under the point.

HOUSING_RULES §4: blind tapped depth = engagement + 3·P run-out, drilled 118°; steel walls
≥ 3 mm. Measured on re-imported STEP files: the conical faces at the hole centres give the
point's angle and the tip's depth; the floor is the tip's distance to the far face.
"""

from __future__ import annotations

import math

import pytest
import yaml

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.design_options import DesignOptions, parse_options  # noqa: E402
from hdcad.geometry.build import build_parts  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402
from hdcad.models import resolve  # noqa: E402
from hdcad.resources import examples_dir  # noqa: E402

FLOOR_MM = 3.0       # HOUSING_RULES §4: least steel wall
POINT_DEG = 118.0    # twist-drill point (DIN 1412 form A)
TOL = 0.01


def _cones(shape, centres, hole_d):
    """(z_min, z_max, half angle°) of the conical faces centred on ``centres`` that are no
    wider than a hole of Ø ``hole_d``."""
    out = []
    for face in shape.Faces():
        if face.geomType() != "CONE":
            continue
        box = face.BoundingBox()
        cx, cy = (box.xmin + box.xmax) / 2, (box.ymin + box.ymax) / 2
        if box.xlen > hole_d + TOL or not any(math.hypot(cx - x, cy - y) < 0.05
                                              for x, y in centres):
            continue
        half = math.degrees(math.atan2(box.xlen / 2, box.zlen))
        out.append((box.zmin, box.zmax, half))
    return out


def _reimported(part, tmp_path):
    path = tmp_path / f"{part.name}.step"
    export_step(part, path)
    return cq.importers.importStep(str(path)).val()


def _check(part, circle, tmp_path, far_face_z):
    shape = _reimported(part, tmp_path)
    r = circle.diameter_mm / 2
    centres = [(r * math.cos(math.radians(circle.start_angle_deg + 360 * k / circle.count)),
                r * math.sin(math.radians(circle.start_angle_deg + 360 * k / circle.count)))
               for k in range(circle.count)]
    points = [c for c in _cones(shape, centres, circle.hole_diameter_mm)
              if c[2] == pytest.approx(POINT_DEG / 2, abs=0.5)]
    assert len(points) == circle.count
    for z_min, z_max, _ in points:
        tip = z_min if far_face_z < z_min else z_max
        assert abs(tip - far_face_z) >= FLOOR_MM - TOL


def test_gh_motor_flange_tapped_holes_have_a_point_and_a_floor(tmp_path):
    catalog = load_catalog()
    parts = build_parts(resolve("CSF-45-120-GH", catalog), catalog, DesignOptions())
    flange = next(p for p in parts if p.name == "motor_flange")
    (tapped,) = [c for c in flange.bolt_circles if c.kind == "tapped"]
    _check(flange, tapped, tmp_path, 0.0)   # drilled from the motor face towards z = 0


def test_motor_adapter_tapped_holes_have_a_point_and_a_floor(tmp_path):
    catalog = load_catalog()
    raw = yaml.safe_load((examples_dir() / "design_motor_adapter.yaml").read_text("utf-8"))
    options = parse_options(raw)
    parts = build_parts(resolve("CSF-45-120-GH", catalog), catalog, options)
    adapter = next(p for p in parts if p.name == "motor_adapter")
    (tapped,) = [c for c in adapter.bolt_circles if c.kind == "tapped"]
    _check(adapter, tapped, tmp_path, 0.0)  # from the motor face towards the gear-head face
