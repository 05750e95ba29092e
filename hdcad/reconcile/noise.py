"""Noise level of a measurement, estimated from the data itself.

How: the samples are taken in time order and differenced four times at a lag h,
d_h[i] = y[i−2h] − 4·y[i−h] + 6·y[i] − 4·y[i+h] + y[i+2h]. A smooth signal (the physics,
including any missing effect) contributes ≈ y⁗·h⁴, negligible while h is short against the
signal's features (a fourth difference cancels every cubic); stationary noise of variance σ²
contributes 70σ² for white noise at every lag, and for coloured noise rises to 70σ² once h
exceeds its correlation length. The estimate at each lag is s_h = 1.4826·MAD(d_h)/√70 (the
median absolute deviation ignores the few differences that straddle a kink or a jump of the
signal: torque reversals, a backlash step, the edges of an efficiency grid). σ is the largest
s_h over lags 1, 2, 4, … before the signal takes over, which shows as s_h growing faster than
noise can (a factor CURVATURE_GROWTH per doubling of h: coloured noise grows s_h by less than
√2 per doubling, a smooth signal by 16).

The workflow applies it to the residual of the current model, so the structure the model
already explains cannot leak into the estimate; the structure it does not explain is
smooth or sparse in time and is what the differences reject.

Why: the residual of a model cannot be used to judge that model (a missing effect would be
counted as noise), and coloured noise makes adjacent-sample differences underestimate σ;
the lag scan recovers the full variance of noise correlated over several samples.

The correlation time τ (the variance inflation of a mean, τ = 1 + 2·Σ r(k)) of a residual
gives the effective number of independent samples N/τ used by the information criterion.
"""

from __future__ import annotations

import math

import numpy as np

# Growth of s_h per doubling of the lag above which the signal, not the noise, dominates.
# Noise alone grows s_h by less than √2 per doubling; a smooth signal's fourth difference
# grows 16× per doubling. For AR(1) noise with coefficient 0.8 the growth factors are
# 1.40, 1.36, 1.27, 1.13, … (computed from the fourth difference's variance
# 70 − 112r(h) + 56r(2h) − 16r(3h) + 2r(4h)): never above 1.45, and shrinking.
CURVATURE_GROWTH = 1.45
MAX_LAG = 64
MAD_TO_SIGMA = 1.4826  # σ = 1.4826·MAD for Gaussian data


def lag_estimates(y: np.ndarray, max_lag: int = MAX_LAG) -> list[tuple[int, float]]:
    """(h, s_h) for h = 1, 2, 4, … ≤ max_lag: robust noise RMS from fourth differences."""
    y = np.asarray(y, dtype=float)
    out = []
    h = 1
    while h <= max_lag and 4 * h < len(y) // 4:
        n = len(y) - 4 * h
        d = (y[:n] - 4.0 * y[h:h + n] + 6.0 * y[2 * h:2 * h + n] - 4.0 * y[3 * h:3 * h + n]
             + y[4 * h:4 * h + n])
        mad = np.median(np.abs(d - np.median(d)))
        out.append((h, MAD_TO_SIGMA * mad / np.sqrt(70.0)))
        h *= 2
    return out


def noise_rms(y: np.ndarray) -> float:
    """Noise RMS [unit of y] of samples ``y`` in time order (see the module docstring)."""
    estimates = [s for _, s in lag_estimates(y)]
    if not estimates:
        return float(np.std(y))
    best = estimates[0]
    for s0, s1 in zip(estimates, estimates[1:]):
        growth = s1 / s0 if s0 > 0 else math.inf
        if growth > CURVATURE_GROWTH:
            break
        best = max(best, s1)
    return float(best)


def correlation_time(residual: np.ndarray, max_lag: int | None = None) -> float:
    """τ = 1 + 2·Σ r(k) [samples], summed until r(k) first drops below zero.

    N/τ is the effective number of independent samples of a mean or a sum of squares.
    """
    r = np.asarray(residual, dtype=float) - np.mean(residual)
    n = len(r)
    max_lag = max_lag or min(n // 10, 2000)
    spectrum = np.fft.rfft(r, 2 * n)
    acf = np.fft.irfft(spectrum * np.conj(spectrum))[:max_lag + 1]
    if acf[0] <= 0:
        return 1.0
    acf = acf / acf[0]
    negative = np.flatnonzero(acf[1:] <= 0)
    stop = negative[0] + 1 if negative.size else len(acf)
    return float(max(1.0, 1.0 + 2.0 * acf[1:stop].sum()))
