"""Flexspline strength: the number of shocks the flexspline may take.

References
----------
Seed 000 p.013 (formula 013-1), p.015 (example Ns = 1190).
"""

from __future__ import annotations

from ..duty import Shock
from .load_pattern import allowed_shock_count
from .record import CheckResult, Quantity, compared, not_evaluated

SOURCE = "seed 000 p.013 (formula 013-1), p.015 (Ns ≤ 1.0×10⁴); seed 003 p.049"
FORMULA = "Ns = min(10⁴ / (2 · (ns·R/60) · ts), 1.0×10⁴);  shocks expected ≤ Ns"


def shock_count(shock: Shock | None, ratio: float) -> CheckResult:
    """Allowed number of shocks Ns [-]; passes when the duty's expected count ≤ Ns."""
    title = "Number of shocks"
    if shock is None:
        return not_evaluated("shock_count", title, "strength", FORMULA, "the duty has no shock")
    allowed = allowed_shock_count(shock.speed_rpm, shock.time_s, ratio)
    inputs = {"ns": Quantity(shock.speed_rpm, "r/min"), "ts": Quantity(shock.time_s, "s"),
              "R": Quantity(ratio, "")}
    if shock.count is None:
        return not_evaluated("shock_count", title, "strength", FORMULA,
                             "expected number of shocks", inputs, allowed, "",
                             SOURCE, "Ns is reported; add shock.count (shocks expected over "
                                     "the life) to the duty to decide",
                             {"Ns": allowed})
    inputs["shocks expected"] = Quantity(shock.count, "")
    return compared("shock_count", title, "strength", FORMULA, inputs, allowed,
                    float(shock.count), "", ">=", SOURCE,
                    "value is Ns, the allowed number of shocks; limit is the expected count",
                    {"Ns": allowed})
