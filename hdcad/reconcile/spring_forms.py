"""The twist of a spring in series with the gear (housing, shafts, bolted joints, fixtures):
linear, one that stiffens as contact closes, and one whose joint opens and softens. Each is
the twist per unit compliance, so its compliance enters the model as an amplitude.
"""

from __future__ import annotations

import math

import numpy as np


def compliance_twist(torque_Nm: np.ndarray, stiffness_Nm_per_rad: float) -> np.ndarray:
    """Twist of an extra spring in series [rad]: T/K_h (housing, shafts, fixtures)."""
    return torque_Nm / stiffness_Nm_per_rad


def progressive_twist(torque_Nm: np.ndarray, knee_Nm: float) -> np.ndarray:
    """Twist per unit low-torque compliance [rad·N·m/rad = N·m] of a series spring that
    stiffens: k·θ + k·θ³/θ_k² = T (a Duffing spring; contact that closes gradually,
    bolted joints), written θ = (1/k)·T_k·u with u + u³ = T/T_k, T_k = k·θ_k the torque
    where the cubic term equals the linear one. Solved by Cardano's formula; T_k = ∞ is the
    linear spring T/k.

    References: Rivin, E. I. (1999) *Stiffness and Damping in Mechanical Design*, Marcel
    Dekker, ch. 4 (contact deformations: stiffness that grows with load).
    """
    if not math.isfinite(knee_Nm):
        return np.asarray(torque_Nm, dtype=float)
    x = np.abs(torque_Nm) / knee_Nm
    a = np.cbrt(0.5 * x + np.sqrt(0.25 * x * x + 1.0 / 27.0))
    return np.sign(torque_Nm) * knee_Nm * (a - 1.0 / (3.0 * a))


def opening_twist(torque_Nm: np.ndarray, opening_Nm: float) -> np.ndarray:
    """sign(T)·max(|T| − T_o, 0) [N·m]: times a compliance, the twist a bolted joint adds
    once the torque opens it (past T_o its clamped interface separates at the edge and the
    joint softens: bilinear in torque).

    References: VDI 2230 Part 1 (2015), opening limit of a bolted joint under an eccentric
    load; Rivin, E. I. (1999) *Stiffness and Damping in Mechanical Design*, ch. 4.
    """
    t = np.asarray(torque_Nm, dtype=float)
    return np.sign(t) * np.maximum(np.abs(t) - opening_Nm, 0.0)
