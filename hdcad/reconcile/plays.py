"""Hysteresis as a sum of friction elements with fixed slip torques (an Iwan model, or a
Prandtl–Ishlinskii sum of stop operators), each weighted freely.

A stop operator of threshold r is an elastic element that slips at ±r (a Jenkins element):
its output s follows the torque T with s = T − p, p the play operator's output, which
moves only to stay within r of T, so that |s| ≤ r. From rest (s = 0) a branch loading from
its turning point gives s = max(p0, T − r) … the exact Preisach memory, minor loops closing
on their turning points. The loop is Σ a_k·(−s_k/r_k), a_k ≥ 0 [rad]: friction in parallel
with the gear's spring (the twist lags the torque), each element saturating at ±a_k. The
weights enter linearly, so any odd loop that obeys Masing's rules is fitted by bounded
linear least squares over the fixed thresholds, without a shape search: a loop whose
branches follow no one formula (Menegotto–Pinto, Ramberg–Osgood, a density of slip
torques with two modes) is followed as closely as the thresholds resolve it.

In series with the gear the same elements add their slip to its twist: Σ a_k·p_k/r_k, the
play operators' sum (Prandtl–Ishlinskii), = Σ a_k·(T/r_k − s_k/r_k): the loop in parallel
plus a spring of compliance Σ a_k/r_k, so that the gear's twist is the catalog's below the
first slip torque and grows past each (a kinematic-hardening slider, a joint in microslip).

References
----------
Iwan, W. D. (1966) "A distributed-element model for hysteresis and its steady-state dynamic
response", J. Appl. Mech. 33(4): 893-900.
Brokate, M.; Sprekels, J. (1996) *Hysteresis and Phase Transitions*, Springer, ch. 2 (play
and stop operators, the Prandtl–Ishlinskii model).
Masing, G. (1926) "Eigenspannungen und Verfestigung beim Messing", Proc. 2nd Int. Congress
of Applied Mechanics, Zürich.
"""

from __future__ import annotations

import numpy as np

# slip torques r_k = T0 × these shares: spaced evenly in log from loops that turn over near
# zero torque to elements that slip only towards the test's largest torque (one that never
# slips in ±T0 cycles, r ≥ T0, is a linear spring, the catalog curve's own scale)
THRESHOLD_SHARES = np.geomspace(0.005, 0.95, 16)
# elements in series with the gear slip at this share of T0 or more: one that slips at r adds
# a compliance past r and a loop 2·r wide in torque beside it, so an element slipping near
# zero torque is a housing spring in disguise (its loop under the noise)
SERIES_MIN_SHARE = 0.05


def thresholds(T0: float) -> np.ndarray:
    """The elements' slip torques [N·m] for a test to ±T0 [N·m]."""
    return T0 * THRESHOLD_SHARES


def series_first() -> int:
    """Index of the first element that may act in series with the gear."""
    return int(np.searchsorted(THRESHOLD_SHARES, SERIES_MIN_SHARE))


def stop_states(torque_Nm: np.ndarray, r_Nm: np.ndarray,
                branches: tuple[np.ndarray, int], load_share: float = 0.0,
                T0: float = 0.0) -> np.ndarray:
    """s_k/R_k (n × K, each in −1 … 1) of stop operators with thresholds ``r_Nm`` along the
    torque history, from rest.

    ``branches`` = (turning-point rows, first direction), as for the Bouc–Wen loop: within a
    branch the torque is taken at its running extreme in the branch's direction (noise in
    the torque makes no minor loops). With a ``load_share`` μ > 0 each threshold grows with
    the torque carried, r_k + μ·|T| (Coulomb friction on flanks that the transmitted torque
    presses together), and R_k = r_k + μ·``T0`` [N·m], the threshold at the test's largest
    torque; else R_k = r_k. T − r − μ|T| rises with T for μ < 1, so a branch's play is still
    the running extreme of it."""
    torque = np.asarray(torque_Nm, dtype=float)
    r = np.asarray(r_Nm, dtype=float)
    reach = r + load_share * T0
    starts, direction = branches  # the first branch starts at row 0
    bounds = list(starts) + [len(torque)]
    out = np.empty((len(torque), len(r)))
    play = np.full(len(r), torque[0])
    for s, e in zip(bounds[:-1], bounds[1:]):
        seg = torque[s:e + 1]  # to the next turning point, where this branch ends
        reached = seg[0] + direction * np.maximum.accumulate(direction * (seg - seg[0]))
        slip = r + load_share * np.abs(reached)[:, None]
        if direction > 0:
            p = np.maximum(play, reached[:, None] - slip)
        else:
            p = np.minimum(play, reached[:, None] + slip)
        out[s:e] = ((reached[:, None] - p) / reach)[:e - s]
        play = p[-1]
        direction = -direction
    return out


def centre_lines(torque_Nm: np.ndarray, r_Nm: np.ndarray, T0: float,
                 load_share: float = 0.0) -> np.ndarray:
    """Centre line (mean of loading and unloading) of each element's steady loop between
    ±T0 [N·m], in units of s/R (n × K, :func:`stop_states`): the backbone the loop adds
    besides its width."""
    t = np.asarray(torque_Nm, dtype=float)[:, None]
    r = np.asarray(r_Nm, dtype=float)
    reach = r + load_share * T0
    slip = r + load_share * np.abs(t)
    up = np.minimum(t + T0 - reach, slip)      # loading from −T0, where s = −R
    down = np.maximum(t - T0 + reach, -slip)   # unloading from +T0, where s = +R
    return 0.5 * (up + down) / reach


def loss_at_zero(weights_rad: np.ndarray, r_Nm: np.ndarray, T0: float,
                 load_share: float = 0.0) -> float:
    """The loop's width in twist at zero torque [rad] between ±T0 [N·m]: the catalog's
    hysteresis loss (seed 000 p.020). An element that slips (2R ≤ 2T0, R = r + μ·T0) adds
    2·min(r, T0 − R)/R of its weight."""
    r = np.asarray(r_Nm, dtype=float)
    reach = r + load_share * T0
    share = 2.0 * np.clip(np.minimum(r, T0 - reach), 0.0, None) / reach
    return float(np.sum(np.asarray(weights_rad, dtype=float) * share))
