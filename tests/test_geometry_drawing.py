"""Part drawings (hdcad.geometry.drawing): export each part to STEP, draw it from the file and
check the drawing against the catalog, the standards and the STEP solid measured here.

Expected numbers come from the catalog tables (seed 001 table 311-1 fd0_dimensions, table
312-1 fd2_dimensions; seed 003 table 064-1 gh_motor_flange) and from the ISO tables the parts
are built with (hdcad.geometry.standards: ISO 273 medium clearance holes, ISO 2306 tap drills),
never from the drawing module. Timings are printed, not asserted (benchmark material).
"""

import dataclasses
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

cq = pytest.importorskip("cadquery")
from PIL import Image  # noqa: E402  (pillow comes with matplotlib)

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.build import build_parts  # noqa: E402
from hdcad.geometry.drawing import clip_half, part_drawing  # noqa: E402
from hdcad.geometry.flanges import MOTOR_HOLE_COUNT  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402
from hdcad.geometry.standards import ISO_273_MEDIUM_MM, TAP_DRILL_MM  # noqa: E402
from hdcad.models import resolve  # noqa: E402

CATALOG = load_catalog()
TOL = 0.01  # mm: the drawing's promise (a dimension may differ from the solid by at most this)
SHEET = (250.0, 150.0)  # mm, the sheet size the task asks for
CASES = [("FD-25-80-2", None), ("FD-25-80-0", None), ("CSF-45-120-GH", "PA"),
         ("CSF-45-120-GH", "PG")]  # PA: round flange; PG: square flange in table 064-1
# "6× M5×8 (drill Ø4.2) on Ø80" (tapped) or "6× Ø4.5 for M4 on Ø75" (clearance)
LABEL = re.compile(r"^(\d+)× (?:(M\d+)×[\d.]+ \(drill Ø([\d.]+)\)|Ø([\d.]+) for (M\d+)) "
                   r"on Ø([\d.]+)$")
TIMES: list[tuple[str, float]] = []


def _parts(code, flange):
    return build_parts(resolve(code, CATALOG), CATALOG, DesignOptions(motor_flange=flange))


DRAWN_IDS = [f"{c}-{p.name}" + (f"-{f}" if f else "") for c, f in CASES for p in _parts(c, f)]


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    """Every part of CASES drawn once: (code, flange, part, step path, result)."""
    out = []
    for code, flange in CASES:
        for part in _parts(code, flange):
            folder = tmp_path_factory.mktemp(f"{code}-{part.name}")
            step = folder / f"{part.name}.step"
            export_step(part, step)
            result = part_drawing(step, part, folder / f"{part.name}.svg",
                                  folder / f"{part.name}.png")
            TIMES.append((f"{code} {flange or ''} {part.name}", result["time_s"]))
            out.append((code, flange, part, step, result))
    return out


def _svg_strings(path) -> list[str]:
    """The SVG parsed as XML; text is drawn as glyphs, each string kept in a comment."""
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    root = ET.parse(path, parser).getroot()
    assert root.tag.endswith("svg")
    return [el.text.strip() for el in root.iter() if el.tag is ET.Comment]


def _expected(code, flange, part):
    """(outer label, diameter labels, bolt-circle tuples (count, hole Ø, circle Ø, thread))
    from the catalog and the ISO tables."""
    if code.startswith("FD"):
        fd0 = CATALOG.find("fd0_dimensions", size=25)  # table 311-1
        gear = (fd0["L_count"], TAP_DRILL_MM[fd0["M_thread"]], fd0["K_mm"], fd0["M_thread"])
        if part.name.startswith("sleeve"):
            # journal sleeve: collar ≥ d_a,min of 6006 (DIN 5418: 30 + 2 × 2.5), journal =
            # bearing bore d (ISO 15), bore = WG hub bore φL (table 312-1)
            fd2 = CATALOG.find("fd2_dimensions", size=25)
            return "Ø35", ["Ø30", f"Ø{fd2['L_H7_mm']:g}"], []
        if part.name.startswith("casing"):
            fd2 = CATALOG.find("fd2_dimensions", size=25)  # table 312-1
            spline = (fd2["J_count"], ISO_273_MEDIUM_MM[fd2["K_thread"]], fd2["I_mm"],
                      fd2["K_thread"])
            # the body behind the running-gap seal is FD-0 φA; the front ring's Ø is a
            # design value (seal journal + walls), so no catalog outer extent to compare.
            # The gear recess: FD-0 φB 65 would leave 75/2 − 8/2 − 65/2 = 1 mm to the DIN
            # 974-1 Ø8 counterbores of the M4 spline screws on φI 75; a 3 mm wall plus the
            # recess's 0.5 mm lead-in gives 75 − 8 − 2 × 3.5 = 60
            return (None, [f"Ø{fd0['A_mm']:g}", f"Ø{fd2['A_g7_mm']:g}", "Ø60"],
                    [spline, gear])
        clearance = (fd0["L_count"], ISO_273_MEDIUM_MM[fd0["M_thread"]], fd0["K_mm"],
                     fd0["M_thread"])
        return f"Ø{fd0['A_mm']:g}", [f"Ø{fd0['B_H7_mm']:g}"], [clearance]
    row = CATALOG.find("gh_motor_flange", series="CSF-GH", size=45, flange_code=flange)
    outer = f"□{row['square_mm']:g}" if row["square_mm"] else None  # round Ø is a design value
    motor = (MOTOR_HOLE_COUNT, TAP_DRILL_MM[row["thread"]], row["bolt_circle_mm"], row["thread"])
    return outer, [f"Ø{row['pilot_H7_mm']:g}"], [motor]


@pytest.mark.parametrize("index", range(len(DRAWN_IDS)), ids=DRAWN_IDS)
def test_svg_has_catalog_dimensions_and_bolt_labels(drawn, index):
    code, flange, part, _, result = drawn[index]
    strings = _svg_strings(result["svg"])
    outer, diameters, circles = _expected(code, flange, part)
    for label in ([outer] if outer else []) + diameters:
        # a diameter with an ISO 286 fit carries its class after the size (Ø85 H7)
        assert any(s == label or s.startswith(label + " ") for s in strings), label
    found = sorted((m[1], float(m[3] or m[4]), float(m[6]), m[2] or m[5])
                   for m in map(LABEL.match, strings) if m)
    want = sorted((str(n), float(h), float(bc), t) for n, h, bc, t in circles)
    assert found == want


@pytest.mark.parametrize("index", range(len(DRAWN_IDS)), ids=DRAWN_IDS)
def test_section_extent_matches_step_and_catalog(drawn, index):
    code, flange, part, step, result = drawn[index]
    box = cq.importers.importStep(str(step)).val().BoundingBox()  # measured here, not there
    ext = result["section_extent_mm"]
    assert ext["x"][1] - ext["x"][0] == pytest.approx(box.xlen, abs=TOL)
    assert ext["z"] == pytest.approx([box.zmin, box.zmax], abs=TOL)
    outer, _, _ = _expected(code, flange, part)
    if outer:  # catalog: 311-1 φA for the FD parts, 064-1 square for flange PG
        assert ext["x"][1] - ext["x"][0] == pytest.approx(float(outer[1:]), abs=TOL)


@pytest.mark.parametrize("index", range(len(DRAWN_IDS)), ids=DRAWN_IDS)
def test_png_size_and_layout(drawn, index):
    *_, result = drawn[index]
    with Image.open(result["png"]) as png:
        width, height = png.size
    # readable raster (>= 120 dpi on the 250 mm sheet) with the sheet's aspect ratio
    assert width >= 250 / 25.4 * 120
    assert width / height == pytest.approx(SHEET[0] / SHEET[1], rel=0.01)
    boxes, views = result["text_boxes_mm"], [v["box_mm"] for v in result["views"]]
    for a, b in [(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:]] + \
            [(t, v) for t in boxes for v in views] + [tuple(views)]:
        assert not _overlap(a, b), (a, b)
    for x0, y0, x1, y1 in boxes + views:
        assert 0 < x0 < x1 < SHEET[0] and 0 < y0 < y1 < SHEET[1]


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _one_part(code, flange=None, name=None):
    parts = _parts(code, flange)
    return next(p for p in parts if name is None or p.name == name)


@pytest.mark.parametrize("key, delta", [("outer_diameter_mm", 0.5), ("seal_recess_mm", -0.02),
                                        ("pilot_recess_mm", 1.0), ("thickness_mm", 0.1),
                                        ("bearing_seat_z_mm", 0.5)])
def test_wrong_dimension_raises(tmp_path, key, delta):
    part = _one_part("FD-25-80-2", name="casing_half_S")
    step = tmp_path / "part.step"
    export_step(part, step)
    wrong = dataclasses.replace(part, dimensions={**part.dimensions,
                                                  key: part.dimensions[key] + delta})
    with pytest.raises(ValueError, match=key):
        part_drawing(step, wrong, tmp_path / "part.svg")


def test_within_tolerance_draws(tmp_path):
    """Half the tolerance off is accepted: the check is not tighter than stated."""
    part = _one_part("FD-25-80-0", name="drive_flange_S")
    step = tmp_path / "part.step"
    export_step(part, step)
    near = dataclasses.replace(part, dimensions={**part.dimensions, "bore_mm":
                                                 part.dimensions["bore_mm"] + TOL / 2})
    result = part_drawing(step, near, tmp_path / "part.svg")
    assert result["png"] is None and (tmp_path / "part.svg").stat().st_size > 0


@pytest.mark.parametrize("field, delta", [("count", 1), ("diameter_mm", 1.0),
                                          ("hole_diameter_mm", 0.1)])
def test_wrong_bolt_circle_raises(tmp_path, field, delta):
    part = _one_part("FD-25-80-0", name="drive_flange_S")
    step = tmp_path / "part.step"
    export_step(part, step)
    bc = part.bolt_circles[0]
    wrong = dataclasses.replace(part, bolt_circles=[
        dataclasses.replace(bc, **{field: getattr(bc, field) + delta})])
    with pytest.raises(ValueError, match="bolt circle"):
        part_drawing(step, wrong, tmp_path / "part.svg")


def test_draws_the_step_file_not_the_shape(tmp_path):
    """A STEP file of another part (drive flange, 18 mm long) under the casing's record
    (45.3 mm thick) must not be drawn with the casing's numbers."""
    casing = _one_part("FD-25-80-2", name="casing_half_S")
    step = tmp_path / "other.step"
    export_step(_one_part("FD-25-80-0", name="drive_flange_S"), step)
    with pytest.raises(ValueError):
        part_drawing(step, casing, tmp_path / "part.svg")


def test_print_timings(drawn, capsys):
    with capsys.disabled():
        print("\npart drawing times (STEP import, measure, draw, SVG + PNG):")
        for name, seconds in TIMES:
            print(f"  {name:42s} {seconds:6.3f} s")
    assert len(TIMES) == len(DRAWN_IDS)


def test_clip_half_cuts_at_the_axis():
    """A zig-zag crossing y = 0 three times: the upper pieces hold exactly the y ≥ 0 length
    (√2 per unit step in x: the triangles are 45°)."""
    zigzag = np.array([[0.0, 1.0], [2.0, -1.0], [4.0, 1.0], [6.0, -1.0]])
    upper = clip_half(zigzag, upper=True)
    lower = clip_half(zigzag, upper=False)
    length = sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in upper)
    assert len(upper) == 2 and len(lower) == 2
    assert all((p[:, 1] >= 0).all() for p in upper) and all((p[:, 1] <= 0).all() for p in lower)
    assert length == pytest.approx(3 * 2 ** 0.5)


def test_axial_positions_are_dimensioned_from_the_mating_face(drawn):
    """The casing's functional faces along the axis (pilot floor, bearing seat, shoulder,
    seal, front ring) are drawn as parallel dimensions from z = 0, each checked against a
    face of the STEP solid."""
    code, _, part, _, result = next(d for d in drawn if d[2].name == "casing_half_D")
    strings = _svg_strings(result["svg"])
    for key in ("pilot_floor_z_mm", "bearing_seat_z_mm", "shoulder_z_mm", "seal_z_mm"):
        assert f"{part.dimensions[key]:g}" in strings, key


def test_fits_and_tolerance_frames_are_on_the_drawing(drawn):
    """The bearing seat reads Ø55 M7 (ISO 286 class after the size, ISO 129-1); the title
    block's first row holds the datums and ISO 1101 frames: ◎ Ø0.02 A for the seat."""
    _, _, part, _, result = next(d for d in drawn if d[2].name == "casing_half_D")
    strings = _svg_strings(result["svg"])
    seat = next(f for f in part.fits if f.code == "M7")
    assert f"Ø{seat.nominal_mm:g} M7" in strings
    assert {"A", "B", "◎", "Ø0.02"} <= set(strings)
    assert "bearing seat" in strings


def test_sections_named_and_axial_positions_as_running_dimensions(drawn):
    """ISO 128-44: the half section carries its name (A–A) and its cutting plane is marked on
    the front view; ISO 129-1: the axial positions from the mating face share one or two
    running dimension lines, so a casing half of FD-25 (eight positions) keeps scale 1:2."""
    from hdcad.geometry.drawing.conventions import AXIAL_KEYS
    for code, _, part, _, result in drawn:
        assert result["views"][1]["section"] == "A–A"
        drawn_keys = {d["key"] for d in result["dimensions"]}
        assert {k for k in AXIAL_KEYS if k in part.dimensions
                and 0 < part.dimensions[k] < part.dimensions["thickness_mm"] - TOL} <= drawn_keys
        if part.name.startswith("casing_half"):
            assert result["scale"] == 0.5, (part.name, result["scale"])


def test_every_tolerance_symbol_is_a_glyph_of_the_drawing_font():
    """An ISO 1101 symbol the font lacks prints as an empty box on the drawing."""
    from matplotlib.font_manager import FontProperties, findfont
    from matplotlib.ft2font import FT2Font
    from hdcad.geometry.drawing.gdt import SYMBOLS
    charmap = FT2Font(findfont(FontProperties())).get_charmap()
    assert [s for s in SYMBOLS.values() if ord(s) not in charmap] == []
