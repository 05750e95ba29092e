"""Plots and the short report of ``hdcad reconcile --out DIR``.

Writes into a folder: ``comparison.svg`` (measured vs baseline vs reconciled),
``residuals.svg`` (residual maps before and after against the kind's operating variable),
``residuals_in_order.svg`` (the same residuals in the record's row order, where a drift with
test time, a re-zeroed sensor or a switched range shows), ``report.html`` and ``report.pdf``
(rendered from ``templates/reconcile_report.html.j2`` with the report machinery of the
calculation sheet, :mod:`hdcad.report.render`). The template only formats: every number is
computed and formatted here. matplotlib and WeasyPrint are imported only when a report is
written.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..report.render import render_html, write_pdf
from .effects import EFFECTS
from .workflow import Reconciliation

TEMPLATE = "reconcile_report.html.j2"
# Points drawn per series: enough to show the structure, small enough for a light SVG.
MAX_PLOT_POINTS = 1500

# x axis of each kind's plots: (series name, label) — the operating variable of the issue.
X_AXIS = {"torsion": ("torque_Nm", "torque T [N·m]"),
          "transmission": ("wg_angle_rad", "WG angle φ mod 2π [rad]"),
          "efficiency": ("alpha", "load ratio α = T/Tr [-]"),
          "vibration": ("input_speed_rpm", "input speed [r/min]")}
ORDER_LABEL = "row of the record (test order) [-]"
Y_LABEL = {"torsion": "twist [rad]", "transmission": "output − input/R [rad]",
           "efficiency": "efficiency [%]", "vibration": "output vibration [rad]"}


def fmt(value: float, unit: str = "") -> str:
    """A number with 4 significant digits and its unit."""
    if value is None or not math.isfinite(value):
        return "—"
    text = f"{value:.4g}"
    return f"{text} {unit}".strip()


# the data's dots are drawn as an image inside the SVG (thousands of vector markers take a
# PDF renderer seconds), at this resolution; axes, lines and text stay vectors
RASTER_DPI = 200


def _x(result: Reconciliation) -> np.ndarray:
    name = X_AXIS[result.kind][0]
    x = result.series[name]
    return np.mod(x, 2 * math.pi) if result.kind == "transmission" else x


def _pick(n: int) -> np.ndarray:
    return np.arange(n) if n <= MAX_PLOT_POINTS else \
        np.linspace(0, n - 1, MAX_PLOT_POINTS).astype(int)


def comparison_plot(result: Reconciliation, path: Path) -> Path:
    """Measured (dots), baseline and reconciled model against the kind's operating variable.

    Transmission and torsion subtract the catalog part (input/R; the catalog twist curve is
    kept for torsion, whose shape is the point of the plot).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = result.series
    minus = s["catalog"] if result.kind == "transmission" else 0.0
    x = _x(result)
    i = _pick(len(x))
    line = np.argsort(x[i], kind="stable") if result.kind == "efficiency" else slice(None)
    fig, ax = plt.subplots(figsize=(7.0, 3.6))
    ax.plot(x[i], (s["measured"] - minus)[i], ".", ms=1.5, color="0.6", label="measured",
            rasterized=True)
    dots = result.kind in ("transmission", "efficiency")
    ax.plot(x[i][line], (s["baseline"] - minus)[i][line], "." if dots else "-", ms=1.5,
            lw=0.8, color="tab:blue", label="baseline (catalog)", rasterized=dots)
    ax.plot(x[i][line], (s["reconciled"] - minus)[i][line], "." if dots else "-", ms=1.5,
            lw=0.8, color="tab:red", label="reconciled", rasterized=dots)
    ax.set_xlabel(X_AXIS[result.kind][1])
    ax.set_ylabel(Y_LABEL[result.kind])
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, markerscale=4)
    fig.tight_layout()
    fig.savefig(path, dpi=RASTER_DPI)
    plt.close(fig)
    return path


def residual_plot(result: Reconciliation, path: Path, in_order: bool = False) -> Path:
    """Residual maps: before (baseline) and after (reconciled), with ±noise RMS bands,
    against the kind's operating variable or, ``in_order``, against the row of the record
    (the order the test ran in: what changes with test time, not with the load, shows
    there)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = result.series
    x = np.arange(len(s["measured"]), dtype=float) if in_order else _x(result)
    i = _pick(len(x))
    fig, axes = plt.subplots(2, 1, figsize=(7.0, 4.6), sharex=True)
    for ax, name, title in ((axes[0], "baseline", "before: measured − baseline"),
                            (axes[1], "reconciled", "after: measured − reconciled")):
        ax.plot(x[i], (s["measured"] - s[name])[i], ".", ms=1.2, color="0.3",
                rasterized=True)
        for sign in (-1, 1):
            ax.axhline(sign * result.noise_rms, color="tab:green", lw=0.8, ls="--")
        ax.set_title(title, fontsize=8)
        ax.set_ylabel(f"residual [{result.unit}]")
        ax.grid(alpha=0.3)
    axes[1].set_xlabel(ORDER_LABEL if in_order else X_AXIS[result.kind][1])
    fig.tight_layout()
    fig.savefig(path, dpi=RASTER_DPI)
    plt.close(fig)
    return path


def report_context(result: Reconciliation, figures: list[dict]) -> dict:
    """Everything the template prints, formatted."""
    unit = result.unit
    gain = 1.0 - result.rmse_after / result.rmse_before if result.rmse_before > 0 else 0.0
    steps = [{"effect": st.effect, "description": EFFECTS[st.effect].description,
              "form": st.form or EFFECTS[st.effect].form, "criterion_gain": f"{st.criterion_gain:.1f}",
              "cv_gain": f"{st.cv_gain:.0%}", "rmse": fmt(st.rmse, unit),
              "params": [{"name": k, "value": fmt(v["value"], v["unit"])}
                         for k, v in st.params.items()]}
             for st in result.steps]
    rounds = [[{"effect": c["effect"], "delta_bic": f"{c['delta_bic']:.1f}",
                "cv_gain": f"{c['cv_gain']:.1%}",
                "explained": f"{c['explained_var_over_noise']:.2f}",
                "verdict": "added" if c["accepted"] else
                "added, set aside later" if c.get("set_aside") else
                "held back: its gear twin reads the same" if c.get("held_for_twin") else
                ("passes, not best" if c["passes"] else "rejected")} for c in r]
              for r in result.candidates]
    regions = [{"where": r["where"], "before": fmt(r["rms_before"], unit),
                "after": fmt(r["rms_after"], unit),
                "flag": region_verdict(r["significant"], r.get("significant_after", False))}
               for r in result.regions]
    return {
        "kind": result.kind, "model": result.model, "unit": unit,
        "noise": fmt(result.noise_rms, unit),
        "rmse_before": fmt(result.rmse_before, unit), "rmse_after": fmt(result.rmse_after, unit),
        "gain": f"{gain:.0%}",
        "missing": ", ".join(result.missing_effects) or "none",
        "baseline_params": [{"name": k, "value": fmt(v["value"], v["unit"])}
                            for k, v in result.baseline_params.items()],
        "disagreements": [{"where": d["where"], "rms": fmt(d["rms"], unit)}
                          for d in result.disagreements],
        "steps": steps, "rounds": rounds, "regions": regions,
        "unexplained": result.unexplained, "notes": result.notes, "figures": figures,
        "rig": [{"effect": m["effect"], "detail": m.get("reading") or ", ".join(
            f"{k} = {fmt(v['value'], v['unit'])}" for k, v in m["params"].items())}
            for m in result.measurement_effects],
        "nuisances": [n["text"] for n in result.nuisances],
        "readings": [r["text"] for r in result.equivalent_readings],
        "outliers": result.outliers,
    }


def region_verdict(before: bool, after: bool) -> str:
    """Before → after reading of one region: the baseline against the reconciled model."""
    if before:
        return "disagreed → still disagrees" if after else "disagreed → explained"
    return "new disagreement" if after else ""


def write_report(result: Reconciliation, folder: Path) -> list[str]:
    """Write the plots, report.html and report.pdf into ``folder``; the file names."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    comparison_plot(result, folder / "comparison.svg")
    residual_plot(result, folder / "residuals.svg")
    residual_plot(result, folder / "residuals_in_order.svg", in_order=True)
    figures = [{"file": "comparison.svg",
                "caption": "Measured data, the catalog baseline and the reconciled model."},
               {"file": "residuals.svg",
                "caption": "Residuals before and after; dashed: ± the noise RMS estimated "
                           "from the data."},
               {"file": "residuals_in_order.svg",
                "caption": "The same residuals in the record's row order: a drift with test "
                           "time, a step where a sensor was re-zeroed or a range switched, "
                           "blocks run at one temperature."}]
    html = render_html(TEMPLATE, report_context(result, figures))
    (folder / "report.html").write_text(html, encoding="utf-8")
    write_pdf(html, folder / "report.pdf", folder)
    return ["comparison.svg", "residuals.svg", "residuals_in_order.svg", "report.html",
            "report.pdf"]
