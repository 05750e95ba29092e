"""Load-torque pattern: average torque, average speeds, allowed shock count.

References
----------
Seed 000 pp.013-015 (model selection flowchart and the CSF-40-120 example); seed 003
pp.044-049 (CSF-45-120-GH example).
"""

from __future__ import annotations

from typing import Sequence

from ..duty import Segment

FLEXSPLINE_FLEX_LIMIT = 1.0e4  # seed 000 p.013: flexing count limit during shock torque [-]


def average_torque(cycle: Sequence[Segment]) -> float:
    """Average load torque on the output side, Tav [N·m].

    Tav = ∛( Σ nᵢ·tᵢ·|Tᵢ|³ / Σ nᵢ·tᵢ ), nᵢ output speed [r/min], tᵢ time [s], Tᵢ torque [N·m].
    Segments at standstill carry no weight (nᵢ·tᵢ = 0). Seed 000 p.014.
    """
    weight = sum(s.speed_rpm * s.time_s for s in cycle)
    if weight <= 0:
        raise ValueError("the cycle has no moving segment")
    return (sum(s.speed_rpm * s.time_s * abs(s.torque_Nm) ** 3 for s in cycle) / weight) ** (1 / 3)


def average_output_speed(cycle: Sequence[Segment]) -> float:
    """Average output speed no_av = Σ nᵢ·tᵢ / Σ tᵢ [r/min], rest segments included.

    Seed 000 p.015: 46.9 / 3.9 = 12 r/min (seed 003 prints a 3.7 s denominator but its
    12 r/min result uses 3.9 s).
    """
    return sum(s.speed_rpm * s.time_s for s in cycle) / sum(s.time_s for s in cycle)


SHOCK_COUNT_CAP = 1.0e4  # the allowed number of shocks never exceeds 10⁴


def allowed_shock_count(shock_speed_rpm: float, shock_time_s: float, ratio: float) -> float:
    """Allowed number of shocks Ns = 10⁴ / (2 · (ns·R/60) · ts) [-].

    The flexspline flexes twice per wave-generator revolution; the flexing count during
    shocks is limited to 1.0×10⁴. ns output speed [r/min], ts shock duration [s], R ratio.
    Capped at Ns ≤ 1.0×10⁴. Seed 000 p.013 (formula 013-1) and p.015 (example: Ns = 1190,
    the cap); seed 003 p.049.
    """
    flexings_per_shock = 2.0 * shock_speed_rpm * ratio / 60.0 * shock_time_s
    # Ns ≤ 1.0×10⁴ (seed 000 p.015, seed 003 p.049): a very short or slow shock does not
    # allow more than ten thousand shocks
    return min(FLEXSPLINE_FLEX_LIMIT / flexings_per_shock, SHOCK_COUNT_CAP)
