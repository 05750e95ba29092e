"""`gap_seal_speed`: the O-ring between the two turning FD casing halves runs slowly enough.

The halves turn against each other at the output speed in reducer use (one circular spline
held, the other the output) and at about the line-shaft speed / (R + 1) plus the adjusting
wave generator's share n_WG / R in differential use (seed 001 p.308: i_D = R/(R + 1)). The
O-ring seals on the D half's spigot Ø D_j: surface speed v = π·D_j·n / 60 000 [m/s].

References
----------
Minnesota Rubber / Quadion design guide, "Defining factors in sealing applications": slow
rotation below 50 ft/min (0.25 m/s) is dynamic duty for a standard O-ring gland.
"""

from __future__ import annotations

import math

from ..duty import Duty
from .record import CheckResult, Quantity, compared, not_evaluated
from .rules import label

TITLE = "Running-gap O-ring surface speed (FD casing halves)"
FORMULA = "v = π·D_j·n_rel / 60000 ≤ v_max"


def relative_casing_rpm(duty: Duty, ratio: float) -> tuple[float, str]:
    """Largest speed [r/min] of one casing half against the other, and how it was read."""
    if duty.use == "differential":
        n = max(abs(s.speed_rpm) / (ratio + 1) + abs(s.wave_generator_rpm) / ratio
                for s in duty.cycle)
        return n, "differential use: max over the cycle of |n_S|/(R+1) + |n_WG|/R"
    return duty.max_output_speed_rpm, "reducer use: the output speed (max_output_speed_rpm)"


def surface_speed_m_s(diameter_mm: float, rpm: float) -> float:
    """Surface speed [m/s] of a diameter [mm] turning at rpm [r/min]."""
    return math.pi * diameter_mm * rpm / 60000.0


def gap_seal_speed(journal_mm: float | None, duty: Duty, ratio: float,
                   limit_m_s: float) -> CheckResult:
    rule = label("rotary_oring_speed_m_s", limit_m_s)
    if journal_mm is None:
        return not_evaluated("gap_seal_speed", TITLE, "lubrication", FORMULA,
                             "a running-gap seal in the generated parts")
    n, how = relative_casing_rpm(duty, ratio)
    v = surface_speed_m_s(journal_mm, n)
    inputs = {"D_j": Quantity(journal_mm, "mm", "generated D half: running spigot"),
              "n_rel": Quantity(n, "r/min", how), "v_max": Quantity(limit_m_s, "m/s", rule)}
    note = (f"{how}; {rule}" + ("" if v <= limit_m_s else
            "; above it use a rotary O-ring gland (lighter squeeze, O-ring ID 1-3 % above the "
            "spigot) or a lip seal across the gap (the casing grows by the seal's section)"))
    return compared("gap_seal_speed", TITLE, "lubrication", FORMULA, inputs, v, limit_m_s,
                    "m/s", "<=", "seed 001 p.308; " + rule, note)
