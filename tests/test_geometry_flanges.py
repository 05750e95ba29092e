"""Flange part families: build every catalog size / complete flange code, export STEP,
re-import it and measure the solid against the catalog table."""

import math

import cadquery as cq
import pytest
import yaml
from OCP.BRep import BRep_Tool

from hdcad.catalog import load_catalog
from hdcad.design_options import DesignOptions
from hdcad.geometry.flanges import (PILOT_BOSS_HEIGHT_MM, FDDriveFlange, GHMotorFlange,
                                    check_ring)
from hdcad.geometry.part import export_step

TOL = 0.01  # mm
CATALOG = load_catalog()
FD_SIZES = FDDriveFlange.sizes(CATALOG)
GH_CODES = [(series, size, code) for series in GHMotorFlange.series_names(CATALOG)
            for size in GHMotorFlange.sizes(CATALOG, series)
            for code in GHMotorFlange.codes(CATALOG, series, size)]


def reimported(part, tmp_path) -> cq.Workplane:
    path = tmp_path / f"{part.name}.step"
    export_step(part, path)
    return cq.importers.importStep(str(path))


def cylinders(shape: cq.Shape) -> list[tuple[float, float, float, float]]:
    """(radius, x, y, |axis·Z|) of every cylindrical face."""
    from hdcad.geometry.drawing.measure import cylinder_faces
    return [(r, x, y, z) for _, r, (x, y), z in cylinder_faces(shape)]


def single_closed_solid(wp: cq.Workplane) -> cq.Solid:
    solids = wp.solids().vals()
    assert len(solids) == 1
    solid = solids[0]
    assert solid.isValid()
    assert all(BRep_Tool.IsClosed_s(shell.wrapped) for shell in solid.Shells())
    return solid


def on_axis_radii(cyls) -> list[float]:
    return [r for r, x, y, z in cyls if z > 1 - 1e-9 and math.hypot(x, y) < TOL]


def hole_centres(cyls, hole_d: float) -> set[tuple[float, float]]:
    """Distinct centres of Z-parallel, off-axis cylinders of the hole diameter."""
    return {(round(x, 3), round(y, 3)) for r, x, y, z in cyls
            if abs(2 * r - hole_d) < TOL and z > 1 - 1e-9 and math.hypot(x, y) > 1.0}


def assert_bolt_circle(cyls, circle):
    centres = hole_centres(cyls, circle.hole_diameter_mm)
    assert len(centres) == circle.count
    for x, y in centres:
        assert math.hypot(x, y) == pytest.approx(circle.diameter_mm / 2, abs=TOL)


@pytest.mark.parametrize("size", FD_SIZES)
def test_fd_drive_flange_matches_table(size, tmp_path):
    row = CATALOG.find("fd0_dimensions", size=size)
    part = FDDriveFlange(size, CATALOG, DesignOptions()).build()
    solid = single_closed_solid(reimported(part, tmp_path))
    box = solid.BoundingBox()
    assert box.xlen == pytest.approx(row["A_mm"], abs=TOL)
    assert box.ylen == pytest.approx(row["A_mm"], abs=TOL)
    assert box.zmin == pytest.approx(-PILOT_BOSS_HEIGHT_MM, abs=TOL)
    cyls = cylinders(solid)
    radii = on_axis_radii(cyls)
    assert any(abs(2 * r - row["B_H7_mm"]) < TOL for r in radii)       # pilot boss φB
    assert any(abs(2 * r - part.dimensions["bore_mm"]) < TOL for r in radii)
    assert part.dimensions["bore_mm"] > row["C_mm"]                   # clears the WG shaft φC
    (circle,) = part.bolt_circles
    assert (circle.kind, circle.count, circle.thread) == ("clearance", row["L_count"],
                                                          row["M_thread"])
    assert circle.diameter_mm == row["K_mm"]
    assert_bolt_circle(cyls, circle)
    assert len(hole_centres(cyls, part.dimensions["counterbore_diameter_mm"])) == circle.count


@pytest.mark.parametrize("series,size,code", GH_CODES)
def test_gh_motor_flange_matches_table(series, size, code, tmp_path):
    row = CATALOG.find("gh_motor_flange", series=series, size=size, flange_code=code)
    part = GHMotorFlange(series, size, code, CATALOG, DesignOptions()).build()
    solid = single_closed_solid(reimported(part, tmp_path))
    box = solid.BoundingBox()
    width = row["square_mm"] or part.dimensions["outer_diameter_mm"]
    assert box.xlen == pytest.approx(width, abs=TOL)
    assert box.ylen == pytest.approx(width, abs=TOL)
    assert (box.zmin, box.zmax) == pytest.approx((0, part.dimensions["thickness_mm"]), abs=TOL)
    cyls = cylinders(solid)
    radii = on_axis_radii(cyls)
    assert any(abs(2 * r - row["pilot_H7_mm"]) < TOL for r in radii)   # motor pilot
    assert part.dimensions["bore_mm"] > row["coupling_bore_max_mm"]
    assert any(abs(2 * r - part.dimensions["bore_mm"]) < TOL for r in radii)
    (circle,) = part.bolt_circles
    assert (circle.kind, circle.thread, circle.depth_mm) == ("tapped", row["thread"],
                                                             row["thread_depth_mm"])
    assert circle.diameter_mm == row["bolt_circle_mm"]
    assert_bolt_circle(cyls, circle)
    # the plate is ordered and drawn in whole millimetres, under the drill's point and floor
    t = part.dimensions["thickness_mm"]
    assert t == int(t) and t >= part.dimensions["drill_depth_mm"] + 3.0


def test_complete_codes_listed():
    assert len(GH_CODES) == 31
    assert GHMotorFlange.codes(CATALOG, "CSG-GH", 14) == ["AB", "AD", "BA"]
    assert GHMotorFlange.sizes(CATALOG, "CSF-GH") == [14, 45]


def test_incomplete_code_names_missing_column_and_complete_codes():
    with pytest.raises(ValueError, match=r"KB.*lacks pilot_H7_mm, bolt_circle_mm.*KA, KC, KD"):
        GHMotorFlange("CSG-GH", 32, "KB", CATALOG)


@pytest.mark.parametrize("args,allowed", [
    (("CSF-GH", 45, "XX"), "PA, PB, PC, PD, PE, PF, PG, PR, PP, PQ"),
    (("CSF-GH", 20, "PA"), "allowed sizes: 14, 45"),
    (("CSX-GH", 14, "AB"), "allowed: CSF-GH, CSG-GH"),
])
def test_unknown_gh_request_lists_allowed(args, allowed):
    with pytest.raises(ValueError, match=allowed):
        GHMotorFlange(*args, CATALOG)


def test_unknown_fd_size_lists_allowed():
    with pytest.raises(ValueError, match="allowed sizes: 20, 25, 32, 40, 50, 65, 80, 100"):
        FDDriveFlange(30, CATALOG)


def test_input_shaft_outside_coupling_range():
    with pytest.raises(ValueError, match="outside the input coupling bore range 14-24"):
        GHMotorFlange("CSF-GH", 45, "PA", CATALOG, DesignOptions(input_shaft_mm=30.0))


def overlay_catalog(tmp_path, table, row):
    path = tmp_path / "overlay.yaml"
    path.write_text(yaml.safe_dump({"source": "test", "tables": {table: [row]}}))
    return load_catalog(path)


def test_gh_bolt_circle_inside_pilot_raises(tmp_path):
    row = dict(CATALOG.find("gh_motor_flange", series="CSF-GH", size=45, flange_code="PA"))
    row.update(bolt_circle_mm=72.0, note=None, source=None)
    catalog = overlay_catalog(tmp_path, "gh_motor_flange",
                              {k: v for k, v in row.items() if v is not None})
    with pytest.raises(ValueError, match=r"bolt circle Ø72 .* cuts the Ø70 pilot") as err:
        GHMotorFlange("CSF-GH", 45, "PA", catalog)
    assert "\n" not in str(err.value)


def test_fd_bolt_circle_outside_edge_raises(tmp_path):
    row = dict(CATALOG.find("fd0_dimensions", size=20), K_mm=82.0)
    catalog = overlay_catalog(tmp_path, "fd0_dimensions", row)
    with pytest.raises(ValueError, match=r"bolt circle Ø82 .* does not fit inside the Ø85"):
        FDDriveFlange(20, catalog)


def test_gh_bolt_circle_outside_square_raises(tmp_path):
    row = dict(CATALOG.find("gh_motor_flange", series="CSF-GH", size=45, flange_code="PG"))
    row.update(bolt_circle_mm=175.0, note=None, source=None)
    catalog = overlay_catalog(tmp_path, "gh_motor_flange",
                              {k: v for k, v in row.items() if v is not None})
    with pytest.raises(ValueError, match=r"does not fit inside the □130 square"):
        GHMotorFlange("CSF-GH", 45, "PG", catalog)


def test_overlapping_neighbours_raise():
    with pytest.raises(ValueError, match="overlap their neighbours"):
        check_ring("test", 40.0, 16, 9.0, 10.0, outer_d=80.0)
