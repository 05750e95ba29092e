"""The user's motor on a GH gear head: which flange code takes it, whether an adapter plate is
needed, and whether its shaft still reaches the input coupling.

Seed 003 tables 053-1 … 064-1 give per flange code the motor side only (pilot A, depth B,
bolt circle C, thread D, square E, coupling bore F). The coupling's engagement length (how far
the motor shaft must reach from the flange's motor face) is on the delivery drawing, not in
the seeds: the reach check needs it in the overlay column ``gh_motor_flange.shaft_engagement_mm``.
"""

from __future__ import annotations

from .record import PASS, CheckResult, Quantity, compared, not_evaluated

SOURCE = "seed 003 tables 053-1 … 064-1 (motor side of each flange code)"


def motor_fit(row: dict, mismatch: list[str], motor: dict) -> CheckResult:
    """Which code to order and whether an adapter plate is needed (informative, pass)."""
    code = row["flange_code"]
    inputs = {"motor pilot": Quantity(motor["pilot_diameter_mm"], "mm", "design option motor"),
              "motor bolt circle": Quantity(motor["bolt_circle_mm"], "mm",
                                            "design option motor"),
              "motor shaft": Quantity(motor["shaft_diameter_mm"], "mm", "design option motor"),
              "A": Quantity(row["pilot_H7_mm"], "mm", SOURCE),
              "C": Quantity(row["bolt_circle_mm"], "mm", SOURCE),
              "F": Quantity(row["coupling_bore_max_mm"], "mm", SOURCE)}
    if not mismatch:
        note = (f"the motor bolts straight onto flange code {code}: order the gear head with "
                f"{code}; no adapter plate is needed")
    else:
        note = (f"no flange code fits the motor directly; nearest {code} (its coupling takes the "
                f"Ø{motor['shaft_diameter_mm']:g} shaft): " + "; ".join(mismatch)
                + f". Order {code} and fit the generated motor_adapter plate")
    return CheckResult("motor_fit", "Motor on the gear head's flange code", "geometry",
                       "A = pilot, C = bolt circle, D = thread, F_min ≤ shaft ≤ F_max", inputs,
                       float(len(mismatch)), None, "", "", PASS, SOURCE, note, None,
                       {"flange_code": code, "adapter": bool(mismatch), "mismatch": mismatch})


def motor_shaft_reach(row: dict, motor: dict, shift_mm: float) -> CheckResult:
    """Shaft length left at the flange face after the plate moved the motor back ≥ the
    coupling's engagement length (overlay)."""
    title, formula = "Motor shaft reach into the input coupling", "L_shaft − t_plate ≥ L_engage"
    inputs = {"L_shaft": Quantity(motor["shaft_length_mm"], "mm", "design option motor"),
              "t_plate": Quantity(shift_mm, "mm", "generated motor_adapter")}
    need = row.get("shaft_engagement_mm")
    if need is None:
        return not_evaluated("motor_shaft_reach", title, "geometry", formula,
                             "the coupling's engagement length (overlay column "
                             "gh_motor_flange.shaft_engagement_mm, from the delivery drawing "
                             f"of flange {row['flange_code']})", inputs,
                             motor["shaft_length_mm"] - shift_mm, "mm", SOURCE,
                             note=f"the plate moves the motor {shift_mm:g} mm back: the shaft "
                                  f"reaches {motor['shaft_length_mm'] - shift_mm:g} mm beyond "
                                  "the flange face")
    inputs["L_engage"] = Quantity(need, "mm", "overlay gh_motor_flange")
    return compared("motor_shaft_reach", title, "geometry", formula, inputs,
                    motor["shaft_length_mm"] - shift_mm, need, "mm", ">=", SOURCE)


MOUNTING_FIELDS = ("pilot_diameter_mm", "pilot_kind", "pilot_depth_mm", "bolt_circle_mm",
                   "bolt_count", "bolt_thread")


def gh_mounting_plate(catalog_has_interface: bool, plate: dict | None = None
                      ) -> CheckResult:
    """The gear head's mounting plate on the machine needs the gear head's own mounting
    interface (output-side pilot and bolt pattern), which the seeds do not give. Built from
    the overlay, the check reports how far the corner screws' heads [mm] stand clear of the
    gear head's outline (they must be reachable with the gear head fitted); the screws'
    torque capacity is in the plate's bolt_pattern records."""
    title = "Mounting plate of the gear head on the machine"
    formula = "corner head clearance = a·√2 − outline/2 − head/2 ≥ 1 mm"
    if not catalog_has_interface or plate is None:
        return not_evaluated("gh_mounting_plate", title, "geometry", formula,
                             "the gear head's mounting interface (overlay table "
                             "gh_mounting_interface: " + ", ".join(MOUNTING_FIELDS)
                             + "); the seeds' outline figures 050/058 are lost",
                             source="seed 003 (outline drawings not in the text)")
    a, outline, head = (plate["corner_hole_offset_mm"], plate["gear_head_outline_mm"],
                        plate["head_diameter_mm"])
    inputs = {"a": Quantity(a, "mm", "generated plate"),
              "outline": Quantity(outline, "mm", "overlay gh_mounting_interface"),
              "head": Quantity(head, "mm", "ISO 4762")}
    return compared("gh_mounting_plate", title, "geometry", formula, inputs,
                    a * 2 ** 0.5 - outline / 2 - head / 2, 1.0, "mm", ">=",
                    "overlay gh_mounting_interface; HOUSING_RULES §4",
                    f"plate □{plate['square_mm']:g} × {plate['thickness_mm']:g} built from the "
                    "overlay; its screw patterns are checked as bolt_pattern records")
