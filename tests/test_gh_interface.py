"""The gear-head side of the GH motor flange: from the overlay table gh_input_interface, or
marked NOT FOR MANUFACTURE (the seeds give only the motor side; HOUSING_RULES §5 (1))."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.build import build_parts  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402
from hdcad.models import resolve  # noqa: E402

OVERLAY = Path(__file__).parent / "data" / "overlay_gh_interface_TEST_DATA_NOT_CATALOG.yaml"


def _cylinders(shape):
    """(radius, distance of the axis from Z) of every cylindrical face along Z [mm]."""
    from hdcad.geometry.drawing.measure import z_cylinders
    return [(round(c.diameter / 2, 3), round(math.hypot(c.x, c.y), 3)) for c in z_cylinders(shape)]


def test_without_the_interface_the_flange_is_not_for_manufacture(catalog):
    part = build_parts(resolve("CSF-45-120-GH", catalog), catalog, DesignOptions())[0]
    assert any("NOT FOR MANUFACTURE" in n for n in part.notes)
    assert [c.name for c in part.bolt_circles] == ["motor screws"]
    # seed 003 table 064-1 PA: motor pilot Ø70 H7; ISO 286: 50 < 70 ≤ 80 → IT7 = 30 µm
    (pilot,) = part.fits
    assert (pilot.nominal_mm, pilot.code, pilot.deviations_um) == (70, "H7", (30, 0))


def test_the_interface_gives_recess_screws_and_o_ring(tmp_path):
    catalog = load_catalog(OVERLAY)
    part = build_parts(resolve("CSF-45-120-GH", catalog), catalog, DesignOptions())[0]
    export_step(part, tmp_path / "flange.step")
    shape = cq.importers.importStep(str(tmp_path / "flange.step")).val()
    cylinders = _cylinders(shape)
    assert (50.0, 0.0) in cylinders  # Ø100 recess over the gear-head spigot
    holes = [c for c in cylinders if c == (4.5, 61.0)]  # 4 × Ø9 (ISO 273 medium M8) on Ø122
    assert len(holes) == 4
    assert (7.5, 61.0) in cylinders  # DIN 974-1 counterbore Ø15 for the M8 heads
    # face gland: inner Ø d1, width 3.7 for d2 2.62 (ISO 3601-2 gland table, catalog file)
    d1, width = 104.37, 3.7
    assert (round(d1 / 2, 3), 0.0) in cylinders and (round(d1 / 2 + width, 3), 0.0) in cylinders
    box = shape.BoundingBox()
    assert box.zlen == pytest.approx(part.dimensions["thickness_mm"], abs=1e-3)
    assert box.xlen == pytest.approx(146, abs=1e-3)  # the interface's outline
    gh = next(c for c in part.bolt_circles if c.name == "gear-head screws")
    assert gh.kind == "clearance" and gh.count == 4 and gh.grip_mm > 0
    fits = {f.feature: f for f in part.fits}
    # ISO 286: 80 < 100 ≤ 120 → IT7 = 35 µm
    assert fits["gear-head pilot"].deviations_um == (35, 0)
    assert not any("NOT FOR MANUFACTURE" in n for n in part.notes)


def test_the_drawing_states_tolerances_edges_material_mass_and_fits(tmp_path):
    from hdcad.geometry.drawing import part_drawing
    catalog = load_catalog(OVERLAY)
    part = build_parts(resolve("CSF-45-120-GH", catalog), catalog, DesignOptions())[0]
    export_step(part, tmp_path / "flange.step")
    part_drawing(tmp_path / "flange.step", part, tmp_path / "flange.svg", None, 2.25, "steel")
    svg = (tmp_path / "flange.svg").read_text(encoding="utf-8")
    # matplotlib writes each text as a comment before its glyphs
    for words in ("ISO 2768-mK", "ISO 13715", "material steel", "mass 2.25 kg",
                  "Ø70 H7 (+0.030/+0.000)", "Ø100 H7 (+0.035/+0.000)"):
        assert words in svg, words
