"""A named hysteresis as a viscoelastic loop: creep elements (standard linear solids) with
relaxation times spread over the record, weighted freely, in place of the friction loop
found so far or beside it.

A standard linear solid (Zener) loaded by a torque T twists J_u·T at once and creeps
towards its relaxed twist J_r·T = (J_u + c)·T with a relaxation time τ: θ = J_r·T +
c·(T_τ − T), where T_τ is the torque passed through a first-order lag of time constant τ
(τ·dT_τ/dt = T − T_τ). The catalog's curve is measured slowly, the relaxed curve, so each
element adds c_k·(T_τk − T), c_k ≥ 0: the twist lags the torque on loading and unloading
alike, a loop whose width grows with the loading rate (a friction loop's does not). The
delayed compliances enter linearly, so a spectrum of relaxation times (a Prony series) is
fitted by bounded linear least squares over fixed τ_k, without a shape search, as the
friction elements of :mod:`.plays` are.

The record's time is its ``time_s`` column when the file has one (τ in seconds); else its
rows are taken as equally spaced in time (a logger's fixed sampling rate) and τ is given in
rows. The lag is integrated exactly for a torque linear between rows (first-order hold).

References
----------
Zener, C. (1948) *Elasticity and Anelasticity of Metals*, University of Chicago Press.
Findley, W. N.; Lai, J. S.; Onaran, K. (1976) *Creep and Relaxation of Nonlinear
Viscoelastic Materials*, North-Holland, ch. 5 (the standard linear solid, Prony series).
Franklin, G. F.; Powell, J. D.; Workman, M. L. (1998) *Digital Control of Dynamic Systems*,
3rd ed., Addison-Wesley, sec. 6.3 (triangle-hold equivalent of a first-order lag).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.signal import lfilter, lfilter_zi

# relaxation times: from one step of the record to half its span, this many per decade (an
# element slower than that creeps through the whole test, the catalog curve's own scale)
PER_DECADE = 3
LONGEST_SHARE = 0.5


def clock(n_rows: int, time_s: np.ndarray | None = None) -> np.ndarray:
    """The record's time: its ``time_s`` [s] when the file has one, else the row [rows]."""
    return np.arange(float(n_rows)) if time_s is None else np.asarray(time_s, dtype=float)


def relaxation_times(time: np.ndarray) -> np.ndarray:
    """The elements' relaxation times, in the unit of ``time`` (:func:`clock`): from its
    median step (of those that advance) to ``LONGEST_SHARE`` of the record's span (the last
    step counted)."""
    steps = np.diff(time)
    step = float(np.median(steps[steps > 0])) if np.any(steps > 0) else 1.0
    longest = max(LONGEST_SHARE * (float(np.ptp(time)) + step), step)
    count = max(int(math.ceil(PER_DECADE * math.log10(longest / step))) + 1, 1)
    return np.geomspace(step, longest, count)


def record_taus(n_rows: int, time_s: np.ndarray | None = None) -> tuple[np.ndarray, str]:
    """The relaxation times of a record of ``n_rows`` and their unit: seconds when it has a
    ``time_s`` column, else rows."""
    return relaxation_times(clock(n_rows, time_s)), "rows" if time_s is None else "s"


def lagged(torque_Nm: np.ndarray, tau_rows: float) -> np.ndarray:
    """T_τ [N·m]: the torque through a first-order lag of ``tau_rows``, at rest at the first
    row, integrated exactly for a torque linear between equally spaced rows."""
    u = np.asarray(torque_Nm, dtype=float)
    a = math.exp(-1.0 / tau_rows)
    g = tau_rows * (1.0 - a)
    b, den = [1.0 - g, g - a], [1.0, -a]
    out, _ = lfilter(b, den, u, zi=lfilter_zi(b, den) * u[0])
    return out


def _lagged_uneven(torque_Nm: np.ndarray, taus: np.ndarray, steps: np.ndarray) -> np.ndarray:
    """(n × K) [N·m]: the torque through first-order lags of ``taus`` over uneven
    ``steps`` (the same exact step as :func:`lagged`, one row at a time; a step of 0, a
    logger's repeated sample, leaves the lag where it was)."""
    u = np.asarray(torque_Nm, dtype=float)
    a = np.exp(-steps[:, None] / taus)
    with np.errstate(divide="ignore", invalid="ignore"):  # a repeated time: the row holds
        g = np.where(steps[:, None] > 0, taus / steps[:, None] * (1.0 - a), 1.0)
    out = np.empty((len(u), len(taus)))
    out[0] = u[0]
    for k in range(1, len(u)):
        out[k] = a[k - 1] * out[k - 1] + (1.0 - g[k - 1]) * u[k] + (g[k - 1] - a[k - 1]) * u[k - 1]
    return out


def creep_states(torque_Nm: np.ndarray, taus: np.ndarray, T0: float,
                 time: np.ndarray | None = None) -> np.ndarray:
    """(T_τk − T)/T0 (n × K) [-]: each element's creep per unit weight c_k·T0 [rad]; the
    relaxation times ``taus`` in the unit of ``time`` (rows when it is None)."""
    t = np.asarray(torque_Nm, dtype=float)
    steps = np.diff(clock(len(t), time))
    if len(steps) and np.ptp(steps) > 1e-9 * np.mean(steps):
        return (_lagged_uneven(t, np.asarray(taus, dtype=float), steps) - t[:, None]) / T0
    step = float(steps[0]) if len(steps) else 1.0
    return np.column_stack([(lagged(t, tau / step) - t) / T0 for tau in taus])


def centre_lines(states: np.ndarray, torque_Nm: np.ndarray, T0: float) -> np.ndarray:
    """Each element's centre line over the record: its least-squares odd quintic in T/T0,
    the backbone it adds besides its width (a loop drawn about the catalog curve has
    none)."""
    x = np.asarray(torque_Nm, dtype=float) / T0
    basis = np.column_stack([x, x ** 3, x ** 5])
    coef, *_ = np.linalg.lstsq(basis, states, rcond=None)
    return basis @ coef


def loss_at_zero(weights_rad: np.ndarray, taus: np.ndarray, torque_Nm: np.ndarray,
                 T0: float, time: np.ndarray | None = None) -> float:
    """The loop's width at zero torque over the record [rad]: the mean contribution where
    the torque falls through zero less where it rises through it (0 when it never
    crosses both ways)."""
    t = np.asarray(torque_Nm, dtype=float)
    c = creep_states(t, taus, T0, time) @ np.asarray(weights_rad, dtype=float)
    rising = (t[:-1] < 0) & (t[1:] >= 0)
    falling = (t[:-1] > 0) & (t[1:] <= 0)
    if not rising.any() or not falling.any():
        return 0.0
    k = np.flatnonzero(rising | falling)
    w = t[k] / (t[k] - t[k + 1])
    at_zero = c[k] + w * (c[k + 1] - c[k])
    falling = falling[k]
    return float(at_zero[falling].mean() - at_zero[~falling].mean())
