"""Speed checks: ratio against the motor speed, average and maximum input speed.

References
----------
Seed 000 p.014-015: ni_max/no_max ≥ R, ni_av = no_av·R, ni_max = no_max·R.
"""

from __future__ import annotations

from ..catalog import Datum
from .record import CheckResult, Quantity, compared, not_evaluated, quantity

FAMILY = "speed"
SELECTION_SOURCE = "seed 000 p.014 (selection flowchart)"


def ratio_limit(motor_max_rpm: float, max_output_rpm: float, ratio: float) -> CheckResult:
    """The motor can reach the maximum output speed: ni_max,motor / no_max ≥ R [-]."""
    value = motor_max_rpm / max_output_rpm
    inputs = {"ni_max (motor)": Quantity(motor_max_rpm, "r/min"),
              "no_max": Quantity(max_output_rpm, "r/min"), "R": Quantity(ratio, "")}
    return compared("ratio_limit", "Ratio against motor speed", FAMILY,
                    "ni_max / no_max ≥ R", inputs, value, float(ratio), "", ">=",
                    SELECTION_SOURCE)


def avg_input_speed(ni_av_rpm: float, limit: Datum | None, missing: str = "") -> CheckResult:
    """Average input speed ni_av [r/min] against the allowed average input speed."""
    title, formula = "Average input speed", "ni_av = no_av·R ≤ ni_av,allowed"
    inputs = {"ni_av": Quantity(ni_av_rpm, "r/min")}
    if limit is None:
        return not_evaluated("avg_input_speed", title, FAMILY, formula,
                             missing or "allowed average input speed missing from the catalog",
                             inputs, ni_av_rpm, "r/min")
    inputs["ni_av,allowed"] = quantity(limit)
    return compared("avg_input_speed", title, FAMILY, formula, inputs, ni_av_rpm, float(limit),
                    "r/min", "<=", limit.source)


def max_input_speed(ni_max_rpm: float, limit: Datum | None, rule: str = "") -> CheckResult:
    """Maximum input speed ni_max = no_max·R [r/min] against the allowed maximum."""
    title, formula = "Maximum input speed", "ni_max = no_max·R ≤ ni_max,allowed"
    inputs = {"ni_max": Quantity(ni_max_rpm, "r/min")}
    if limit is None:
        return not_evaluated("max_input_speed", title, FAMILY, formula,
                             "allowed maximum input speed missing from the catalog", inputs,
                             ni_max_rpm, "r/min")
    inputs["ni_max,allowed"] = quantity(limit)
    return compared("max_input_speed", title, FAMILY, formula, inputs, ni_max_rpm, float(limit),
                    "r/min", "<=", limit.source, rule)


# seed 003, note 6 of tables 050-1/058-1: the allowed maximum input speed is for
# non-continuous running; for continuous running take 3000 r/min or less as the guide
GH_CONTINUOUS_GUIDE_RPM = 3000.0
GH_CONTINUOUS_SOURCE = "seed 003 tables 050-1/058-1, note 6 (p.050/058)"


def continuous_input_speed(cycle, ratio: float) -> CheckResult:
    """Gear heads: input speed of the steady segments [r/min] against the 3000 r/min guide
    for continuous running. Beyond it the check warns (a guide, not a rating)."""
    from .record import PASS, WARN
    steady = [s for s in cycle if s.phase == "steady"] or list(cycle)
    speed = max(s.speed_rpm for s in steady) * ratio
    inputs = {"n steady (output)": Quantity(max(s.speed_rpm for s in steady), "r/min"),
              "R": Quantity(ratio, ""),
              "guide": Quantity(GH_CONTINUOUS_GUIDE_RPM, "r/min", GH_CONTINUOUS_SOURCE)}
    result = compared("continuous_input_speed", "Continuous input speed (gear head)", FAMILY,
                      "ni,steady = n_steady·R ≤ 3000 r/min (guide for continuous running)",
                      inputs, speed, GH_CONTINUOUS_GUIDE_RPM, "r/min", "<=",
                      GH_CONTINUOUS_SOURCE)
    if result.status != PASS:
        result.status = WARN
        result.note = ("above the catalog's guide for continuous running (the allowed "
                       "maximum input speed is for non-continuous running): confirm with "
                       "Harmonic Drive")
    return result
