"""Bill of materials: ISO 4762 screw lengths, screws listed once per joint, lubricant rows."""

import pytest

from hdcad.report.bom import bill_of_materials, screw_length_mm


@pytest.mark.parametrize("thread, grip, depth, expected", [
    # M4, grip 10, thread depth 8: needs ≥ 10 + 4 = 14, must not pass 18 → ISO 4762 length 16
    ("M4", 10.0, 8.0, 16.0),
    # M6, grip 58.3, depth 12: 64.3 … 70.3 → 65
    ("M6", 58.3, 12.0, 65.0),
    # M5, grip 7.5, depth 8: 12.5 … 15.5 holds no preferred length (12 is short, 16 bottoms)
    ("M5", 7.5, 8.0, None),
])
def test_screw_length_is_the_shortest_preferred_length_that_engages_and_does_not_bottom(
        thread, grip, depth, expected):
    assert screw_length_mm(thread, grip, depth) == expected


def _circle(name, kind, **kw):
    base = {"name": name, "diameter_mm": 75.0, "count": 6, "hole_diameter_mm": 4.5,
            "thread": "M4", "kind": kind, "depth_mm": 8.0, "grip_mm": 10.0}
    base.update(kw)
    return base


def _bolt_check(part, name, torque):
    return {"id": "bolt_pattern", "details": {"name": f"{part}/{name}"},
            "inputs": {"M_A": {"value": torque}}}


def test_bom_lists_each_joint_once_with_length_and_tightening_torque():
    parts = [{"name": "cover", "bolt_circles": [_circle("cs", "clearance")],
              "purchased": [{"item": "bearing", "designation": "6002", "quantity": 1}]},
             {"name": "housing", "bolt_circles": [_circle("cs", "tapped", in_bom=False)]}]
    checks = [_bolt_check("cover", "cs", 5.24)]
    rows = bill_of_materials(parts, checks, "2A-GR", "grease", "SK-1A", "12.9", grease_g=40)
    screws = [r for r in rows if r.item == "screws"]
    assert len(screws) == 1  # the housing's tapped holes take the cover's screws
    assert screws[0].designation == "ISO 4762 M4×16 – 12.9" and screws[0].quantity == "6"
    assert "M_A = 5.2 N·m" in screws[0].note
    assert any(r.item == "bearing" and r.part == "cover" for r in rows)
    assert any(r.item == "o-ring / gasket" for r in rows)
    grease = next(r for r in rows if r.item == "lubricant")
    assert grease.quantity == "40 g" and "SK-1A" in grease.designation


def test_oil_amount_comes_from_the_oil_level_check():
    oil = {"id": "oil_level", "value": 15.0, "details": {"oil_volume_mL": 46.2},
           "inputs": {"A": {"value": 15.0, "unit": "mm"}}}
    rows = bill_of_materials([], [oil], "FD-2", "oil", "SK-1A", "12.9")
    lubricant = next(r for r in rows if r.item == "lubricant")
    assert lubricant.designation == "oil ISO VG68" and lubricant.quantity == "≤ 46 mL"
    assert "A = 15 mm" in lubricant.note


def test_gear_heads_are_factory_filled():
    rows = bill_of_materials([], [], "GH", "grease", "SK-1A", "12.9")
    assert [r.designation for r in rows] == ["grease (factory fill)"]


def test_a_grip_without_a_preferred_length_says_how_deep_to_counterbore():
    # M4, grip 26.8, depth 8: 30.8 … 34.8 holds no preferred length; 30 needs 0.8 mm more sink
    parts = [{"name": "casing", "bolt_circles": [_circle("spline", "clearance", grip_mm=26.8)]}]
    row = bill_of_materials(parts, [], "FD-2", "oil", "SK-1A", "12.9")[0]
    assert row.designation == "ISO 4762 M4×? – 12.9"
    assert "deepen the counterbores by 0.8 mm for M4×30" in row.note


def test_every_fd_casing_takes_a_preferred_length_spline_screw(catalog):
    pytest.importorskip("cadquery")
    from hdcad.geometry.fd_casing import FDCasingHalf
    from hdcad.geometry.standards import ISO_4762_HEAD_MM
    for size in FDCasingHalf.sizes(catalog):
        part = FDCasingHalf(size, catalog, side="S").build()
        circle = next(b for b in part.bolt_circles if b.name == "spline_screws")
        assert screw_length_mm(circle.thread, circle.grip_mm, circle.depth_mm), size
        # the head still sinks fully below the face the user's gear sits on
        sink = part.dimensions["counterbore_depth_mm"]
        assert sink >= ISO_4762_HEAD_MM[circle.thread][1], size


def test_tapped_holes_name_the_screw_with_its_length_rule():
    # the mating part's flange (a motor's) is not generated: its thickness is the unknown grip
    parts = [{"name": "motor_flange", "bolt_circles": [_circle("motor screws", "tapped")]}]
    row = bill_of_materials(parts, [], "GH", "grease", "SK-1A", "12.9")[0]
    assert row.designation == "ISO 4762 M4×L – 12.9"
    assert "L = grip of the mating part" in row.note and "preferred length" in row.note
