"""`hdcad catalog MODEL`: every value the catalog holds for one model, with its source,
and for a gear head its motor-flange codes (pilot, bolt circle, thread) to pick one from."""

from __future__ import annotations

from .catalog import Catalog
from .models import GearModel
from .report.format import fmt, unit_text
from .sources import source_text

FLANGE_TABLE = "gh_motor_flange"


def model_lines(model: GearModel, catalog: Catalog) -> list[str]:
    """Lines of text: the model's data (value, unit, source), FD ratings by speed, flanges."""
    lines = [f"{model.code}: {model.description} (catalog revision {catalog.revision})", ""]
    rows = [[name, fmt(d.value), unit_text(d.unit), source_text(d.source)]
            for name, d in sorted(model.data.items())]
    lines += table(["quantity", "value", "unit", "source"], rows)
    if model.fd_torque_by_speed:
        lines += ["", "rated torque by input speed (FD):"]
        lines += table(["speed [r/min]", "torque [N·m]", "source"],
                       [[fmt(s), fmt(d.value), source_text(d.source)]
                        for s, d in model.fd_torque_by_speed])
    if model.family == "GH":
        lines += ["", "motor flanges (design option motor_flange):"]
        lines += table(["code", "type", "pilot H7 [mm]", "pilot depth [mm]", "bolt circle [mm]",
                        "thread × depth", "square [mm]", "coupling bore [mm]", "table"],
                       flange_rows(model, catalog))
    return lines


def flange_rows(model: GearModel, catalog: Catalog) -> list[list[str]]:
    rows = []
    for r in catalog.rows(FLANGE_TABLE, series=model.series, size=model.size):
        depth = f" × {fmt(r['thread_depth_mm'])}" if r.get("thread_depth_mm") else ""
        bore = (f"{fmt(r['coupling_bore_min_mm'])}…{fmt(r['coupling_bore_max_mm'])}"
                if r.get("coupling_bore_max_mm") else "—")
        rows.append([r["flange_code"], r.get("flange_type") or "", fmt(r.get("pilot_H7_mm")),
                     fmt(r.get("pilot_depth_mm")), fmt(r.get("bolt_circle_mm")),
                     (r.get("thread") or "—") + depth, fmt(r.get("square_mm")), bore,
                     r.get("table") or ""])
    return rows


def table(headers: list[str], rows: list[list[str]]) -> list[str]:
    """A plain-text table: columns padded to their widest cell."""
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *rows)]

    def line(cells) -> str:
        return "  ".join(str(c).ljust(w) for c, w in zip(cells, widths)).rstrip()
    return [line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows]
