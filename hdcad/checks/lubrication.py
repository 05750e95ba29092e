"""Lubrication: lubricant choice by series, size and ratio; temperature; FD grease limits.

References
----------
Seed 000 p.016 (tables 016-1 … 016-6: lubricants, ambient ranges, grease by size and
ratio; unit and gear-head types ship grease-filled), p.018 (oil ISO VG68, change after
100 h then every 1000 h or 6 months). Seed 001 p.315 (FD: oil level A, table 315-1; grease
only for ED ≤ 10 % and ≤ 10 min continuous running, input speed within table 313-4,
recommended grease SK-1A).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from ..duty import Duty, Segment
from .record import CheckResult, Quantity, FAIL, NOT_EVALUATED, PASS, WARN

FD_GREASE_MAX_ED_PCT = 10.0  # seed 001 p.315
FD_GREASE_MAX_CONTINUOUS_S = 600.0  # seed 001 p.315: 10 min
FD_RECOMMENDED_GREASE = "SK-1A"  # seed 001 p.315
OIL_NAME = "ISO VG68"
SOURCE = "seed 000 pp.016-018 (tables 016-2, 016-5, 016-6); seed 001 p.315"
FORMULA = ("lubricant suited to size and ratio (016-5/016-6); ambient within its range "
           "(016-2); FD grease: ED ≤ 10 %, continuous run ≤ 10 min")


@dataclass
class Criterion:
    name: str
    status: str
    text: str


def duty_ratio_pct(cycle: Sequence[Segment]) -> float:
    """ED [%]: moving time over cycle time."""
    return 100.0 * sum(s.time_s for s in cycle if s.speed_rpm > 0) / sum(s.time_s for s in cycle)


def longest_continuous_run_s(cycle: Sequence[Segment]) -> float:
    """Longest uninterrupted moving time [s] with the cycle repeating; inf if it never stops."""
    if all(s.speed_rpm > 0 for s in cycle):
        return float("inf")
    longest = run = 0.0
    for seg in list(cycle) * 2:  # twice round, so a run across the cycle boundary counts
        run = run + seg.time_s if seg.speed_rpm > 0 else 0.0
        longest = max(longest, run)
    return longest


def _grease_rating(size: int, ratio: int, grease: str, rows: list[dict]) -> str | None:
    for row in rows:
        high = row.get("ratio_max")
        if (row["size"] == size and row["grease"] == grease and row["ratio_min"] <= ratio
                and (high is None or ratio <= high)):
            return row["rating"]
    return None


def _temperature(lubricant: str, ambient_C: float | None, rows: list[dict]) -> Criterion:
    if ambient_C is None:
        return Criterion("temperature", PASS, "ambient_C not given: temperature range not checked")
    for row in rows:
        if row["lubricant"] == lubricant and row.get("basis") == "ambient":
            low, high = row["use_min_C"], row["use_max_C"]
            ok = low <= ambient_C <= high
            return Criterion("temperature", PASS if ok else FAIL,
                             f"ambient {ambient_C:g} °C {'within' if ok else 'outside'} "
                             f"{lubricant} range {low:g}…{high:g} °C (table 016-2)"
                             + ("" if ok else "; see 019-1…019-3 for special lubricants"))
    return Criterion("temperature", NOT_EVALUATED,
                     f"ambient range of {lubricant} missing from the catalog")


def _fd_criteria(duty: Duty, oil_level_mm: float | None) -> tuple[list[Criterion], dict]:
    if duty.lubrication == "oil":
        level = (f"oil level A = {oil_level_mm:g} mm (table 315-1)" if oil_level_mm is not None
                 else "oil level A missing from table 315-1")
        return [Criterion("lubricant", PASS, f"oil {OIL_NAME}; {level}")], {}
    ed = duty_ratio_pct(duty.cycle)
    run = longest_continuous_run_s(duty.cycle)
    out = [
        Criterion("grease", PASS if duty.grease == FD_RECOMMENDED_GREASE else WARN,
                  f"grease {duty.grease}; the FD series recommends {FD_RECOMMENDED_GREASE}"
                  + ("" if duty.grease == FD_RECOMMENDED_GREASE else
                     ": another grease only after consulting Harmonic Drive (seed 001 p.315)")),
        Criterion("ED", PASS if ed <= FD_GREASE_MAX_ED_PCT else FAIL,
                  f"ED {ed:.1f} % (grease allowed up to {FD_GREASE_MAX_ED_PCT:g} %)"),
        Criterion("continuous run", PASS if run <= FD_GREASE_MAX_CONTINUOUS_S else FAIL,
                  "continuous running " + ("unbounded (the cycle never stops)" if run == float("inf")
                                           else f"{run:g} s") + " (grease allowed up to 10 min)"),
    ]
    return out, {"ED_pct": ed}


def _cup_criteria(family: str, size: int, ratio: int, duty: Duty,
                  suitability: list[dict]) -> list[Criterion]:
    if duty.lubrication == "oil":
        if family == "GH":
            return [Criterion("lubricant", WARN, "gear heads ship grease-filled; oil "
                                                 "lubrication only after consulting Harmonic "
                                                 "Drive (seed 000 p.016)")]
        return [Criterion("lubricant", PASS, f"oil {OIL_NAME}; oil level for component types is "
                                             "not in the seeds (add the series' design-guide "
                                             "value through an overlay)")]
    rating = _grease_rating(size, ratio, duty.grease, suitability)
    if rating is None:
        return [Criterion("grease", NOT_EVALUATED,
                          f"suitability of {duty.grease} for size {size}, ratio {ratio} missing "
                          "from tables 016-5/016-6")]
    ok = rating != "not_suitable"
    return [Criterion("grease", PASS if ok else FAIL,
                      f"{duty.grease} for size {size}, ratio {ratio}: {rating.replace('_', ' ')} "
                      "(tables 016-5/016-6)")]


def lubrication(family: str, size: int, ratio: int, duty: Duty, suitability: list[dict],
                temperatures: list[dict], oil_level_mm: float | None = None) -> CheckResult:
    """Whether the duty's lubricant suits the model; details list every criterion."""
    value = limit = None
    unit = sense = ""
    if family.startswith("FD"):
        criteria, numbers = _fd_criteria(duty, oil_level_mm)
        if "ED_pct" in numbers:
            value, limit, unit, sense = numbers["ED_pct"], FD_GREASE_MAX_ED_PCT, "%", "<="
    else:
        criteria = _cup_criteria(family, size, ratio, duty, suitability)
    lubricant = duty.grease if duty.lubrication == "grease" else OIL_NAME
    criteria.append(_temperature(lubricant, duty.ambient_C, temperatures))
    statuses = {c.status for c in criteria}
    status = next(s for s in (FAIL, WARN, NOT_EVALUATED, PASS) if s in statuses or s == PASS)
    ed = next((c for c in criteria if c.name == "ED"), None)
    if ed is not None and ed.status != status:
        value = limit = None  # the row's numbers are ED's: shown only when ED decides it
        unit = sense = ""
    note = "; ".join(c.text for c in criteria)
    if duty.lubrication == "oil":
        note += "; change oil after 100 h, then every 1000 h or 6 months (seed 000 p.018)"
    margin = None if value is None else (limit - value) / limit
    return CheckResult("lubrication", "Lubrication", "lubrication", FORMULA,
               {"lubrication": Quantity(duty.lubrication), "lubricant": Quantity(lubricant),
                "ambient": Quantity(duty.ambient_C, "°C")},
               value, limit, unit, sense, status, SOURCE, note, margin,
               {"criteria": [c.__dict__ for c in criteria]})
