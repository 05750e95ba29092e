"""Mounting plate of a GH gear head on the machine: built only from the overlay table
gh_mounting_interface (the seeds' outline figures are lost), measured on its STEP file.

Expected numbers come from the test overlay (invented data, named so), ISO 273 (medium
clearance Ø11 for M10), DIN 974-1 (counterbore Ø18 for M10 ISO 4762) and ISO 286-2
(H7 on Ø160: 120 < 160 ≤ 180 → IT7 = 40 µm), never from the plate module.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.checks.geometric import geometric_checks  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.build import build_parts  # noqa: E402
from hdcad.geometry.drawing import part_drawing  # noqa: E402
from hdcad.geometry.drawing.measure import z_cylinders  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402
from hdcad.models import resolve  # noqa: E402

OVERLAY = Path(__file__).parent / "data" / "overlay_gh_mounting_TEST_DATA_NOT_CATALOG.yaml"
TOL = 0.01


def _plate(catalog):
    parts = build_parts(resolve("CSF-45-120-GH", catalog), catalog, DesignOptions())
    return parts, next((p for p in parts if p.name == "mounting_plate"), None)


def test_without_the_interface_no_plate_and_the_check_names_the_fields():
    catalog = load_catalog()
    parts, plate = _plate(catalog)
    assert plate is None
    (check,) = [c for c in geometric_checks(resolve("CSF-45-120-GH", catalog), parts,
                                            DesignOptions(), catalog)
                if c.id == "gh_mounting_plate"]
    assert check.status == "not_evaluated"
    for field in ("pilot_diameter_mm", "bolt_circle_mm", "bolt_count", "bolt_thread"):
        assert field in str(check.__dict__)


def test_plate_from_the_overlay_measured_on_its_step(tmp_path):
    catalog = load_catalog(OVERLAY)
    parts, plate = _plate(catalog)
    assert plate is not None
    path = tmp_path / "mounting_plate.step"
    export_step(plate, path)
    shape = cq.importers.importStep(str(path)).val()
    assert len(shape.Solids()) == 1 and shape.isValid()
    box = shape.BoundingBox()
    t = plate.dimensions["thickness_mm"]
    assert box.zlen == pytest.approx(t, abs=TOL)
    side = box.xlen
    assert box.ylen == pytest.approx(side, abs=TOL)
    cyl = z_cylinders(shape)
    central = {round(c.diameter, 3) for c in cyl if math.hypot(c.x, c.y) < TOL}
    assert {160.0, 120.0} <= central                      # gear-head pilot recess, output bore
    recess = [c for c in cyl if abs(c.diameter - 160) < TOL and math.hypot(c.x, c.y) < TOL]
    assert max(c.z1 for c in recess) == pytest.approx(6.0, abs=TOL)   # overlay pilot depth
    ring = [c for c in cyl if abs(c.diameter - 11) < TOL
            and abs(math.hypot(c.x, c.y) - 95) < TOL]
    assert len({(round(c.x, 2), round(c.y, 2)) for c in ring}) == 8   # 8 × Ø11 on Ø190
    assert side / 2 - 95 >= 1.5 * 10 - TOL                             # their edge distance
    cbores = [c for c in cyl if abs(c.diameter - 18) < TOL]
    assert cbores and all(c.z1 == pytest.approx(t, abs=TOL) for c in cbores)  # machine face
    corners = {(round(c.x, 2), round(c.y, 2)) for c in cyl if abs(c.diameter - 11) < TOL
               and math.hypot(c.x, c.y) > 95 + TOL}
    assert len(corners) == 4
    head = 16.0  # ISO 4762 M10 head Ø dk
    for x, y in corners:   # 1.5·d (M10) from both edges, heads clear of the gear head's Ø215
        assert side / 2 - max(abs(x), abs(y)) >= 1.5 * 10 - TOL
        assert math.hypot(x, y) - head / 2 - 215 / 2 >= 1.0 - TOL
    (fit,) = plate.fits
    assert (fit.nominal_mm, fit.code, fit.deviations_um) == (160, "H7", (40, 0))
    checks = geometric_checks(resolve("CSF-45-120-GH", catalog), parts, DesignOptions(),
                              catalog)
    (mount,) = [c for c in checks if c.id == "gh_mounting_plate"]
    assert mount.status == "pass"
    # corner screw heads: a·√2 − 215/2 − 16/2 measured from the STEP corner holes
    a = max(abs(x) for x, _ in corners)
    assert mount.value == pytest.approx(a * math.sqrt(2) - 215 / 2 - head / 2, abs=TOL)
    patterns = [c for c in checks if c.id == "bolt_pattern"
                and "mounting_plate" in str(c.__dict__)]
    assert len(patterns) == 2
    result = part_drawing(path, plate, tmp_path / "p.svg", tmp_path / "p.png")
    assert {b["count_found"] for b in result["bolt_circles"]} == {8, 4}


THREADS = Path(__file__).parent / "data" / "overlay_gh_threads_TEST_DATA_NOT_CATALOG.yaml"


def test_without_thread_depth_the_plate_has_no_review_bodies():
    _, plate = _plate(load_catalog(OVERLAY))
    assert plate.neighbours == []
    assert any("no thread_depth_mm" in n for n in plate.notes)


def test_review_assembly_of_both_plates_with_the_gear_head_and_screws():
    """With the gear head's thread depth (overlay), both plates meet the gear-head housing:
    nothing overlaps, each screw engages ≥ 1·d (VDI 2230, steel) and stays short of the
    thread's end; the M10 corner screws' heads sit on the gear side, clear of the housing."""
    from hdcad.geometry.build import review_plan
    from hdcad.geometry.review import run_review
    catalog = load_catalog(THREADS)
    model = resolve("CSF-45-120-GH", catalog)
    parts = build_parts(model, catalog, DesignOptions())
    assert {p.name for p in parts} >= {"motor_flange", "mounting_plate"}
    result = run_review(parts, review_plan(model, parts))
    assert not [i for i in result["interferences"] if i["volume_mm3"] > 0.01]
    screws = result["screws"]
    m8 = [s for s in screws if "M8" in s["screw"]]
    m10 = [s for s in screws if "M10" in s["screw"]]
    assert (len(m8), len(m10)) == (4, 8 + 4)
    for s in screws:
        d = 8.0 if "M8" in s["screw"] else 10.0
        assert d - 1e-6 <= s["engaged"] <= s["thread_depth"] + 1e-6
    assert {s["thread_depth"] for s in m8} == {12}
    assert 16 in {s["thread_depth"] for s in m10}
    plate = next(p for p in parts if p.name == "mounting_plate")
    corner = [n for n in plate.neighbours if n.kind == "screw" and n.z_mm == 0.0]
    assert len(corner) == 4
    for n in corner:   # head on the gear side (z < 0 in plate coordinates)
        box = n.body.BoundingBox()
        assert box.zmin < 0 and box.zmax == pytest.approx(n.dims["l"], abs=0.05)
