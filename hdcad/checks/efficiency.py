"""Efficiency with the low-load correction factor Ke.

References
----------
Seed 000 p.023: η = Ke·ηR, α = T/Tr, Ke = 1 for α ≥ 1. Graph 023-1 survives only as one
point (α = 0.58 → Ke = 0.93, example CSF-20-80: 0.93 × 78 % = 73 %).
"""

from __future__ import annotations

from typing import Sequence


def torque_ratio(load_torque_Nm: float, rated_torque_Nm: float) -> float:
    """α = T / Tr [-]."""
    return abs(load_torque_Nm) / rated_torque_Nm


def correction_factor(alpha: float, curve: Sequence[tuple[float, float]]) -> float | None:
    """Ke at α from the catalog's (α, Ke) points; None where the curve is unknown.

    Ke = 1 for α ≥ 1 (seed 000 p.023). Between two known points Ke is interpolated
    linearly (hdcad's assumption: graph 023-1 is lost, its shape between the points is
    unknown); below the lowest known point the lost graph cannot be read, so None.
    """
    if alpha >= 1.0:
        return 1.0
    points = sorted(curve)
    for (a0, k0), (a1, k1) in zip(points, points[1:]):
        if a0 <= alpha <= a1:
            return k0 + (k1 - k0) * (alpha - a0) / (a1 - a0) if a1 > a0 else k0
    return next((k for a, k in points if a == alpha), None)


def efficiency_pct(rated_efficiency_pct: float, ke: float) -> float:
    """η = Ke·ηR [%]."""
    return ke * rated_efficiency_pct
