"""Wave-generator life.

References
----------
Seed 000 p.012 (table 012-1, formula 012-1): Lh = Ln·(Tr/Tav)³·(Nr/Nav), Ln = L10 or L50
base life of the series, Tr rated torque, Nr = 2000 r/min rated input speed, Tav average
output torque, Nav average input speed. Example CSF-40-120: 7,610 h (seed 000 p.015);
CSF-45-120-GH: 19,457 h (seed 003 p.049). Seed 003 prints (Tr³/Tav) in its flowchart; its
own example uses (Tr/Tav)³.
"""

from __future__ import annotations

from ..catalog import Datum
from .record import CheckResult, Quantity, compared, not_evaluated, quantity

FORMULA = "L10 = Ln·(Tr/Tav)³·(Nr/ni_av);  L50 = L50,base·(Tr/Tav)³·(Nr/ni_av)"


def life_hours(base_life_h: float, rated_torque_Nm: float, tav_Nm: float,
               rated_speed_rpm: float, avg_input_speed_rpm: float) -> float:
    """Wave-generator life Lh [h] from the base life Ln [h] at Tr [N·m] and Nr [r/min]."""
    return base_life_h * (rated_torque_Nm / tav_Nm) ** 3 * (rated_speed_rpm / avg_input_speed_rpm)


def wg_life(tav_Nm: float, ni_av_rpm: float, required_h: float, rated_torque: Datum | None,
            rated_speed: Datum | None, l10: Datum | None, l50: Datum | None) -> CheckResult:
    """L10 wave-generator life [h] against the required life [h]; L50 reported in details."""
    title = "Wave-generator life (L10)"
    inputs = {"Tav": Quantity(tav_Nm, "N·m"), "ni_av": Quantity(ni_av_rpm, "r/min"),
              "required L10": Quantity(required_h, "h")}
    missing = [name for name, d in (("rated torque Tr", rated_torque),
                                    ("rated input speed Nr", rated_speed),
                                    ("base life L10 of the series (table 012-1)", l10))
               if d is None]
    if missing:
        return not_evaluated("wg_life", title, "life", FORMULA, ", ".join(missing) +
                             " missing from the catalog", inputs, unit="h")
    inputs.update({"Tr": quantity(rated_torque), "Nr": quantity(rated_speed),
                   "Ln (L10)": quantity(l10)})
    if tav_Nm <= 0:
        return compared("wg_life", title, "life", FORMULA, inputs, float("inf"), required_h,
                        "h", ">=", l10.source, "no load torque: life not limited by load")
    terms = (float(rated_torque), tav_Nm, float(rated_speed), ni_av_rpm)
    l10_h = life_hours(float(l10), *terms)
    details = {"L10_h": l10_h}
    if l50 is not None:
        inputs["Ln (L50)"] = quantity(l50)
        details["L50_h"] = life_hours(float(l50), *terms)
    note = f"L50 = {details['L50_h']:,.0f} h" if "L50_h" in details else ""
    return compared("wg_life", title, "life", FORMULA, inputs, l10_h, required_h, "h", ">=",
                    f"{l10.source}; rating {rated_torque.source}", note, details)
