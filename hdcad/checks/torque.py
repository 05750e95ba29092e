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
    """Largest torque of the normal operating cycle |Tᵢ| [N·m] against the repeated peak.

    Every segment of the normal cycle counts (start, steady, stop): the repeated peak torque
    bounds the whole operating pattern, while the momentary torque is for abnormal shocks
    only (seed 000 p.012, rating terms; p.014 flowchart). The governing segment is named.
    """
    title = "Peak torque of the operating cycle"
    formula = "max over the cycle of |Tᵢ| ≤ T_peak"
    inputs = {f"T{i + 1} ({s.phase})": Quantity(s.torque_Nm, "N·m")
              for i, s in enumerate(cycle)}
    governing = max(range(len(cycle)), key=lambda i: abs(cycle[i].torque_Nm))
    value = abs(cycle[governing].torque_Nm)
    details = {"governing_segment": governing, "phase": cycle[governing].phase}
    if limit is None:
        return not_evaluated("peak_torque", title, FAMILY, formula,
                             missing or "allowed peak torque missing from the catalog",
                             inputs, value, "N·m", details=details)
    inputs["T_peak"] = quantity(limit)
    return compared("peak_torque", title, FAMILY, formula, inputs, value, float(limit), "N·m",
                    "<=", limit.source, f"governing: segment {governing + 1} "
                    f"({cycle[governing].phase}), |T| = {value:g} N·m", details)


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
