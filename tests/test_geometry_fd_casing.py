"""FD-…-2 casing half: build every size, export STEP, re-import it and measure the solid."""

import copy
import math

import pytest

cq = pytest.importorskip("cadquery")
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.fd_casing import FDCasingHalf  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402

TOL = 0.01
SIZES = FDCasingHalf.sizes(load_catalog())


def _z_cylinders(shape):
    """(x, y, radius) of every cylindrical face whose axis is parallel to Z, deduplicated."""
    found = set()
    for face in shape.Faces():
        if face.geomType() != "CYLINDER":
            continue
        cyl = BRepAdaptor_Surface(face.wrapped).Cylinder()
        axis = cyl.Axis().Direction()
        if abs(abs(axis.Z()) - 1.0) > 1e-9:
            continue
        loc = cyl.Location()
        found.add((round(loc.X(), 4), round(loc.Y(), 4), round(cyl.Radius(), 4)))
    return found


def _holes_on_circle(cylinders, circle_d, hole_d):
    """Centres of holes Ø hole_d whose centre lies on the circle Ø circle_d (± TOL)."""
    return {(x, y) for x, y, r in cylinders
            if abs(r - hole_d / 2) <= TOL and abs(math.hypot(x, y) - circle_d / 2) <= TOL}


def _central_diameters(cylinders):
    return {2 * r for x, y, r in cylinders if math.hypot(x, y) <= TOL}


@pytest.fixture(scope="module")
def catalog():
    return load_catalog()


@pytest.mark.parametrize("size", SIZES)
def test_casing_half_step_round_trip(size, catalog, tmp_path):
    part = FDCasingHalf(size, catalog, DesignOptions(), side="D").build()
    assert part.name == "casing_half_D"
    path = tmp_path / f"{part.name}.step"
    export_step(part, path)
    shape = cq.importers.importStep(str(path)).val()

    solids = shape.Solids()
    assert len(solids) == 1 and shape.isValid()
    assert isinstance(solids[0], cq.Solid)
    dims = part.dimensions
    box = shape.BoundingBox()
    assert box.xlen == pytest.approx(dims["outer_diameter_mm"], abs=TOL)
    assert box.ylen == pytest.approx(dims["outer_diameter_mm"], abs=TOL)
    assert box.zmin == pytest.approx(0.0, abs=TOL)
    assert box.zlen == pytest.approx(dims["thickness_mm"], abs=TOL)

    cylinders = _z_cylinders(shape)
    central = _central_diameters(cylinders)
    for key in ("pilot_recess_mm", "bearing_seat_mm", "spigot_recess_mm", "seal_recess_mm",
                "shaft_hole_mm"):
        assert any(abs(d - dims[key]) <= TOL for d in central), (key, sorted(central))

    screws, gear = part.bolt_circles
    for circle in (screws, gear):
        centres = _holes_on_circle(cylinders, circle.diameter_mm, circle.hole_diameter_mm)
        assert len(centres) == circle.count, circle.name
        measured = 2 * sum(math.hypot(x, y) for x, y in centres) / len(centres)
        assert measured == pytest.approx(circle.diameter_mm, abs=TOL), circle.name

    # the M10×1 oil hole (tap drill Ø9) at the radius the part reports
    plug = _holes_on_circle(cylinders, 2 * dims["oil_plug_radius_mm"], 9.0)
    assert len(plug) == 1


@pytest.mark.parametrize("size", SIZES)
def test_catalog_values_and_axial_rule(size, catalog):
    fd0, fd2 = catalog.find("fd0_dimensions", size=size), catalog.find("fd2_dimensions", size=size)
    options = DesignOptions(running_gap_mm=0.6)
    half = FDCasingHalf(size, catalog, options, side="S")
    part = half.build()
    dims = part.dimensions
    assert part.name == "casing_half_S"
    assert dims["outer_diameter_mm"] == fd0["A_mm"]
    assert dims["pilot_recess_mm"] == fd2["A_g7_mm"]
    assert dims["spigot_recess_mm"] == fd0["B_H7_mm"]
    assert dims["pilot_depth_mm"] == pytest.approx(fd2["B_mm"] + fd2["C_mm"] / 2 - 0.3)
    floor = dims["thickness_mm"] - dims["pilot_depth_mm"]
    assert floor >= (fd0["D_mm"] - fd2["D_mm"]) / 2 - 1e-9
    assert floor >= half.bearing_w + half.seal_w + options.wall_mm
    if floor == pytest.approx((fd0["D_mm"] - fd2["D_mm"]) / 2):
        # two halves plus the running gap make exactly the FD-0 unit width
        assert 2 * dims["thickness_mm"] + 0.6 == pytest.approx(fd0["D_mm"])
    assert dims["oil_plug_radius_mm"] >= catalog.find("fd_oil_level", size=size)["A_mm"]
    screws, gear = part.bolt_circles
    assert (screws.name, screws.diameter_mm, screws.count, screws.thread, screws.kind) == (
        "spline_screws", fd2["I_mm"], fd2["J_count"], fd2["K_thread"], "clearance")
    assert (gear.name, gear.diameter_mm, gear.count, gear.thread, gear.kind, gear.depth_mm) == (
        "gear_mount", fd0["K_mm"], fd0["L_count"], fd0["M_thread"], "tapped", fd0["M_depth_mm"])
    assert any("running_gap" in n for n in part.notes)
    assert any("oil level A" in n and "axis" in n for n in part.notes)


def test_unknown_size_names_the_allowed_sizes(catalog):
    with pytest.raises(ValueError, match="allowed sizes: 20, 25, 32"):
        FDCasingHalf(33, catalog, DesignOptions())
    with pytest.raises(ValueError, match="allowed: S, D"):
        FDCasingHalf(20, catalog, DesignOptions(), side="X")


def test_bolt_circle_that_does_not_fit_raises(catalog):
    bad = copy.deepcopy(catalog)  # deep copy: the shipped rows are shared between catalogs
    bad.find("fd2_dimensions", size=40)["I_mm"] = 140.0  # holes beyond the Ø135 spline
    with pytest.raises(ValueError, match="spline_screws.*annulus"):
        FDCasingHalf(40, bad, DesignOptions())
    bad.find("fd0_dimensions", size=50)["L_count"] = 60  # 60 × M10 on Ø155 overlap
    with pytest.raises(ValueError, match="gear_mount.*overlap"):
        FDCasingHalf(50, bad, DesignOptions())
