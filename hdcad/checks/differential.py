"""FD in differential use: relative speeds, and the phase adjuster's gear train and torque.

In differential use the line shaft turns the circular spline S (each segment's ``speed_rpm``)
and the wave generator is the adjusting input (``wave_generator_rpm``, 0 = held). The FD
ratings (table 310-1), speed limits (313-3/313-4) and the wave-generator life are given for
the speed of the wave generator relative to the circular spline, |n_WG − n_S| (seed 001
p.310). An ``adjustment`` block sizes the phase adjuster of seed 001 pp.308-309: tooth
counts Z1…Z4 for the drive shaft N1 and the roller N4, the phase change per turn of the
wave generator Δθ = (Z2/Z1)·(1/R)·360°, and the torque the adjusting drive needs,
T = Tw·(Z2/Z1)·(1/R)·(1/η).

References
----------
Seed 001 p.308 (table 308-1, i_D = R/(R+1)), p.309 (worked example FD-25-80: Z1..Z4 = 30,
16, 36, 16; Δθ = 2.4° = 3.3 mm on a 500 mm roller; T = 0.07 kgf·m), p.310 (ratings by
relative speed).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Sequence

from ..duty import Adjustment, Duty, Segment
from .fd import adjustment_torque, arc_length_mm, differential_ratio, phase_adjustment_deg, \
    select_teeth
from .record import CheckResult, Quantity, compared, not_evaluated
from .rules import label

FAMILY = "adjustment"
SOURCE = "seed 001 pp.308-309 (gear-tooth selection, worked example FD-25-80)"


def relative_speed_rpm(segment: Segment) -> float:
    """|n_WG − n_S| [r/min]: wave generator against the circular spline S."""
    return abs(segment.wave_generator_rpm - segment.speed_rpm)


def relative_speeds(cycle: Sequence[Segment]) -> dict[str, float]:
    """Time-weighted average, loaded (moving segments only) and largest relative speed."""
    total = sum(s.time_s for s in cycle)
    moving = [s for s in cycle if relative_speed_rpm(s) > 0]
    return {"avg": sum(relative_speed_rpm(s) * s.time_s for s in cycle) / total,
            "loaded": (sum(relative_speed_rpm(s) * s.time_s for s in moving) /
                       sum(s.time_s for s in moving)) if moving else 0.0,
            "max": max(relative_speed_rpm(s) for s in cycle)}


def adjustment_checks(duty: Duty, ratio: int, efficiency: float) -> list[CheckResult]:
    """Gear train, phase adjustment per WG turn and adjustment torque of the adjuster."""
    adj = duty.adjustment
    if adj is None:
        return []
    try:
        train = select_teeth(Fraction(str(adj.roller_speed_rpm)),
                             Fraction(str(adj.drive_speed_rpm)), ratio, adj.min_teeth,
                             adj.max_teeth)
    except ValueError as exc:
        return [not_evaluated("fd_gear_train", "Gear train of the phase adjuster", FAMILY,
                              "(Z2·Z4)/(Z1·Z3) = (N4/N1)·R/(R+1)", f"a gear train: {exc}",
                              source=SOURCE)]
    return [_train(adj, ratio, train), _phase(adj, ratio, train),
            _torque(adj, ratio, train, efficiency)]


def _train(adj: Adjustment, ratio: int, train) -> CheckResult:
    n3 = adj.drive_speed_rpm * train.z4 / train.z3
    n2 = n3 / float(differential_ratio(ratio))
    achieved = n2 * train.z2 / train.z1
    error = abs(achieved - adj.roller_speed_rpm) / adj.roller_speed_rpm
    error = 0.0 if error < 1e-12 else error  # exact ratio: float round-off only
    inputs = {"N1": Quantity(adj.drive_speed_rpm, "r/min"),
              "N4 wanted": Quantity(adj.roller_speed_rpm, "r/min"), "R": Quantity(ratio, ""),
              "Z1, Z2, Z3, Z4": Quantity(f"{train.z1}, {train.z2}, {train.z3}, {train.z4}", ""),
              "N3 = N1·Z4/Z3": Quantity(n3, "r/min"),
              "N2 = N3·(R+1)/R": Quantity(n2, "r/min"), "N4 achieved": Quantity(achieved, "r/min")}
    return compared("fd_gear_train", "Gear train of the phase adjuster", FAMILY,
                    "(Z2·Z4)/(Z1·Z3) = (N4/N1)·R/(R+1); |N4,achieved − N4|/N4 ≤ 10⁻⁶",
                    inputs, error, 1e-6, "", "<=", SOURCE,
                    f"Z1 = {train.z1}, Z2 = {train.z2}, Z3 = {train.z3}, Z4 = {train.z4} "
                    f"(fewest teeth in [{adj.min_teeth}, {adj.max_teeth}]); N3 = {n3:.1f}, "
                    f"N2 = {n2:.1f} r/min",
                    {"Z": [train.z1, train.z2, train.z3, train.z4], "N2_rpm": n2, "N3_rpm": n3})


def _phase(adj: Adjustment, ratio: int, train) -> CheckResult:
    angle = phase_adjustment_deg(train.z1, train.z2, ratio)
    inputs = {"Z2/Z1": Quantity(train.z2 / train.z1, ""), "R": Quantity(ratio, "")}
    note = f"Δθ = {angle:.3g}° per turn of the wave generator"
    if adj.roller_circumference_mm:
        arc = arc_length_mm(angle, adj.roller_circumference_mm)
        inputs["Lw"] = Quantity(adj.roller_circumference_mm, "mm")
        note += f" = {arc:.2g} mm on the roller"
    if adj.total_phase_deg:
        turns = adj.total_phase_deg / angle
        inputs["total phase wanted"] = Quantity(adj.total_phase_deg, "deg")
        note += (f"; a {adj.total_phase_deg:g}° phase shift takes {turns:.3g} turns of the "
                 "wave generator")
    title, formula = "Phase adjustment per WG turn", "Δθ = (Z2/Z1)·(1/R)·360° ≤ Δθ wanted"
    if adj.max_adjust_per_turn_deg is None:
        return not_evaluated("fd_phase_adjustment", title, FAMILY, formula,
                             "the wanted adjustment per turn (adjustment.max_adjust_per_turn_"
                             "deg)", inputs, angle, "deg", SOURCE, note)
    return compared("fd_phase_adjustment", title, FAMILY, formula, inputs, angle,
                    adj.max_adjust_per_turn_deg, "deg", "<=", SOURCE, note)


def _torque(adj: Adjustment, ratio: int, train, efficiency: float) -> CheckResult:
    title, formula = "Torque of the adjusting drive", "T = Tw·(Z2/Z1)·(1/R)·(1/η) ≤ T_drive"
    if adj.roller_torque_Nm is None:
        return not_evaluated("fd_adjustment_torque", title, FAMILY, formula,
                             "the roller torque Tw (adjustment.roller_torque_Nm)", source=SOURCE)
    torque = adjustment_torque(adj.roller_torque_Nm, train.z1, train.z2, ratio, efficiency)
    inputs = {"Tw": Quantity(adj.roller_torque_Nm, "N·m"),
              "Z2/Z1": Quantity(train.z2 / train.z1, ""), "R": Quantity(ratio, ""),
              "η": Quantity(efficiency, "", label("adjustment_efficiency", efficiency))}
    note = (f"η = {efficiency:g}: the worked example's value; "
            f"{label('adjustment_efficiency', efficiency)}")
    if adj.drive_torque_Nm is None:
        return not_evaluated("fd_adjustment_torque", title, FAMILY, formula,
                             "the adjusting drive's torque (adjustment.drive_torque_Nm)", inputs,
                             torque, "N·m", SOURCE, note)
    return compared("fd_adjustment_torque", title, FAMILY, formula, inputs, torque,
                    adj.drive_torque_Nm, "N·m", "<=", SOURCE, note)
