"""Template context of a batch's index page: candidates side by side (formatting only)."""

from __future__ import annotations

from .. import __version__
from ..batch import INDEX_CHECKS
from .format import fmt, margin_text, status_text


def index_context(summaries: list[dict], duty_name: str) -> dict:
    """Rows of the index table, one per candidate, in the batch's order."""
    return {"duty_name": duty_name, "version": __version__, "columns": list(INDEX_CHECKS),
            "rows": [_row(s) for s in summaries],
            "built": sum(s["built"] for s in summaries), "total": len(summaries)}


def _row(s: dict) -> dict:
    if not s["built"]:
        return {"model": s["model"], "built": False, "error": s["error"]}
    gov = s["governing"]
    return {"model": s["model"], "built": True, "link": f"{s['folder']}/calc_sheet.pdf",
            "description": s["description"], "verdict": s["verdict"],
            "status": "pass" if s["all_passed"] else "fail",
            "counts": " · ".join(f"{n} {status_text(k).lower()}"
                                 for k, n in s["counts"].items()),
            "governing": "—" if gov is None else
            (f"{gov['id']}[{gov['name']}]" if gov["name"] else gov["id"]) + " "
            + margin_text(gov["margin"]),
            "margins": [margin_text(s["margins"].get(c)) for c in INDEX_CHECKS],
            "life": fmt(s["life_h"]), "mass": fmt(s["mass_kg"]), "parts": s["parts"],
            "seconds": f"{s['seconds']:.1f}"}
