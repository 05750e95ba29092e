"""Wave-generator thrust force (cup-type gears).

References
----------
Seed 000 p.027, tables 027-3/027-4 and example 027-1: F = 2·(T/D)·0.07·tan β,
D = size·0.00254 m, β = 32° (R = 30), 30° (R = 50), 20° (R ≥ 80). CSF-32-50 at its
momentary maximum torque 382 N·m → 380 N.
"""

from __future__ import annotations

import math

from ..catalog import Datum
from .record import CheckResult, Quantity, compared, not_evaluated, quantity

FORMULA = "F = 2·(T/D)·0.07·tan β,  D = size·0.00254 m"
TITLE = "Wave-generator thrust force"


def thrust_angle(ratio: int, rows: list[dict]) -> float | None:
    """β [deg] for a ratio from table 027-3 rows (ratio_min, ratio_max, beta_deg)."""
    for row in rows:
        high = row.get("ratio_max")
        if row["ratio_min"] <= ratio and (high is None or ratio <= high):
            return float(row["beta_deg"])
    return None


def wg_thrust_force(torque_Nm: float, size: int, beta_deg: float) -> float:
    """Maximum thrust force on the wave generator F [N] at output torque T [N·m]."""
    diameter_m = size * 0.00254
    return 2.0 * (abs(torque_Nm) / diameter_m) * 0.07 * math.tan(math.radians(beta_deg))


GUIDELINE = ("design guideline 2 (seed 000 p.024): the input shaft must carry this thrust, "
             "towards the diaphragm when reducing")
SHAFT_CAPACITY = "axial capacity of the input-shaft support (give it in the design options)"


def thrust_force(torque_Nm: float, size: int, beta: Datum | None, applies: str = "",
                 capacity_N: float | None = None,
                 missing_capacity: str = SHAFT_CAPACITY) -> CheckResult:
    """Thrust force [N] at the largest duty torque against the input-side axial capacity.

    ``applies`` is '' for a cup-type gear; otherwise the reason the formula does not apply.
    """
    inputs = {"T": Quantity(torque_Nm, "N·m"), "size": Quantity(size, "")}
    if applies:
        return not_evaluated("thrust_force", TITLE, "thrust", FORMULA, applies, inputs)
    if beta is None:
        return not_evaluated("thrust_force", TITLE, "thrust", FORMULA,
                             "thrust angle β for this ratio missing from table 027-3", inputs)
    inputs["β"] = quantity(beta)
    force = wg_thrust_force(torque_Nm, size, float(beta))
    if capacity_N is None:
        return not_evaluated(
            "thrust_force", TITLE, "thrust", FORMULA,
            missing_capacity, inputs, force, "N", beta.source,
            GUIDELINE if missing_capacity == SHAFT_CAPACITY else "")
    return compared("thrust_force", TITLE, "thrust", FORMULA, inputs, force, capacity_N, "N",
                    "<=", beta.source)
