"""A named hysteresis as a Duhem loop whose height follows the last excursion.

Harmonic drives lose more per cycle at larger torque amplitudes (Tuttle & Seering 1996;
Taghirad & Bélanger 1998), and Dhaouadi, Ghorbel & Gandhi (2003) describe their hysteresis
by a rate-independent Duhem operator. After theirs, with a memory of the amplitude: the
loop's state w relaxes along each branch towards a height set by the excursion just made
(this height rule is ours, not theirs):

    dw/d|u| = λ·(−d·h − w),   h = (A/T0)^p,

u = T/T0 the torque over the test's largest, d the branch's direction and A half the torque
excursion of the branch that ended at its turning point (h = 0 on the first branch, from
rest; the first reversal's A is half the excursion from the record's first torque, so a
test that starts at zero torque and loads to T0 aims its second branch at 0.5^p). Between
turning points the target is fixed, so the state is exact per branch:
w = −d·h + (w_0 + d·h)·exp(−λ·|u − u_0|). A Bouc–Wen loop saturates at one height whatever
the amplitude and a Preisach loop's minor loops close on their turning points; this loop's
height is the last excursion's, a memory of one half-cycle.

References
----------
Duhem, P. (1897) "Die dauernden Aenderungen und die Thermodynamik", Z. Phys. Chem. 22.
Visintin, A. (1994) *Differential Models of Hysteresis*, Springer, ch. V (the Duhem model).
Dhaouadi, R.; Ghorbel, F. H.; Gandhi, P. S. (2003) "A new dynamic model of hysteresis in
harmonic drives", IEEE Trans. Industrial Electronics 50(6): 1165-1171.
"""

from __future__ import annotations

import numpy as np


def states(torque_Nm: np.ndarray, branches: tuple[np.ndarray, int], T0: float,
           rate: float, power: float) -> np.ndarray:
    """The loop's state w (n,) along the torque history [N·m] from rest, for a relaxation
    ``rate`` λ [per T0 of torque travelled] and a height exponent ``power`` p [-];
    ``branches`` = (turning-point rows, first direction), as for the friction elements:
    within a branch the torque is taken at its running extreme in the branch's direction
    (noise in the torque makes no minor loops)."""
    u = np.asarray(torque_Nm, dtype=float) / T0
    starts, direction = branches
    bounds = list(starts) + [len(u)]
    out = np.empty(len(u))
    w, height, before = 0.0, 0.0, u[0]
    for j, (s, e) in enumerate(zip(bounds[:-1], bounds[1:])):
        u0 = u[s]
        if j > 0:  # the height the branch that ended here sets
            height = (0.5 * abs(u0 - before)) ** power
        seg = u[s:e + 1]  # to the next turning point, where this branch ends
        travelled = np.maximum.accumulate(direction * (seg - u0))
        target = -direction * height
        branch = target + (w - target) * np.exp(-rate * travelled)
        out[s:e] = branch[:e - s]
        w, before, direction = branch[-1], u0, -direction
    return out


def loss_at_zero(amplitude_rad: float, rate: float, power: float) -> float:
    """The steady loop's width in twist at zero torque [rad] between ±T0: branches from
    ±T0 relax over one T0 of travel towards ∓1 (h = 1 at full amplitude), from the
    previous branch's end, the same by symmetry."""
    # w_end = −1 + (w_start + 1)·e^(−2λ) with w_start = −w_end (steady): w_end = −tanh(λ)
    end = -np.tanh(rate)
    at_zero = -1.0 + (-end + 1.0) * np.exp(-rate)
    return float(2.0 * abs(at_zero) * amplitude_rad)
