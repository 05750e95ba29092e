"""Calculation-sheet plots: valid SVG of the column size, promised labels, WeasyPrint renders them.

Text is written as glyph paths; matplotlib puts the string of each text in an XML comment just
before its glyph group ``<g transform="translate(x y) scale(s -s)">`` with s = font size / 100,
so the tests read labels and font sizes from the SVG itself.
"""

from __future__ import annotations

import dataclasses
import html
import math
import re
import xml.etree.ElementTree as ET

import pytest

pytest.importorskip("matplotlib")

from hdcad.checks.life import wg_life  # noqa: E402
from hdcad.checks.run import run_checks, stiffness_curve  # noqa: E402
from hdcad.duty import load_duty  # noqa: E402
from hdcad.errors import InputError  # noqa: E402
from hdcad.models import resolve  # noqa: E402
from hdcad.report import plots  # noqa: E402
from hdcad.resources import examples_dir  # noqa: E402

SVG = "{http://www.w3.org/2000/svg}"
PT_PER_MM = 72 / 25.4
MODEL = "CSF-45-120-GH"
# seed 003 table 052-1 (CSF-GH size 45, ratio ≥ 80): T2 = 275 N·m, θ2 = 11.1e-4 rad,
# K3 = 33e4 N·m/rad; seed 000 p.020: θ = θ2 + (T − T2)/K3 above T2
T2_NM, THETA2_RAD, K3_NM_PER_RAD = 275.0, 0.00111, 330000.0


@pytest.fixture(scope="module")
def evaluation(catalog):
    model = resolve(MODEL, catalog)
    return run_checks(model, load_duty(examples_dir() / "duty_seed_example.yaml"), catalog)


@pytest.fixture(scope="module")
def svgs(evaluation, catalog, tmp_path_factory):
    """The four plots of the CSF-45-120-GH example, written once for the module."""
    out = tmp_path_factory.mktemp("plots")
    model, duty = evaluation.model, evaluation.duty
    curve, _ = stiffness_curve(model)
    points = {"Tav": evaluation.derived["avg_torque_Nm"], "peak": 400.0,
              "shock": duty.shock.torque_Nm}
    return {
        "duty": plots.duty_cycle_plot(duty, out / "duty.svg"),
        "twist": plots.torque_twist_plot(curve, points, out / "twist.svg",
                                         float(model.get("momentary_torque_Nm"))),
        "life": plots.life_plot(evaluation.check("wg_life"), duty.required_life_h,
                                out / "life.svg"),
        "bolts": _motor_flange_plot(evaluation, catalog, out / "bolts.svg"),
    }


def _motor_flange_plot(evaluation, catalog, path):
    """Bolt pattern of the real GH motor flange, circles as results.json carries them."""
    pytest.importorskip("cadquery")
    from hdcad.design_options import DesignOptions
    from hdcad.geometry.build import build_parts
    from hdcad.geometry.flanges import MOTOR_HOLE_START_DEG
    part = build_parts(evaluation.model, catalog, DesignOptions())[0]
    circles = [dict(dataclasses.asdict(b), start_angle_deg=MOTOR_HOLE_START_DEG)
               for b in part.bolt_circles]
    return plots.bolt_pattern_plot(circles, path, "motor flange",
                                   part.dimensions.get("outer_diameter_mm"),
                                   part.dimensions["bore_mm"])


def _parse(path):
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    return ET.parse(path, parser).getroot()


def _texts(root) -> list[tuple[str, float]]:
    """(text, font size [pt]) of every text drawn as glyph paths."""
    out = []
    for parent in root.iter():
        children = list(parent)
        for comment, group in zip(children, children[1:]):
            if comment.tag is ET.Comment and group.tag == f"{SVG}g":
                scale = re.search(r"scale\(([\d.]+)", group.get("transform", ""))
                if scale:
                    # matplotlib escapes the comment text (< → &lt;)
                    out.append((html.unescape(comment.text.strip()),
                                float(scale.group(1)) * 100))
    return out


def _all_text(path) -> str:
    return "\n".join(text for text, _ in _texts(_parse(path)))


@pytest.mark.parametrize("kind", ["duty", "twist", "life", "bolts"])
def test_svg_is_column_sized_with_text_as_paths_of_8pt_or_more(svgs, kind):
    root = _parse(svgs[kind])
    assert root.tag == f"{SVG}svg"
    _, _, width, height = (float(v) for v in root.get("viewBox").split())
    # the brief: an A4 portrait column, 170 mm wide and 80-95 mm high (viewBox unit = 1 pt)
    assert width == pytest.approx(170 * PT_PER_MM, abs=0.01)
    assert 80 * PT_PER_MM - 0.01 <= height <= 95 * PT_PER_MM + 0.01
    assert root.find(f".//{SVG}text") is None  # glyph paths: WeasyPrint needs no font
    texts = _texts(root)
    assert len(texts) > 10  # tick labels at least; a parse that finds none would pass below
    small = [(t, s) for t, s in texts if s < 8.0 - 1e-6]
    assert not small, f"text below 8 pt: {small}"


def test_duty_plot_labels(svgs, evaluation):
    text = _all_text(svgs["duty"])
    for label in ("time t [s]", "output torque T [N·m]", "output speed n [r/min]",
                  "start", "steady", "stop", "rest"):
        assert label in text
    # Tav of the seed example: 319.7 N·m (reference_examples.yaml: seed rounds it to 319)
    tav = float(re.search(r"Tav = ([\d.,]+) N·m", text).group(1).replace(",", ""))
    assert tav == pytest.approx(319.7, abs=0.05)
    assert "shock Ts = 500 N·m" in text  # duty_seed_example.yaml shock torque


def test_twist_plot_labels_and_twist_at_peak_torque(svgs):
    text = _all_text(svgs["twist"])
    for label in ("output torque T [N·m]", "twist θ [arcmin]", "twist θ [mrad]",
                  "T1 = 76, T2 = 275 N·m", "limit ±1,760 N·m"):
        assert label in text
    shown = float(re.search(r"peak: 400 N·m → ([\d.]+) arcmin", text).group(1))
    expected = (THETA2_RAD + (400.0 - T2_NM) / K3_NM_PER_RAD) * 180 / math.pi * 60
    assert shown == pytest.approx(expected, abs=0.005 + 1e-9)  # label has 2 decimals


def test_twist_plot_without_curve_writes_nothing(tmp_path):
    path = tmp_path / "twist.svg"
    assert plots.torque_twist_plot(None, {"Tav": 300.0}, path) is None
    assert not path.exists()


def test_life_plot_labels(svgs, evaluation):
    text = _all_text(svgs["life"])
    for label in ("average output torque Tav [N·m]", "wave-generator life L10 [h]",
                  "required 7,000 h", "pass: L10 ≥ required", "fail: L10 < required"):
        assert label in text
    # the operating point shows the check's own L10 (seed 003 p.049 prints 19,457 h from
    # rounded intermediates; the check's full-precision value is within 1.5 % of it)
    shown = float(re.search(r"L10 = ([\d,]+) h", text).group(1).replace(",", ""))
    assert shown == pytest.approx(evaluation.check("wg_life").value, abs=0.5)
    assert shown == pytest.approx(19457, rel=0.015)


def test_life_plot_not_evaluated_writes_nothing(tmp_path):
    record = wg_life(320.0, 1440.0, 7000.0, None, None, None, None)  # no catalog ratings
    path = tmp_path / "life.svg"
    assert record.status == "not_evaluated"
    assert plots.life_plot(record, 7000.0, path) is None
    assert not path.exists()


def _hole_markers(path) -> list[str]:
    return [g.get("id") for g in _parse(path).iter(f"{SVG}g")
            if (g.get("id") or "").startswith("hole_")]


def test_bolt_pattern_one_marker_per_hole_gh_flange(svgs):
    # GH motor flange of CSF-45 (table gh_motor_flange): 4 × M5 on Ø90
    assert len(_hole_markers(svgs["bolts"])) == 4
    text = _all_text(svgs["bolts"])
    assert "4 × M5 on Ø90" in text
    assert "x [mm]" in text and "y [mm]" in text


def test_bolt_pattern_two_circles_of_fd_casing(catalog, tmp_path):
    pytest.importorskip("cadquery")
    from hdcad.geometry.fd_casing import FDCasingHalf
    part = FDCasingHalf(50, catalog).build()
    circles = [dataclasses.asdict(b) for b in part.bolt_circles]
    path = plots.bolt_pattern_plot(circles, tmp_path / "casing.svg", "casing half",
                                   part.dimensions["outer_diameter_mm"],
                                   part.dimensions["seal_recess_mm"])
    assert len(_hole_markers(path)) == sum(c["count"] for c in circles)
    text = _all_text(path)
    for c in circles:
        assert f"{c['count']} × {c['thread']} on Ø{c['diameter_mm']:g}" in text
    assert f"outer Ø{part.dimensions['outer_diameter_mm']:g}" in text


def test_hole_centres_lie_on_the_circle_evenly_spaced():
    centres = plots.hole_centres(90.0, 4, 45.0)
    assert [math.hypot(x, y) for x, y in centres] == pytest.approx([45.0] * 4)
    angles = [math.degrees(math.atan2(y, x)) % 360 for x, y in centres]
    assert angles == pytest.approx([45.0, 135.0, 225.0, 315.0])


@pytest.mark.parametrize("circles", [[], [{"name": "x", "diameter_mm": 50.0, "count": None,
                                           "hole_diameter_mm": 5.5}]])
def test_bolt_pattern_missing_data_writes_nothing(tmp_path, circles):
    path = tmp_path / "bolts.svg"
    assert plots.bolt_pattern_plot(circles, path) is None
    assert not path.exists()


def test_non_svg_path_is_input_error(evaluation, tmp_path):
    with pytest.raises(InputError, match="svg"):
        plots.duty_cycle_plot(evaluation.duty, tmp_path / "duty.png")


def test_weasyprint_renders_all_four_on_one_page(svgs, tmp_path):
    pytest.importorskip("weasyprint")
    pypdf = pytest.importorskip("pypdf")
    from hdcad.report.render import write_pdf
    # WeasyPrint prints an image's alt text when it cannot draw it: its absence in the PDF
    # text shows the SVG was drawn (checked: a truncated SVG does print its alt text)
    body = "".join(f"<figure><img src='{p.name}' style='width:170mm' alt='NOT DRAWN {k}'>"
                   f"<figcaption>Figure {k}</figcaption></figure>" for k, p in svgs.items())
    page = f"<html><head><style>@page {{size: A4}}</style></head><body>{body}</body></html>"
    pdf = tmp_path / "plots.pdf"
    pages = write_pdf(page, pdf, next(iter(svgs.values())).parent)
    text = "".join(page.extract_text() for page in pypdf.PdfReader(pdf).pages)
    assert all(f"Figure {k}" in text for k in svgs)  # text extraction itself works
    assert "NOT DRAWN" not in text
    assert pages <= 4  # four column-sized figures fit on at most one page each


def test_bolt_pattern_says_when_the_hole_angle_is_not_given(tmp_path):
    # results.json bolt circles carry no angle: the legend must not present 0° as a fact
    circle = {"name": "ring", "diameter_mm": 90.0, "count": 4, "hole_diameter_mm": 4.2,
              "thread": "M5", "kind": "tapped"}
    assert "angle not given" in _all_text(plots.bolt_pattern_plot([circle], tmp_path / "a.svg"))
    text = _all_text(plots.bolt_pattern_plot([dict(circle, start_angle_deg=45.0)],
                                             tmp_path / "b.svg"))
    assert "1st hole at 45°" in text and "angle not given" not in text


def _text_problems(fig) -> list:
    """Pairs of texts whose boxes overlap, and texts drawn over a curve (display coordinates)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text
    FigureCanvasAgg(fig)
    renderer = fig.canvas.get_renderer()
    fig.draw(renderer)
    texts = [t for ax in fig.axes for t in ax.texts if t.get_text().strip()]
    texts += [t for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    # Text's own extent: an Annotation's extent would include its leader line
    boxes = [(t.get_text(), Text.get_window_extent(t, renderer)) for t in texts]
    assert len(boxes) >= 2  # a plot without texts would pass below
    clashes = [(a, b) for i, (a, ba) in enumerate(boxes) for b, bb in boxes[i + 1:]
               if ba.overlaps(bb)]
    lines = [ln for ax in fig.axes for ln in ax.get_lines() if ln.get_linestyle() != "None"]
    points = [ln.get_transform().transform(ln.get_xydata()) for ln in lines]
    return clashes + [text for text, box in boxes
                      if any(box.contains(x, y) for pts in points for x, y in pts)]


def _captured_figure(monkeypatch, draw) -> object:
    figures = []
    save = plots._save
    monkeypatch.setattr(plots, "_save", lambda fig, path, title="": (figures.append(fig),
                                                                     save(fig, path, title))[1])
    draw()
    return figures[0]


@pytest.mark.parametrize("kind", ["duty", "twist", "life"])
def test_plot_texts_do_not_overlap(evaluation, tmp_path, monkeypatch, kind):
    model, duty = evaluation.model, evaluation.duty
    curve, _ = stiffness_curve(model)
    points = {"Tav": evaluation.derived["avg_torque_Nm"], "peak": 400.0,
              "shock": duty.shock.torque_Nm}
    draw = {"duty": lambda: plots.duty_cycle_plot(duty, tmp_path / "d.svg"),
            "twist": lambda: plots.torque_twist_plot(curve, points, tmp_path / "t.svg",
                                                     float(model.get("momentary_torque_Nm"))),
            "life": lambda: plots.life_plot(evaluation.check("wg_life"), duty.required_life_h,
                                            tmp_path / "l.svg")}[kind]
    assert not _text_problems(_captured_figure(monkeypatch, draw))


# small gear heads: T1 and T2 lie close together on the torque axis, where on-curve texts
# once collided (CSF-14-50-GH: T1 = 2, T2 = 6.9 N·m; CSG-20-100-GH: T1 = 7, T2 = 25 N·m)
@pytest.mark.parametrize("code", ["CSF-14-50-GH", "CSG-20-100-GH"])
def test_twist_texts_do_not_overlap_on_small_gears(catalog, tmp_path, monkeypatch, code):
    from hdcad.report.sheet import operating_points
    model = resolve(code, catalog)
    evaluation = run_checks(model, load_duty(examples_dir() / "duty_seed_example.yaml"), catalog)
    curve, _ = stiffness_curve(model)
    fig = _captured_figure(monkeypatch, lambda: plots.torque_twist_plot(
        curve, operating_points(evaluation), tmp_path / "t.svg",
        float(model.get("momentary_torque_Nm"))))
    assert not _text_problems(fig)
