"""The FD-0 drive flange's driving feature, as the user chooses it (design option drive)."""

from __future__ import annotations

import math

import numpy as np

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.design_options import parse_options  # noqa: E402
from hdcad.errors import InputError  # noqa: E402
from hdcad.geometry.flanges import FDDriveFlange  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402


def _flange(catalog, tmp_path, drive):
    part = FDDriveFlange(25, catalog, parse_options({"drive": drive})).build()
    export_step(part, tmp_path / "f.step")
    return part, cq.importers.importStep(str(tmp_path / "f.step")).val()


def test_key_seat_on_the_hub(catalog, tmp_path):
    # FD-25-0 table 311-1: hub Ø φB 65; JIS B 1301 for 58 < d ≤ 65: key 18 × 11, t1 = 7.0
    plain = FDDriveFlange(25, catalog).build().shape.val().Volume()
    part, solid = _flange(catalog, tmp_path, {"kind": "key"})
    row = next(r for r in catalog.rows("parallel_key_jisb1301")
               if r["shaft_min_mm"] < 65 <= r["shaft_max_mm"])
    b, t1 = row["b_mm"], row["t1_mm"]
    hub_len = part.dimensions["hub_length_mm"]
    # removed volume = hub length × area of the hub section beyond x = r − t1 within |y| ≤ b/2:
    # ∫ (√(r² − y²) − (r − t1)) dy over −b/2 … b/2
    r = 32.5
    chord = lambda y: y / 2 * math.sqrt(r * r - y * y) + r * r / 2 * math.asin(y / r)  # noqa
    area = chord(b / 2) - chord(-b / 2) - b * (r - t1)
    # less what the hub's 20° × 1 mm lead-in already took from the key seat: the band between
    # the cone (radius r − s·tan 20°, s ≤ 1 from where the chamfer starts) and r, |y| ≤ b/2
    def band(rho):
        c = lambda y: y / 2 * math.sqrt(rho * rho - y * y) + rho * rho / 2 * math.asin(y / rho)  # noqa
        return chord(b / 2) - chord(-b / 2) - (c(b / 2) - c(-b / 2))
    s = np.linspace(0.0, 1.0, 2001)
    v = np.array([band(r - x * math.tan(math.radians(20))) for x in s])
    overlap = float(np.sum((v[1:] + v[:-1]) / 2 * np.diff(s)))  # trapezoid rule
    assert plain - solid.Volume() == pytest.approx(area * hub_len - overlap, rel=1e-5)
    assert any("parallel key" in n and "JIS B 1301" in n for n in part.notes)


def test_tapped_holes_for_the_gear_in_the_hub_face(catalog, tmp_path):
    part, solid = _flange(catalog, tmp_path, {"kind": "bolts", "count": 6, "thread": "M5",
                                              "circle_mm": 48})
    gear = next(c for c in part.bolt_circles if c.name == "gear screws")
    assert (gear.count, gear.thread, gear.kind, gear.depth_mm) == (6, "M5", "tapped", 7.5)
    holes = [f for f in solid.Faces() if f.geomType() == "CYLINDER"
             and abs(f._geomAdaptor().Cylinder().Radius() - 2.1) < 1e-6]  # tap drill Ø4.2
    assert len(holes) == 6


@pytest.mark.parametrize("drive, field", [
    ({"kind": "bolts", "count": 4, "thread": "M5"}, "drive.circle_mm"),
    ({"kind": "rivets"}, "drive.kind"),
])
def test_bad_drive_options_name_the_field(drive, field):
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        parse_options({"drive": drive})


def test_a_circle_outside_the_hub_is_refused_with_the_range(catalog):
    with pytest.raises(ValueError, match=r"circle_mm 90 must lie in \["):
        FDDriveFlange(25, catalog, parse_options(
            {"drive": {"kind": "pins", "count": 2, "diameter_mm": 6, "circle_mm": 90}})).build()


def test_outer_edges_are_broken(catalog, monkeypatch):
    # 0.5 × 45° on both outer circular edges of the Ø95 FD-25-0 flange: two rings of
    # triangular section 0.5²/2 at the centroid radius R − 0.5/3 (Pappus)
    from hdcad.geometry import flanges
    from hdcad.geometry.primitives import EDGE_BREAK_MM
    broken = FDDriveFlange(25, catalog).build()
    monkeypatch.setattr(flanges, "break_outer_edges", lambda shape, *a, **k: shape)
    sharp = FDDriveFlange(25, catalog).build()
    c, r = EDGE_BREAK_MM, 95 / 2
    ring = 2 * (c * c / 2) * 2 * math.pi * (r - c / 3)
    removed = sharp.shape.val().Volume() - broken.shape.val().Volume()
    assert removed == pytest.approx(ring, rel=1e-6)
    # the two outer breaks, and the 20° lead-ins on the pilot boss and the hub
    assert sum(f.geomType() == "CONE" for f in broken.shape.val().Faces()) == 4
    assert any("ISO 13715" in n for n in broken.notes)
