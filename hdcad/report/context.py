"""Template context of the calculation sheet, built from the design's results.json data.

Every number the sheet prints is formatted here; ``templates/calc_sheet.html.j2`` only lays
it out. Inputs: the results dict (as written to results.json), the catalog (for its
interpretations and corrections), the figures and drawings written beside the sheet, the BOM.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from datetime import date

from .. import __version__
from ..catalog import Catalog
from ..models import parse_code
from ..sources import source_text
from .bom import BomRow
from .format import (check_label, fmt, margin_text, relation_text, status_text,
                     unit_text)

FAMILY_TITLES = {"torque": "Torque", "speed": "Speed", "strength": "Flexspline strength",
                 "life": "Wave-generator life", "thrust": "Thrust force",
                 "stiffness": "Stiffness and resonance", "lubrication": "Lubrication",
                 "bearing": "Main bearing", "geometry": "Geometry (generated parts)",
                 "adjustment": "FD phase adjuster (differential use)"}
DUTY_UNITS = {"torque_Nm": "N·m", "time_s": "s", "speed_rpm": "r/min"}
OPTION_UNITS = {"input_shaft_mm": "mm", "wall_mm": "mm", "running_gap_mm": "mm",
                "input_thrust_capacity_N": "N"}


@dataclass
class Figure:
    """An image beside the sheet (relative path), or the reason it is missing."""

    title: str
    file: str | None
    caption: str = ""
    reason: str = ""


def sheet_context(result: dict, catalog: Catalog, figures: list[Figure],
                  drawings: list[Figure], bom: list[BomRow], description: str,
                  today: date | None = None) -> dict:
    checks = result["checks"]
    counts = {s: sum(c["status"] == s for c in checks) for s in ("pass", "warn", "fail", "not_evaluated")}
    return {
        "model": result["model"], "description": description,
        "verdict": result["verdict"], "counts": counts, "all_passed": result["all_passed"],
        "date": (today or date.today()).isoformat(), "version": __version__,
        "revision": result["catalog_revision"],
        "duty_name": result["duty"].get("name", ""),
        "duty_summary": duty_summary(result),
        "cycle": cycle_rows(result["duty"]), "duty_extras": duty_extras(result["duty"]),
        "options": option_rows(result["design_options"]),
        "families": check_families(checks), "figures": figures, "drawings": drawings,
        "bom": [r.as_dict() for r in bom], "parts": part_rows(result["parts"]),
        "assumptions": assumptions(result, catalog),
        "provenance": provenance(checks),
        "failures": [check_label(c["id"], c["details"]) for c in checks if c["status"] == "fail"],
        "not_evaluated": [{"label": check_label(c["id"], c["details"]), "reason": _reason(c)}
                          for c in checks if c["status"] == "not_evaluated"],
        "warnings": [{"label": check_label(c["id"], c["details"]), "reason": c["note"]}
                     for c in checks if c["status"] == "warn"],
    }


def _reason(check: dict) -> str:
    """Why a check was not evaluated, from its note (first clause, without the prefix)."""
    note = check["note"] or ""
    return note.removeprefix("not evaluated: ").split("; ")[0].split(". ")[0]


def duty_summary(result: dict) -> list[tuple[str, str]]:
    d, duty = result["derived"], result["duty"]
    return [("average output torque Tav", f"{fmt(d['avg_torque_Nm'])} N·m"),
            ("largest torque", f"{fmt(d['max_torque_Nm'])} N·m"),
            ("average output speed", f"{fmt(d['avg_output_speed_rpm'])} r/min"),
            ("average / max WG speed relative to S" if duty.get("use") == "differential"
             else "average / max input speed", f"{fmt(d['avg_input_speed_rpm'])} / "
                                               f"{fmt(d['max_input_speed_rpm'])} r/min"),
            ("ratio", fmt(d["ratio"])),
            ("required life L10", f"{fmt(duty['required_life_h'])} h"),
            ("use", duty.get("use", "reducer")),
            ("lubrication", duty["lubrication"] + (f" ({duty['grease']})"
                                                  if duty["lubrication"] == "grease" else ""))]


def cycle_rows(duty: dict) -> list[dict]:
    rows = [{"phase": s["phase"], "torque": fmt(s["torque_Nm"]), "time": fmt(s["time_s"]),
             "speed": fmt(s["speed_rpm"])} for s in duty["cycle"]]
    shock = duty.get("shock")
    if shock:
        rows.append({"phase": f"shock ({fmt(shock.get('count'))} in the life)",
                     "torque": fmt(shock["torque_Nm"]), "time": fmt(shock["time_s"]),
                     "speed": fmt(shock["speed_rpm"])})
    return rows


def duty_extras(duty: dict) -> list[tuple[str, str]]:
    rows = [("max output speed", f"{fmt(duty['max_output_speed_rpm'])} r/min"),
            ("max input speed (motor)", f"{fmt(duty['max_input_speed_rpm'])} r/min"),
            ("ambient temperature", f"{fmt(duty.get('ambient_C'))} °C"),
            ("load inertia", f"{fmt(duty.get('load_inertia_kgm2'))} kg·m²")]
    load = duty.get("external_load")
    if load:
        rows.append(("external load", f"Fr {fmt(load['radial_N'])} N, Fa {fmt(load['axial_N'])} N, "
                                      f"Lr {fmt(load['Lr_m'])} m, La {fmt(load['La_m'])} m, "
                                      f"fw {fmt(load['fw'])}"))
    return rows


OPTION_NONE = {"motor_flange": "first complete code of the table (part notes name it)",
               "input_shaft_mm": "not given", "input_thrust_capacity_N": "not given"}


def option_rows(options: dict) -> list[dict]:
    """Each design option with its value and whether the design file set it."""
    from ..checks.rules import Rules
    given = set(options.get("given") or ())
    rows = [{"key": k, "unit": "" if v is None else OPTION_UNITS.get(k, ""),
             "default": k not in given,
             "value": OPTION_NONE.get(k, "—") if v is None else fmt(v)}
            for k, v in options.items()
            if k not in ("extra", "given", "rules", "drive", "motor")]
    for key, empty in (("drive", "none (the user fastens the gear)"),
                       ("motor", "not given (the flange code's own motor side)")):
        block = options.get(key) or {}
        rows.append({"key": key, "unit": "", "default": key not in given,
                     "value": ", ".join(f"{k} {fmt(v)}" for k, v in block.items()
                                        if v is not None) or empty})
    changed = options.get("rules") or {}
    # hdcad's own rules (checks/rules.py): listed so a reviewer sees which were changed
    rows += [{"key": f"rules.{k}", "unit": "", "default": k not in changed,
              "value": "from fw (table 034-3 mapping)" if v is None else fmt(v)}
             for k, v in dict(Rules().as_dict(), **changed).items()]
    return rows


def check_row(c: dict) -> dict:
    inputs = [{"name": name, "value": fmt(q["value"]), "unit": unit_text(q["unit"]),
               "source": q["source"]}
              for name, q in c["inputs"].items()]
    return {"label": check_label(c["id"], c["details"], criterion=False),
            "criterion": c["details"].get("governing", ""), "id": c["id"], "title": c["title"],
            "formula": c["formula"], "inputs": inputs, "value": fmt(c["value"]),
            "limit": fmt(c["limit"]), "sense": relation_text(c["sense"], c["status"]),
            "unit": unit_text(c["unit"]),
            "margin": margin_text(c["margin"]), "status": c["status"],
            "status_text": status_text(c["status"]), "note": c["note"], "source": c["source"],
            "criteria": criteria_rows(c["details"].get("criteria"))}


def criteria_rows(criteria) -> list[dict]:
    """Sub-criteria of a check (bolt pattern, lubrication, oil level) as table rows."""
    if isinstance(criteria, dict):
        return [{"name": k, "status": v["status"], "status_text": status_text(v["status"]),
                 "text": f"{fmt(v['value'])} {relation_text(v['sense'], v['status'])} {fmt(v['limit'])} "
                         f"{unit_text(v['unit'])}: "
                         f"{v['rule']}"} for k, v in criteria.items()]
    return [{"name": c["name"], "status": c["status"], "status_text": status_text(c["status"]),
             "text": c["text"]} for c in criteria or []]


def check_families(checks: list[dict]) -> list[dict]:
    order = list(dict.fromkeys(c["family"] for c in checks))
    return [{"title": FAMILY_TITLES.get(f, f.title()), "checks":
             [check_row(c) for c in checks if c["family"] == f]} for f in order]


def part_rows(parts: list[dict]) -> list[dict]:
    return [{"name": p["name"], "mass": fmt(p["mass_kg"]),
             "mass_before": fmt(p["mass_before_pockets_kg"])
             if p.get("mass_before_pockets_kg") else "",
             "dimensions": [(k.removesuffix("_mm").replace("_", " "), fmt(v))
                            for k, v in p["dimensions"].items()], "notes": p["notes"],
             "material": p.get("material", ""),
             "fits": [fit_row(f) for f in p.get("fits", [])],
             "tolerances": [tolerance_row(t) for t in p.get("tolerances", [])]}
            for p in parts]


def fit_row(f: dict) -> dict:
    up, low = f["deviations_um"]
    return {"feature": f["feature"], "fit": f"Ø{f['nominal_mm']:g} {f['code']}",
            "limits": f"{up / 1000:+.3f} / {low / 1000:+.3f}", "mate": f["mate"],
            "reason": f["reason"]}


def tolerance_row(t: dict) -> dict:
    value = "" if t["value_mm"] is None else f"{t['value_mm']:g}"
    return {"feature": t["feature"], "characteristic": t["characteristic"],
            "value": value, "datums": t["datums"]}


def provenance(checks: list[dict]) -> list[dict]:
    """Every input that carries a source (catalog table or standard), once, with its users."""
    rows: dict[tuple, dict] = {}
    for c in checks:
        for name, q in c["inputs"].items():
            if not q["source"]:
                continue
            key = (name, fmt(q["value"]), unit_text(q["unit"]), q["source"])
            row = rows.setdefault(key, {"name": name, "value": fmt(q["value"]),
                                        "unit": unit_text(q["unit"]), "source": q["source"],
                                        "used_by": []})
            label = check_label(c["id"], c["details"])
            if label not in row["used_by"]:
                row["used_by"].append(label)
    return [dict(r, used_by=", ".join(r["used_by"])) for r in rows.values()]


TABLE_ID = re.compile(r"\d{3}-\d")


def _table_ids(catalog: Catalog, file: str) -> set[str]:
    listed = " ".join(map(str, catalog.sources.get(file, {}).get("tables", []) or []))
    return set(TABLE_ID.findall(file + " " + listed))


SIZE_MENTION = re.compile(r"\b[Ss]ize (\d+)\b")


def _used_sources(result: dict) -> str:
    """Source text of the catalog values this design actually used.

    A check that was not evaluated because it does not apply (grease instead of oil, a closed
    gear head) used no table even though its record names one; only inputs with a value count.
    """
    texts = []
    for c in result["checks"]:
        if c["status"] != "not_evaluated":
            texts.append(c["source"])
        texts += [q["source"] for q in c["inputs"].values() if q.get("value") is not None]
    texts += [n for p in result["parts"] for n in p["notes"]]
    return " ".join(texts)


def note_applies(text: str, used_ids: set[str], size: int | None) -> bool:
    """Whether an interpretation note bears on this design.

    A note that names seed tables applies when it names one the design used; a note that names
    gear sizes applies when it names this size. Notes that name neither apply to the whole table.
    """
    ids = set(TABLE_ID.findall(text))
    if ids and not ids & used_ids:
        return False
    sizes = {int(m) for m in SIZE_MENTION.findall(text)}
    return not sizes or size is None or size in sizes


def assumptions(result: dict, catalog: Catalog) -> list[dict]:
    """Interpretations of the catalog tables this design used, then the tool's own choices."""
    used_ids = set(TABLE_ID.findall(_used_sources(result)))
    size = parse_code(result["model"])[2]
    rows = [{"where": file, "text": text} for file, text in catalog.interpretations()
            if used_ids & _table_ids(catalog, file) and note_applies(text, used_ids, size)]
    for part in result["parts"]:
        rows += [{"where": part["name"], "text": source_text(note)} for note in part["notes"]]
    return rows
