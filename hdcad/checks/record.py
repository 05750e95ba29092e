"""The one result record every check returns."""

from __future__ import annotations

from dataclasses import dataclass, field, asdict
from typing import Any

from ..catalog import Datum

PASS, FAIL, NOT_EVALUATED = "pass", "fail", "not_evaluated"
# allowed only after confirmation with the maker ("consult Harmonic Drive"), or beyond a
# guide value the catalog gives without making it a limit: does not fail the design
WARN = "warn"
STATUSES = (PASS, WARN, FAIL, NOT_EVALUATED)


@dataclass
class Quantity:
    value: Any
    unit: str = ""
    source: str = ""


@dataclass
class CheckResult:
    """Outcome of one selection or geometric check.

    ``margin`` is the fraction of the limit left over: (limit − value)/limit for an upper
    limit (``sense`` ``<=``), (value − limit)/limit for a lower limit (``>=``). Negative
    margins fail.
    """

    id: str
    title: str
    family: str
    formula: str
    inputs: dict[str, Quantity]
    value: float | None
    limit: float | None
    unit: str
    sense: str  # "<=" value must not exceed limit; ">=" value must reach limit
    status: str
    source: str
    note: str = ""
    margin: float | None = None
    details: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        """The record for results.json: sources with the seed documents' titles, plus
        ``source_refs`` ({document, table, page, line} per citation) for machines."""
        from ..sources import source_refs, source_text
        data = asdict(self)
        data["source_refs"] = source_refs(self.source)
        data["source"] = source_text(self.source)
        for q in data["inputs"].values():
            q["source"] = source_text(q["source"])
        return data

    @property
    def failed(self) -> bool:
        return self.status == FAIL


def quantity(datum: Datum | float | None, unit: str = "", source: str = "") -> Quantity:
    """A Quantity from a catalog Datum (keeps its source) or a plain number."""
    if isinstance(datum, Datum):
        return Quantity(datum.value, datum.unit or unit, datum.source)
    return Quantity(datum, unit, source)


def margin_of(value: float, limit: float, sense: str) -> float | None:
    if limit == 0:
        return None
    return (limit - value) / limit if sense == "<=" else (value - limit) / limit


def compared(id: str, title: str, family: str, formula: str, inputs: dict[str, Quantity],
             value: float, limit: float, unit: str, sense: str, source: str,
             note: str = "", details: dict | None = None) -> CheckResult:
    """A check that compares ``value`` with ``limit``; pass when the sense holds."""
    ok = value <= limit if sense == "<=" else value >= limit
    return CheckResult(id, title, family, formula, inputs, value, limit, unit, sense,
                       PASS if ok else FAIL, source, note, margin_of(value, limit, sense),
                       details or {})


def not_evaluated(id: str, title: str, family: str, formula: str, missing: str,
                  inputs: dict[str, Quantity] | None = None, value: float | None = None,
                  unit: str = "", source: str = "", note: str = "",
                  details: dict | None = None) -> CheckResult:
    """A check that cannot be decided; ``missing`` names the data that is missing."""
    text = f"not evaluated: {missing}" + (f". {note}" if note else "")
    return CheckResult(id, title, family, formula, inputs or {}, value, None, unit, "",
                       NOT_EVALUATED, source, text, None, details or {})


def criterion(value, limit, unit: str, sense: str, rule: str, status: str | None = None) -> dict:
    """One sub-criterion of a multi-criterion check (bolt circle, main bearing)."""
    if status is None:
        ok = value <= limit if sense == "<=" else value >= limit
        status = PASS if ok else FAIL
    margin = margin_of(value, limit, sense) if status != NOT_EVALUATED and limit else None
    return {"value": value, "limit": limit, "unit": unit, "sense": sense, "status": status,
            "margin": margin, "rule": rule}


def governing_criterion(criteria: dict[str, dict], default: str) -> str:
    """The criterion a one-line summary shows: a failing one, else the smallest margin."""
    decided = {k: c for k, c in criteria.items() if c["margin"] is not None}
    if not decided:
        return default
    return min(decided, key=lambda k: (criteria[k]["status"] != FAIL, decided[k]["margin"]))


def governed(id: str, title: str, family: str, formula: str, inputs: dict, criteria: dict,
             default: str, source: str, note: str, details: dict) -> CheckResult:
    """A check whose row shows its governing criterion's value, limit, unit and sense; it
    fails when any criterion fails. All criteria stay in ``details['criteria']``."""
    key = governing_criterion(criteria, default)
    g = criteria[key]
    details = dict(details, criteria=criteria, governing=key)
    result = compared(id, title, family, formula, inputs, g["value"], g["limit"], g["unit"],
                      g["sense"], source, f"governing: {key}; {note}" if note else
                      f"governing: {key}", details)
    if any(c["status"] == FAIL for c in criteria.values()):
        result.status = FAIL
    return result
