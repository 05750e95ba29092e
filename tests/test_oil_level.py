"""oil_level: the pure check's criteria, and the cavity volume from OCCT against the
circular-segment formula."""

import math

import pytest

from hdcad.checks.oil_level import oil_level


def _check(**kw):
    args = dict(lubrication="oil", level_mm=15.0, level_source="table 315-1",
                axis="horizontal", cavity_depth_mm=42.5, seal_shaft_mm=30.0,
                oil_volume_mL=40.0)
    args.update(kw)
    return oil_level(**args)


def test_level_between_seal_lip_and_cavity_bottom_passes():
    r = _check()
    assert r.status == "pass" and (r.value, r.limit) == (15.0, 42.5)
    assert r.margin == pytest.approx((42.5 - 15) / 42.5)
    assert "40 mL" in r.note and r.details["oil_volume_mL"] == 40.0


def test_seal_lip_below_the_oil_surface_fails():
    # a Ø40 shaft puts the lip 20 mm below the axis, under a surface 15 mm below it
    r = _check(seal_shaft_mm=40.0)
    assert r.status == "fail"
    seals = next(c for c in r.details["criteria"] if c["name"] == "seals")
    assert seals["status"] == "fail" and "stand in oil" in seals["text"]


def test_cavity_that_does_not_reach_the_level_fails():
    assert _check(level_mm=50.0, cavity_depth_mm=42.5).status == "fail"


@pytest.mark.parametrize("kw, reason", [
    ({"lubrication": "grease"}, "grease lubrication"),
    ({"axis": "vertical"}, "vertical axis"),
    ({"level_mm": None}, "oil level for this model missing"),
    ({"cavity_depth_mm": None}, "oil cavity"),
])
def test_cases_that_cannot_be_decided_are_not_evaluated(kw, reason):
    r = _check(**kw)
    assert r.status == "not_evaluated" and reason in r.note


def test_level_port_beyond_a_is_turned_to_the_level():
    # a port opening at radius 27.5 stands A = 15 below the axis when turned acos(15/27.5)
    r = _check(plug_radius_mm=27.5)
    hole = next(c for c in r.details["criteria"] if c["name"] == "level hole")
    assert hole["status"] == "pass" and "56.9° from the bottom" in hole["text"]
    inside = _check(plug_radius_mm=10.0)
    assert inside.status == "fail" and "cannot show the level" in inside.note


def _segment_area(radius, depth):
    """Area of the part of a circle of ``radius`` lying more than ``depth`` below its centre."""
    if depth >= radius:
        return 0.0
    return radius ** 2 * math.acos(depth / radius) - depth * math.sqrt(radius ** 2 - depth ** 2)


@pytest.mark.parametrize("code", ["FD-20-80-2", "FD-25-80-2", "FD-65-78-2"])
def test_fd_cavity_volume_matches_the_circular_segment_formula(catalog, code):
    pytest.importorskip("cadquery")
    from hdcad.design_options import DesignOptions
    from hdcad.geometry.build import build_parts
    from hdcad.geometry.oil import fd_casing_cavity, volume_below_mL
    from hdcad.models import resolve
    model = resolve(code, catalog)
    size = model.size
    parts = build_parts(model, catalog, DesignOptions())
    cavity = fd_casing_cavity(parts)
    level = float(catalog.find("fd_oil_level", size=size)["A_mm"])
    # independent: the FD-2 φA g7 cylinder (table 312-1) over both pilot depths and the
    # running gap, plus each half's port window (Ø relief from the spline face to the
    # bearings), less the user's shaft φL (table 312-1)
    fd2 = catalog.find("fd2_dimensions", size=size)
    big_r, small_r = fd2["A_g7_mm"] / 2, fd2["L_H7_mm"] / 2
    half = parts[0].dimensions
    length = 2 * half["pilot_depth_mm"] + DesignOptions().running_gap_mm
    # the window: relief (or seat) Ø outside; the shaft up to the WG hub end, then the
    # sleeve collar inside; integrated piecewise between the breakpoints
    sleeve = next(p for p in parts if p.name == "sleeve_S").dimensions
    edges = sorted({half["pilot_depth_mm"], half["relief_end_mm"],
                    half["bearing_seat_z_mm"], sleeve["sleeve_start_mm"]})
    window = 0.0
    for a, b in zip(edges, edges[1:]):
        mid = (a + b) / 2
        outer = (half["relief_diameter_mm"] if mid < half["relief_end_mm"]
                 else half["bearing_seat_mm"]) / 2
        inner = small_r if mid < sleeve["sleeve_start_mm"] else sleeve["outer_diameter_mm"] / 2
        window += (_segment_area(outer, level) - _segment_area(inner, level)) * (b - a)
    expected = ((_segment_area(big_r, level) - _segment_area(small_r, level)) * length
                + 2 * window) / 1000
    # OCCT booleans on exact cylinders: agreement to 0.1 % (tessellation plays no part)
    assert volume_below_mL(cavity.solid, level) == pytest.approx(expected, rel=1e-3)
    assert cavity.depth_mm == big_r
    # the cavity is empty space: it overlaps no generated part
    for part in parts:
        assert cavity.solid.intersect(part.placed()).Volume() < 1e-3


def test_component_set_cavity_is_empty_space_and_holds_the_oil(catalog):
    pytest.importorskip("cadquery")
    from pathlib import Path
    from hdcad.catalog import load_catalog
    from hdcad.design_options import DesignOptions
    from hdcad.geometry.build import build_parts
    from hdcad.geometry.oil import component_set_cavity, volume_below_mL
    from hdcad.models import resolve
    # invented test overlay (tests/data/…TEST_DATA_NOT_CATALOG.yaml), not catalog data
    overlay = load_catalog(Path(__file__).parent / "data" /
                           "overlay_2a_gr_TEST_DATA_NOT_CATALOG.yaml")
    parts = build_parts(resolve("CSF-40-120-2A-GR", overlay), overlay, DesignOptions())
    cavity = component_set_cavity(parts)
    for part in parts:
        assert cavity.solid.intersect(part.placed()).Volume() < 1e-3, part.name
    level = overlay.find("component_housing", series="CSF", size=40)["oil_level_from_axis_mm"]
    below, total = volume_below_mL(cavity.solid, level), cavity.solid.Volume() / 1000
    # the surface lies below the axis: less than half of the cavity holds oil, but some does
    assert 0 < below < total / 2
    # the level is read against the seal lips of the larger shaft (output journal)
    housing = next(p for p in parts if p.name == "housing").dimensions
    assert cavity.seal_shaft_mm == pytest.approx(housing["seal_shaft_mm"])
    assert housing["seal_shaft_mm"] == parts[-1].dimensions["journal_diameter_mm"]


@pytest.mark.parametrize("bearing_od, says", [(55.0, "dip into the bath"),
                                              (20.0, "stay above the bath")])
def test_the_note_says_whether_the_support_bearings_reach_the_bath(bearing_od, says):
    # level 15 mm below the axis: a Ø55 outer ring reaches 27.5 mm down, a Ø20 one 10 mm
    assert says in _check(support_bearing_od_mm=bearing_od).note


def test_an_opening_below_the_level_fails_and_is_named():
    r = _check(openings=["a 1 mm gap all round"])
    sealed = next(c for c in r.details["criteria"] if c["name"] == "sealed")
    assert r.status == "fail" and sealed["status"] == "fail" and "1 mm gap" in sealed["text"]


def test_fd_running_gap_is_closed_by_the_spigot_o_ring(catalog):
    pytest.importorskip("cadquery")
    from hdcad.design_options import DesignOptions
    from hdcad.geometry.build import build_parts
    from hdcad.geometry.oil import fd_casing_cavity
    from hdcad.models import resolve
    options = DesignOptions(running_gap_mm=1.5)
    parts = build_parts(resolve("FD-25-80-2", catalog), catalog, options)
    assert fd_casing_cavity(parts).openings == []
    s_half = next(p for p in parts if p.name == "casing_half_S")
    ring = next(n for n in s_half.neighbours if n.kind == "oring")
    # the O-ring sits in the S half's bore groove, over the D half's spigot
    assert 0 < ring.z_mm < s_half.dimensions["gap_seal_length_mm"]


def test_no_margin_is_shown_when_a_non_numeric_criterion_fails():
    assert _check(openings=["gap"]).margin is None
    assert _check(level_mm=50.0).margin < 0
