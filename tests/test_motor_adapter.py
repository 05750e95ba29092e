"""GH motor adapter plate: the flange code a motor fits directly, else the nearest code and a
plate between its motor side (seed 003 tables 053-1 … 064-1) and the motor; STEP measured."""

import math

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.checks.motor import motor_shaft_reach  # noqa: E402
from hdcad.design_options import parse_options  # noqa: E402
from hdcad.errors import InputError  # noqa: E402
from hdcad.geometry import review  # noqa: E402
from hdcad.geometry.build import build_parts, motor_choice  # noqa: E402
from hdcad.geometry.drawing.measure import axial_features, z_cylinders  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402
from hdcad.models import resolve  # noqa: E402

CATALOG = load_catalog()
MODEL = resolve("CSF-45-120-GH", CATALOG)
# CSF-45 code PD in table 064-1: A Ø80 H7, C Ø100, M6 × 14, F 14-24
PD_MOTOR = {"pilot_diameter_mm": 80, "pilot_length_mm": 3, "bolt_circle_mm": 100,
            "bolt_count": 4, "bolt_thread": "M6", "shaft_diameter_mm": 19,
            "shaft_length_mm": 40, "square_mm": 90}
# a motor no code takes directly: pilot 73, 4 × M5 on Ø98.4, Ø14 × 30 shaft
ODD_MOTOR = {"pilot_diameter_mm": 73.0, "pilot_length_mm": 1.6, "bolt_circle_mm": 98.4,
             "bolt_count": 4, "bolt_thread": "M5", "shaft_diameter_mm": 14,
             "shaft_length_mm": 30, "square_mm": 86}
TOL = 0.01


def _options(motor, **kw):
    return parse_options({"motor": motor, **kw})


def test_a_motor_that_matches_a_code_needs_no_adapter():
    row, mismatch = motor_choice(MODEL, CATALOG, _options(PD_MOTOR))
    assert row["flange_code"] == "PD" and mismatch == []
    (part,) = build_parts(MODEL, CATALOG, _options(PD_MOTOR))
    assert part.name == "motor_flange" and part.dimensions["pilot_diameter_mm"] == 80


@pytest.fixture(scope="module")
def plate(tmp_path_factory):
    (part,) = build_parts(MODEL, CATALOG, _options(ODD_MOTOR))
    path = tmp_path_factory.mktemp("adapter") / "motor_adapter.step"
    export_step(part, path)
    return part, cq.importers.importStep(str(path)).val()


def test_nearest_code_is_chosen_and_named(plate):
    row, mismatch = motor_choice(MODEL, CATALOG, _options(ODD_MOTOR))
    # PC (M8 × 20) and PD (M6 × 14) both have A Ø80, C Ø100, F 14-24: the nearest pilot
    # and circle; PD's thread is nearer the motor's M5
    assert row["flange_code"] == "PD" and len(mismatch) == 3
    assert any("pilot Ø73 ≠ A Ø80" in m for m in mismatch)


def test_plate_measured_from_step(plate):
    part, shape = plate
    assert shape.isValid() and len(shape.Solids()) == 1
    dims, box = part.dimensions, shape.BoundingBox()
    assert box.zmin == pytest.approx(-dims["spigot_length_mm"], abs=TOL)
    assert box.zmax == pytest.approx(dims["thickness_mm"], abs=TOL)
    assert dims["spigot_length_mm"] <= 8 - 0.5  # table 064-1 PD: B = 8
    feats = {round(c.diameter, 3): c for c in axial_features(z_cylinders(shape))}
    spigot, recess = feats[80.0], feats[73.0]
    assert spigot.z1 == pytest.approx(0.0, abs=TOL)                      # spigot into A
    # motor pilot + 0.5, of which the mouth's 20° lead-in takes a third (0.7 mm)
    assert recess.z1 - recess.z0 == pytest.approx((1.6 + 0.5) * 2 / 3, abs=TOL)
    assert 16.0 in feats                                                # shaft bore Ø14 + 2
    holes = [c for c in z_cylinders(shape) if not c.on_axis]
    flange = {(round(c.x, 2), round(c.y, 2)) for c in holes if abs(c.diameter - 6.6) < TOL}
    motor = {(round(c.x, 2), round(c.y, 2)) for c in holes if abs(c.diameter - 4.2) < TOL}
    assert len(flange) == 4 and len(motor) == 4   # ISO 273 M6 medium 6.6; M5 tap drill 4.2
    assert all(math.hypot(x, y) == pytest.approx(50.0, abs=TOL) for x, y in flange)
    assert all(math.hypot(x, y) == pytest.approx(49.2, abs=TOL) for x, y in motor)
    # every hole ≥ 1.5·d from the square's edge (HOUSING_RULES §4)
    half = dims["square_mm"] / 2
    assert all(half - max(abs(x), abs(y)) >= 1.5 * 5 - 1e-6 for x, y in motor)
    assert all(half - max(abs(x), abs(y)) >= 1.5 * 6 - 1e-6 for x, y in flange)
    assert {f.code for f in part.fits} == {"g6", "H7"}


def test_faces_carry_a_static_o_ring_groove_where_it_fits(plate):
    """Seed 000 p.028: O-ring or sealant on flange faces. ISO 3601-2 face gland for d2 1.78:
    width 2.5, depth 1.33 (catalog oring_gland_iso3601), the 2 mm ligament of HOUSING_RULES
    §4 to the pilot and the hole ligament (≥ 0.5·d, ≥ 2 mm) outside. Motor face: recess Ø73
    widened by its 0.7 mm 20° lead-in to Ø73.51, + 4 = Ø77.6 (rounded up to 0.1) to Ø82.6;
    the M6 counterbores Ø11 on Ø100 leave to 100 − 11 − 6 = Ø83: a groove. Gear-head face:
    spigot Ø80 + 4 = Ø84 to Ø89, but the M6 holes Ø6.6 on Ø100 leave only to
    100 − 6.6 − 6 = Ø87.4: no groove, liquid gasket in the notes."""
    part, shape = plate
    t = part.dimensions["thickness_mm"]
    faces = {}
    for c in axial_features(z_cylinders(shape)):
        faces.setdefault(round(c.diameter, 3), []).append((round(c.z0, 3), round(c.z1, 3)))
    assert (round(t - 1.33, 3), t) in faces[77.6] and (round(t - 1.33, 3), t) in faces[82.6]
    assert 89.0 not in faces
    assert any(n.startswith("gear-head face: no room") for n in part.notes)
    orings = [n for n in part.neighbours if n.kind == "oring"]
    assert len(orings) == 1
    assert sum(p["item"] == "O-ring" for p in part.purchased) == 1


def test_review_assembly_has_no_overlap_and_screws_engage(plate):
    part, _ = plate
    bodies = review.review_bodies([part])
    assert review.interferences(bodies) == []
    screws = review.screw_engagements(bodies)
    assert len(screws) == 4
    for s in screws:  # M6: ≥ 1·d, within the flange's 14 mm thread (table 064-1 PD)
        assert 6.0 <= s["engaged"] <= 14.0


def test_shaft_reach_needs_the_coupling_engagement(tmp_path):
    row = dict(CATALOG.find("gh_motor_flange", series="CSF-GH", size=45, flange_code="PD"))
    assert motor_shaft_reach(row, ODD_MOTOR, 14.0).status == "not_evaluated"
    row["shaft_engagement_mm"] = 20.0
    check = motor_shaft_reach(row, ODD_MOTOR, 14.0)   # 30 − 14 = 16 < 20
    assert check.status == "fail" and check.value == 16.0
    # the column is open to an overlay (delivery-drawing value; invented here for the test)
    from hdcad.catalog import load_catalog
    overlay = tmp_path / "engagement.yaml"
    overlay.write_text("source: test value, not catalog data\ntables:\n  gh_motor_flange:\n"
                       "    - {series: CSF-GH, size: 45, table: 064-1, flange_type: I, "
                       "flange_code: PD, pilot_H7_mm: 80, pilot_depth_mm: 8, "
                       "bolt_circle_mm: 100, thread: M6, thread_depth_mm: 14, "
                       "coupling_bore_min_mm: 14, coupling_bore_max_mm: 24, "
                       "shaft_engagement_mm: 12}\n", encoding="utf-8")
    cat = load_catalog(overlay)
    assert cat.find("gh_motor_flange", series="CSF-GH", size=45,
                    flange_code="PD")["shaft_engagement_mm"] == 12.0


def test_no_code_takes_the_shaft_is_bad_input():
    with pytest.raises(InputError, match="coupling bores"):
        build_parts(MODEL, CATALOG, _options(dict(ODD_MOTOR, shaft_diameter_mm=40)))


def test_motor_block_is_validated():
    with pytest.raises(InputError, match="motor.pilot_diameter_mm"):
        _options({k: v for k, v in ODD_MOTOR.items() if k != "pilot_diameter_mm"})
    with pytest.raises(InputError, match="motor.bolt_thread"):
        _options(dict(ODD_MOTOR, bolt_thread="M7"))
