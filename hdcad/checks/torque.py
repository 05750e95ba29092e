"""Torque checks: average load torque, start/stop peaks, momentary (shock) torque.

References
----------
Seed 000 p.012 (rating-table terms), p.014-015 (selection flowchart and example).
"""

from __future__ import annotations

from typing import Sequence

from ..catalog import Datum
from ..duty import Segment, Shock
from .record import CheckResult, Quantity, compared, not_evaluated, quantity

FAMILY = "torque"


def avg_torque(tav_Nm: float, limit: Datum | None, rule: str = "") -> CheckResult:
    """Tav [N·m] against the allowed maximum average load torque [N·m]."""
    title, formula = "Average load torque", "Tav = ∛(Σ nᵢ·tᵢ·|Tᵢ|³ / Σ nᵢ·tᵢ) ≤ Tav,max"
    inputs = {"Tav": Quantity(tav_Nm, "N·m")}
    if limit is None:
        return not_evaluated("avg_torque", title, FAMILY, formula,
                             "allowed maximum average torque missing from the catalog" +
                             (f" ({rule})" if rule else ""), inputs, tav_Nm, "N·m")
    inputs["Tav,max"] = quantity(limit)
    return compared("avg_torque", title, FAMILY, formula, inputs, tav_Nm, float(limit),
                    "N·m", "<=", limit.source, rule)


def peak_torque(cycle: Sequence[Segment], limit: Datum | None, missing: str = "") -> CheckResult:
    """Largest start/stop segment torque |T1|, |T3| [N·m] against the allowed peak [N·m]."""
    title = "Peak torque at start and stop"
    formula = "max(|T_start|, |T_stop|) ≤ T_peak"
    peaks = [abs(s.torque_Nm) for s in cycle if s.phase in ("start", "stop")]
    value = max(peaks, default=0.0)
    inputs = {f"T{i + 1} ({s.phase})": Quantity(s.torque_Nm, "N·m")
              for i, s in enumerate(cycle) if s.phase in ("start", "stop")}
    if limit is None:
        return not_evaluated("peak_torque", title, FAMILY, formula,
                             missing or "allowed start/stop peak torque missing from the catalog",
                             inputs, value, "N·m")
    inputs["T_peak"] = quantity(limit)
    note = "" if peaks else "the cycle has no start or stop segment"
    return compared("peak_torque", title, FAMILY, formula, inputs, value, float(limit), "N·m",
                    "<=", limit.source, note)


def momentary_torque(shock: Shock | None, limit: Datum | None, rule: str = "") -> CheckResult:
    """Shock torque Ts [N·m] against the momentary maximum torque [N·m]."""
    title, formula = "Momentary (shock) torque", "Ts ≤ T_momentary"
    if shock is None:
        return not_evaluated("momentary_torque", title, FAMILY, formula,
                             "the duty has no shock", note="add shock: {torque_Nm, time_s, "
                                                           "speed_rpm} to the duty")
    inputs = {"Ts": Quantity(shock.torque_Nm, "N·m")}
    if limit is None:
        return not_evaluated("momentary_torque", title, FAMILY, formula,
                             "momentary maximum torque missing from the catalog", inputs,
                             shock.torque_Nm, "N·m")
    inputs["T_momentary"] = quantity(limit)
    return compared("momentary_torque", title, FAMILY, formula, inputs, shock.torque_Nm,
                    float(limit), "N·m", "<=", limit.source, rule)
