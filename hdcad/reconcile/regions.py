"""Where the residual disagrees with the noise: operating-range bins and WG harmonics.

Regions are bins of the kind's operating variable (torque and loading direction, input
speed, load ratio, temperature); transmission's regions are the harmonics of the WG angle.
A region is significant when its mean square residual exceeds the noise variance by
``REGION_Z`` standard errors (with the effective sample size N/τ) and its RMS by
``REGION_RMS_MIN``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import minimize_scalar

from .fitting import Problem
from .harmonics import harmonic, te_order_of
from .encoder_ripple import periodogram_peak

# Significance of a region or a harmonic: z-score against the noise, and a floor relative
# to the noise so that negligible structure is not reported.
REGION_Z = 4.0
REGION_RMS_MIN = 1.2     # region RMS / noise RMS
HARMONIC_Z = 5.0
HARMONIC_RMS_MIN = 0.3   # harmonic RMS / noise RMS
HARMONIC_ORDERS = range(1, 7)
# A transmission residual's ripple at any order (:func:`ripples`): the orders scanned, from
# half a cycle per WG revolution to this many (a WG bearing's ball pass, about half its ball
# count, lies below it); at most this many ripples reported
RIPPLE_ORDERS = (0.5, 24.0)
RIPPLES_MAX = 3


def regions(problem: Problem) -> list[tuple[str, np.ndarray]]:
    """(label, mask) of the operating-range bins where residuals are compared with noise."""
    inp, kind = problem.base.inputs, problem.kind
    if kind == "torsion":
        torque = inp["torque_Nm"]
        direction = directions(problem)
        loading = direction * np.sign(torque) > 0
        out = []
        for lo, hi, mask in _bins(torque, 6):
            for name, m in (("loading", loading), ("unloading", ~loading)):
                out.append((f"torque {lo:.4g}…{hi:.4g} N·m, {name}", mask & m))
        return out
    if kind == "efficiency":
        out = []
        for col, label, unit in (("input_speed_rpm", "input speed", "r/min"),
                                 ("alpha", "load ratio α", ""),
                                 ("temperature_C", "temperature", "°C")):
            for lo, hi, mask in _bins(inp[col], 4):
                span = f"{lo:.4g}" if lo == hi else f"{lo:.4g}…{hi:.4g}"
                out.append((f"{label} {span} {unit}".rstrip(), mask))
        return out
    if kind == "vibration":
        return [(f"input speed {lo:.4g}…{hi:.4g} r/min", mask)
                for lo, hi, mask in _bins(inp["input_speed_rpm"], 8)]
    return []  # transmission: the harmonics of the WG angle are its regions (_harmonics)


def directions(problem: Problem) -> np.ndarray:
    starts, first = problem.branches
    direction = np.empty(len(problem.base.y))
    bounds = list(starts) + [len(direction)]
    d = first
    for s, e in zip(bounds[:-1], bounds[1:]):
        direction[s:e] = d
        d = -d
    return direction


def _bins(x: np.ndarray, count: int):
    """(low, high, mask): the distinct values when there are few, else equal-width bins."""
    values = np.unique(x)
    if len(values) <= count:
        return [(v, v, x == v) for v in values]
    edges = np.linspace(x.min(), x.max(), count + 1)
    # an edge a rounding off zero (−T0…T0 in an even count) is printed as zero
    edges[np.abs(edges) < 1e-9 * (x.max() - x.min())] = 0.0
    index = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, count - 1)
    return [(edges[i], edges[i + 1], index == i) for i in range(count)]


def region_table(problem, before, after, sigma, tau):
    """Rows (label, rms before, rms after, significant) for every region, on its rows less
    the gross outliers (left out of every fit and of the RMSE)."""
    rows = []
    kept = np.ones(len(before), bool)
    kept[problem.outliers] = False
    for label, mask in regions(problem):
        mask = mask & kept
        n = int(mask.sum())
        if n < 10:
            continue
        ms = float(np.mean(before[mask] ** 2))
        dof = max(n / tau, 1.0)
        z = (ms / sigma ** 2 - 1.0) / math.sqrt(2.0 / dof)
        rms = math.sqrt(ms)
        rows.append((label, rms, math.sqrt(float(np.mean(after[mask] ** 2))),
                     z > REGION_Z and rms > REGION_RMS_MIN * sigma))
    return rows


def harmonics(problem, residual, sigma, tau, theta=None):
    """(order, rms, significant) of the residual at k cycles per WG revolution."""
    out = []
    if "wg_angle_rad" not in problem.base.inputs:
        return out
    rows = problem.rows
    n_eff = max(len(rows) / tau, 3.0)
    for k in HARMONIC_ORDERS:
        X = np.column_stack([np.ones(len(rows)), harmonic(problem, k, theta or {}, full=False,
                                                           frames=(0.0, None))[:, :2]])
        beta = np.linalg.lstsq(X, residual[rows], rcond=None)[0]
        part = X[:, 1:] @ beta[1:]
        rms = float(np.sqrt(np.mean(part ** 2)))
        # each of the sin/cos coefficients has a standard error ≈ σ·√(2/N_eff) when the
        # basis is balanced, so the harmonic's RMS has an error ≈ σ/√N_eff
        z = rms / (sigma / math.sqrt(n_eff))
        out.append((k, rms, z > HARMONIC_Z and rms > HARMONIC_RMS_MIN * sigma))
    return out



def unexplained(problem, final, sigma, tau, harmonics, fit) -> list[str]:
    """Significant structure left in the residual after the accepted effects."""
    out = []
    explained_orders = ({te_order_of(e) for e in fit.effects if e.startswith("te_")}
                        | set(problem.te_overtones))
    for k, rms, sig in harmonics:
        if sig and k not in explained_orders:
            out.append(f"residual at {k} cycle(s) per WG revolution (RMS {rms:.3g} "
                       f"{problem.base.unit}), unexplained")
    for label, rms, _, sig in region_table(problem, final, final, sigma, tau):
        if sig:
            out.append(f"residual in {label} (RMS {rms:.3g} {problem.base.unit}, noise "
                       f"{sigma:.3g}), unexplained")
    if problem.kind == "transmission":
        out += [_ripple_text(problem, ripple, sigma, explained_orders)
                for ripple in ripples(problem, final, sigma, tau, explained_orders)]
    return out


def ripples(problem: Problem, residual: np.ndarray, sigma: float, tau: float,
            known: set[int]) -> list[tuple[float, float, bool]]:
    """(order [cycles per WG revolution], RMS [unit of the data], whether the order is a
    whole number within the record's resolution) of the ripples left in a residual at
    orders that are neither in ``HARMONIC_ORDERS`` (reported by :func:`harmonics`) nor in
    ``known``, the strongest first.

    The residual's periodogram against the WG angle (:func:`.encoder_ripple.periodogram_peak`, a bin
    per row) gives the strongest order in ``RIPPLE_ORDERS``, refined to the best-fitting
    sine on the samples themselves; it is significant when its RMS exceeds the noise's
    standard error σ/√N_eff by ``HARMONIC_Z`` standard errors with the look-elsewhere cost
    of the orders scanned added (z² > Z² + ln M, M the independent orders: a white noise's
    largest of M periodogram values is about σ²/N_eff·ln M) and ``HARMONIC_RMS_MIN`` of the
    noise; it is taken out and the scan repeated, up to ``RIPPLES_MAX`` times.

    References: Scargle, J. D. (1982) "Studies in astronomical time series analysis II",
    Astrophys. J. 263: 835-853 (the periodogram's false-alarm level over M frequencies).
    """
    rows = problem.rows
    phi = problem.base.inputs["wg_angle_rad"][rows]
    revolutions = float(np.ptp(phi)) / (2 * math.pi)
    if revolutions < 2 or np.any(np.diff(phi) <= 0):
        return []
    top = min(RIPPLE_ORDERS[1], 0.9 * math.pi / float(np.median(np.diff(phi))))
    independent = (top - RIPPLE_ORDERS[0]) * revolutions
    if independent < 1:
        return []
    threshold = HARMONIC_Z ** 2 + math.log(independent)
    n_eff = max(len(rows) / tau, 3.0)
    r = residual[rows] - residual[rows].mean()
    step = 0.25 / revolutions
    found = []
    for _ in range(RIPPLES_MAX):
        start = 2 * math.pi * periodogram_peak(r, phi, len(phi),
                                              (RIPPLE_ORDERS[0] / (2 * math.pi),
                                               top / (2 * math.pi)))
        order = minimize_scalar(lambda f: -_sine(phi, r, f)[1], method="bounded",
                                bounds=(start - step, start + step)).x
        part, rms = _sine(phi, r, order)
        if (rms / (sigma / math.sqrt(n_eff))) ** 2 <= threshold or \
                rms <= HARMONIC_RMS_MIN * sigma:
            break
        whole = abs(order - round(order)) <= 1 / revolutions
        if not (whole and (round(order) in HARMONIC_ORDERS or round(order) in known)):
            found.append((float(order), rms, whole))
        r = r - part
    return found


def _sine(phi: np.ndarray, r: np.ndarray, order: float) -> tuple[np.ndarray, float]:
    """The least-squares sine of ``r`` at ``order`` cycles per WG revolution (with a mean)
    and its RMS."""
    X = np.column_stack([np.sin(order * phi), np.cos(order * phi), np.ones_like(phi)])
    beta = np.linalg.lstsq(X, r, rcond=None)[0]
    part = X[:, :2] @ beta[:2]
    return part, float(np.sqrt(np.mean(part ** 2)))


def _ripple_text(problem: Problem, ripple: tuple[float, float, bool], sigma: float,
                 known: set[int]) -> str:
    """A ripple (:func:`ripples`) as the report says it: a harmonic of the WG beyond those
    named; beside a named error's order, a sideband of it (the error's amplitude or phase
    varies faster than its slow form follows); else another rotating member's or a
    sensor's."""
    order, rms, whole = ripple
    size = (f"RMS {rms:.3g} {problem.base.unit}, {rms / sigma:.2f}× the noise"
            if sigma > 0 else f"RMS {rms:.3g} {problem.base.unit}")
    if whole:
        return (f"residual at {order:.4g} cycles per WG revolution ({size}), the WG's "
                f"{round(order)}× harmonic within the record's resolution, beyond those "
                "named; unexplained")
    near = min(known, key=lambda k: abs(order - k), default=None)
    if near is not None and abs(order - near) < 0.5:
        return (f"residual at {order:.4g} cycles per WG revolution ({size}), a sideband of the "
                f"{near}× error: its amplitude or phase varies with a period of "
                f"{1 / abs(order - near):.3g} WG revolutions, faster than its slow form "
                "follows; unexplained")
    return (f"residual at {order:.4g} cycles per WG revolution ({size}), not a harmonic of "
            "the WG: another rotating member's (a WG bearing's ball pass, a coupling) or a "
            "ripple of an angle sensor's own (its interpolation); unexplained")
