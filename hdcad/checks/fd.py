"""FD series (harmonic differential gear): speed-dependent ratings and differential use.

References
----------
Seed 001 p.310 (table 310-1 and its notes), p.305 (formulas 305-1 … 305-3), p.308-309
(gear-tooth selection, table 308-1, worked example FD-25-80).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from itertools import product

from ..catalog import Datum

MOMENTARY_FACTOR = 2.0  # seed 001 p.310 note 3: 200 % of the 1450 r/min rating
MOMENTARY_BASE_SPEED_RPM = 1450.0
RATING_RULE = ("FD rating at the WG speed (table 310-1): at or below 500 r/min the 500 r/min "
               "value (note 2); between listed speeds the value at the next higher listed "
               "speed (conservative: ratings fall with speed)")


def rating_at_speed(table: list[tuple[float, Datum]], speed_rpm: float
                    ) -> tuple[Datum | None, str]:
    """Rated torque at a WG speed [r/min] from (speed, torque) rows, and the rule used."""
    listed = sorted((s, d) for s, d in table)
    if not listed:
        return None, "no rows in table 310-1 for this model"
    speed = max(speed_rpm, listed[0][0])
    for listed_speed, datum in listed:
        if listed_speed >= speed:
            return datum, f"{RATING_RULE}: {listed_speed:g} r/min row used"
    return None, (f"{speed_rpm:g} r/min is above the highest speed rated for this model in "
                  f"table 310-1 ({listed[-1][0]:g} r/min)")


def momentary_allowance(table: list[tuple[float, Datum]]) -> Datum | None:
    """Momentary torque [N·m] = 200 % of the 1450 r/min rating (table 310-1 note 3)."""
    for speed, datum in table:
        if speed == MOMENTARY_BASE_SPEED_RPM:
            return Datum(MOMENTARY_FACTOR * float(datum), "Nm",
                         f"{datum.source}, note 3 (200 % of the 1450 r/min value)")
    return None


def phase_adjustment_deg(z1: int, z2: int, ratio: float, wg_turn_deg: float = 360.0) -> float:
    """Output phase change Δθ [deg] for a WG turn: Δθ = (Z2/Z1)·(1/R)·θ. Seed 001 p.309."""
    return z2 / z1 / ratio * wg_turn_deg


def arc_length_mm(angle_deg: float, circumference_mm: float) -> float:
    """Circumferential adjustment [mm] on a roller of the given circumference."""
    return angle_deg / 360.0 * circumference_mm


def adjustment_torque(roller_torque: float, z1: int, z2: int, ratio: float,
                      efficiency: float) -> float:
    """Torque on the adjusting WG: T = Tw·(Z2/Z1)·(1/R)·(1/η), in the unit of Tw."""
    return roller_torque * z2 / z1 / ratio / efficiency


def differential_ratio(ratio: int) -> Fraction:
    """i_D = Z_D/Z_S = R/(R+1) (seed 001 p.308)."""
    return Fraction(ratio, ratio + 1)


@dataclass(frozen=True)
class GearTrain:
    z1: int
    z2: int
    z3: int
    z4: int

    @property
    def total_teeth(self) -> int:
        return self.z1 + self.z2 + self.z3 + self.z4


def select_teeth(output_speed: Fraction | float, input_speed: Fraction | float, ratio: int,
                 min_teeth: int = 16, max_teeth: int = 120) -> GearTrain:
    """Tooth counts Z1…Z4 for a drive speed N1 and a roller speed N4 (seed 001 p.309).

    The train is Z4 → Z3 → differential (C_S/C_D = (R+1)/R) → Z2 → Z1, so
    N4/N1 = (Z4/Z3)·((R+1)/R)·(Z2/Z1) and (Z2·Z4)/(Z1·Z3) = (N4/N1)·R/(R+1) exactly. Among all trains with every Z in
    [min_teeth, max_teeth] the one with the fewest teeth in total is chosen; ties go to the
    most even split of the two stages. The stage nearer 1:1 is Z2/Z1. The default
    min_teeth = 16 is the smallest tooth count in the seed's worked example, which this
    rule reproduces (Z1..Z4 = 30, 16, 36, 16 for 500 → 120 r/min with R = 80).
    """
    target = Fraction(output_speed) / Fraction(input_speed) * differential_ratio(ratio)
    best: tuple | None = None
    span = range(min_teeth, max_teeth + 1)
    for z2, z4 in product(span, span):
        if z4 < z2:
            continue  # symmetric: stages are ordered afterwards
        denominator = Fraction(z2 * z4) / target  # = Z1·Z3
        if denominator.denominator != 1:
            continue
        product_13 = denominator.numerator
        for z1 in span:
            if product_13 % z1:
                continue
            z3 = product_13 // z1
            if not min_teeth <= z3 <= max_teeth:
                continue
            stages = (Fraction(z2, z1), Fraction(z4, z3))
            key = (z1 + z2 + z3 + z4, abs(math.log(stages[0] / stages[1])))
            if best is None or key < best[0]:
                best = (key, (z1, z2, z3, z4))
    if best is None:
        raise ValueError(f"no gear train with teeth in [{min_teeth}, {max_teeth}] gives "
                         f"N4/N1 = {Fraction(output_speed) / Fraction(input_speed)}")
    z1, z2, z3, z4 = best[1]
    if abs(math.log(z2 / z1)) > abs(math.log(z4 / z3)):  # stage nearer 1:1 first
        z1, z2, z3, z4 = z3, z4, z1, z2
    return GearTrain(z1, z2, z3, z4)
