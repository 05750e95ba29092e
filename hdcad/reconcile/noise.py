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


def _fourth_difference_variance(h: int, phi: float) -> float:
    """Var of the lag-h fourth difference of unit-variance AR(1) noise with coefficient φ."""
    r = lambda k: phi ** k
    return 70.0 - 112.0 * r(h) + 56.0 * r(2 * h) - 16.0 * r(3 * h) + 2.0 * r(4 * h)


def noise_model(y: np.ndarray) -> tuple[float, float]:
    """(σ [unit of y], φ [-]) of AR(1) noise fitted to the lagged fourth differences.

    s_h² = σ²·v(h, φ)/70 with v the variance of the fourth difference of AR(1) noise
    (:func:`_fourth_difference_variance`), fitted in log s over the shortest lags 1, 2, 4, 8,
    16 (where a smooth signal contributes least); the longest lag is dropped (twice at most)
    while it lies more than ``CURVATURE_GROWTH`` − 1 above the fit (signal, not noise).
    White noise has φ = 0.

    The noise cannot hold more variance than the series it is read from: when the fit
    extrapolates σ above the RMS of ``y`` (a short series whose few lags leave φ loose, read
    as near 1), σ is held at that RMS and φ fitted again with it.
    """
    estimates = [(h, s) for h, s in lag_estimates(y, 16) if s > 0]
    if len(estimates) < 2:
        return float(np.std(y)), 0.0
    for _ in range(3):
        hs = np.array([h for h, _ in estimates])
        logs = np.log([s for _, s in estimates])
        _, phi, level, shape = _ar1_fit(hs, logs)
        if len(estimates) > 2 and logs[-1] - shape[-1] - level > math.log(CURVATURE_GROWTH):
            estimates = estimates[:-1]
            continue
        break
    rms, n = float(np.std(y)), len(y)
    if rms > 0 and level > _log_ceiling(rms, n, phi):
        _, phi, level, _ = _ar1_fit(hs, logs, lambda p: _log_ceiling(rms, n, p))
    return float(math.exp(level)), float(phi)


def _log_ceiling(rms: float, n: int, phi: float) -> float:
    """log of the largest σ of AR(1) noise whose n samples have the RMS ``rms`` about their
    mean: a sample's variance falls short of σ² by the variance of its mean, ≈ σ²·τ/n."""
    return math.log(rms) - 0.5 * math.log(max(1.0 - ar1_time(phi) / n, 0.25))


def _ar1_fit(hs: np.ndarray, logs: np.ndarray, level=None):
    """(error, φ, log σ, shape) of the AR(1) fit in log s_h over a grid of φ; log σ fitted,
    or given as a function of φ."""
    best = None
    for phi in np.linspace(0.0, 0.95, 96):
        shape = 0.5 * np.log([_fourth_difference_variance(int(h), phi) / 70.0 for h in hs])
        lv = float(np.mean(logs - shape)) if level is None else level(phi)
        err = float(np.sum((logs - shape - lv) ** 2))
        if best is None or err < best[0]:
            best = (err, phi, lv, shape)
    return best


def noise_rms(y: np.ndarray) -> float:
    """Noise RMS [unit of y] of samples ``y`` in time order (see :func:`noise_model`)."""
    return noise_model(y)[0]


def ar1_time(phi: float) -> float:
    """Correlation time τ = (1 + φ)/(1 − φ) [samples] of AR(1) noise."""
    return (1.0 + phi) / (1.0 - phi)


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
