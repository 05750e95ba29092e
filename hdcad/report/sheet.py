"""Write the calculation sheet (HTML + PDF) and its figures into a design folder.

The figures are SVG files in ``figures/`` beside the sheet; the drawings (made by the
geometry package from the STEP files) are in ``drawings/``. The HTML links them relatively,
so the folder can be moved as a whole.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..catalog import Catalog
from ..checks.run import Evaluation, stiffness_curve
from .bom import bill_of_materials
from .context import Figure, sheet_context
from .render import render_html, write_pdf

TEMPLATE = "calc_sheet.html.j2"
# CJK characters (seed quotations in the catalog notes): the PDF embeds only the DejaVu fonts
CJK = re.compile(r"[\u3000-\u30ff\u3400-\u4dbf\u4e00-\u9fff\uff00-\uffef]+")


def operating_points(evaluation: Evaluation) -> dict[str, float]:
    """Output torques [N·m] to mark on the torque–twist curve: each duty phase, Tav, shock."""
    points = {f"{s.phase}": s.torque_Nm for s in evaluation.duty.cycle if s.torque_Nm}
    points["Tav"] = evaluation.derived["avg_torque_Nm"]
    if evaluation.duty.shock:
        points["shock"] = evaluation.duty.shock.torque_Nm
    return points


def make_figures(evaluation: Evaluation, folder: Path) -> list[Figure]:
    """The duty, torque–twist and life plots as SVG in ``folder/figures``."""
    from . import plots
    out = folder / "figures"
    out.mkdir(exist_ok=True)
    duty, model = evaluation.duty, evaluation.model
    figures = [Figure("Duty cycle", _rel(plots.duty_cycle_plot(duty, out / "duty_cycle.svg"),
                                         folder),
                      "Output torque and output speed over one cycle; the dashed line is the "
                      "average torque Tav (formula 014-1).")]
    curve, source = stiffness_curve(model)
    limit = model.get("momentary_torque_Nm")
    twist = plots.torque_twist_plot(curve, operating_points(evaluation), out / "torque_twist.svg",
                                    None if limit is None else float(limit))
    figures.append(Figure("Torque–twist curve", _rel(twist, folder),
                          f"Catalog stiffness ({source}) with the duty's torques marked.",
                          "" if twist else "the catalog gives no stiffness curve for this model"))
    life = evaluation.check("wg_life")
    life_svg = plots.life_plot(life, evaluation.duty.required_life_h, out / "life.svg")
    figures.append(Figure("Wave-generator life", _rel(life_svg, folder),
                          "L10 life against the average output torque (formula 012-1) at the "
                          "duty's average input speed; the horizontal line is the required life.",
                          "" if life_svg else life.note))
    return figures


def make_bolt_figures(parts: list[dict], folder: Path) -> list[Figure]:
    """One bolt-pattern plot per part that has bolt circles, as SVG in ``folder/figures``."""
    from . import plots
    out = folder / "figures"
    out.mkdir(exist_ok=True)
    figures = []
    for part in parts:
        if not part["bolt_circles"]:
            continue
        dims = part["dimensions"]
        svg = plots.bolt_pattern_plot(part["bolt_circles"], out / f"bolts_{part['name']}.svg",
                                      part["name"], dims.get("outer_diameter_mm"),
                                      dims.get("bore_mm") or dims.get("shaft_hole_mm"))
        figures.append(Figure(f"Bolt pattern of {part['name']}", _rel(svg, folder),
                              "Front view of the bolt circles (holes, annulus, edges) that the "
                              "bolt_pattern checks evaluate.", "" if svg else "no data"))
    return figures


def warm_up() -> None:
    """Import the PDF renderer ahead of use (a side process does it while CAD builds)."""
    import weasyprint  # noqa: F401


def _rel(path: Path | None, folder: Path) -> str | None:
    return None if path is None else Path(path).relative_to(folder).as_posix()


def write_calc_sheet(folder: Path, result: dict, evaluation: Evaluation, catalog: Catalog,
                     drawings: list[Figure], figures: list[Figure] | None = None) -> dict:
    """Write calc_sheet.html and calc_sheet.pdf into ``folder``; returns names and page count.

    ``figures``: the plots already made (make_figures + make_bolt_figures); made here if None.
    """
    if figures is None:
        figures = make_figures(evaluation, folder) + make_bolt_figures(result["parts"], folder)
    options = result["design_options"]
    model = evaluation.model
    housing_row = (catalog.find("component_housing", series=model.series, size=model.size)
                   if catalog.has("component_housing") else None)
    bom = bill_of_materials(result["parts"], result["checks"], model.family,
                            evaluation.duty.lubrication, evaluation.duty.grease,
                            options["bolt_class"], (housing_row or {}).get("grease_g"))
    context = sheet_context(result, catalog, figures, drawings, bom,
                            model.description)
    html = render_html(TEMPLATE, context)
    (folder / "calc_sheet.html").write_text(html, encoding="utf-8")
    pages = write_pdf(CJK.sub("[ja]", html), folder / "calc_sheet.pdf", folder)
    images = [f.file for f in figures + drawings if f.file]
    return {"files": ["calc_sheet.html", "calc_sheet.pdf"] + images, "pages": pages,
            "images": images, "bom": [r.as_dict() for r in bom]}
