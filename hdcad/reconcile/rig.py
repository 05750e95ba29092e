"""Measurement-chain effects: what the test rig adds to the data, not the gear.

They are fitted like the gear effects but reported apart (``measurement_effects``), so a
reviewer knows whether to fix the rig or the model. Effects of the rig that are exactly a
nuisance of the catalog model are not separable and are said so instead: a torque- or
angle-sensor gain in torsion reads as the stiffness scale, in efficiency as the level.
Channels in the wrong unit are found before any fit (:mod:`.units`).

References
----------
Seed 000 p.020-021 (test arrangements: twist measured at the output with the input locked;
transmission error as output angle against input angle).
Page, E. S. (1954) "Continuous inspection schemes", Biometrika 41: the CUSUM change point
used to place an offset step.
"""

from __future__ import annotations

import functools

import numpy as np

from .effects import Effect, Parameter


# Time constant of a warm-up drift [half-records]: from a tenth of the record (a rig that
# settles early in the test) to ten records (a slow curvature).
WARM_UP_TAU = (0.2, 20.0)


def _linear(name: str, unit: str, text: str) -> Parameter:
    return Parameter(name, unit, text, -np.inf, np.inf, linear=True)


RIG_EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect(
        name="thermal_drift",
        description=("A slow drift of the measured angle with test time (the rig and the "
                     "gear warm up, the fixture creeps): smooth in time, unrelated to torque "
                     "or angle."),
        form=("y += d1·u + d2·w(u; τ), u = record position from −1 (first row) to 1 "
              "(last), w the first-order warm-up 1 − exp(−(u + 1)/τ) less its straight line, "
              "scaled to a peak of 1 (a long τ makes it a curvature)"),
        parameters=(_linear("d1", "rad", "linear drift over half the record"),
                    _linear("d2", "rad", "largest departure of the drift from a straight line"),
                    Parameter("tau", "-", "warm-up time constant in half-records",
                              WARM_UP_TAU[0], WARM_UP_TAU[1], "1")),
        kinds=("torsion", "transmission", "efficiency", "vibration")),
    Effect(
        name="angle_offset",
        description=("The angle's zero moves once during the test (re-zeroed or slipped "
                     "encoder, a coupling that slips): a step at one instant."),
        form="y += s·[u ≥ u0], u0 at the residual's largest cumulative-sum excursion",
        parameters=(_linear("step", "rad", "height of the step"),),
        kinds=("torsion", "transmission", "vibration")),
    Effect(
        name="encoder_eccentricity",
        description=("An output encoder mounted off-centre reads a once-per-output-"
                     "revolution error; the gear's errors repeat per wave-generator "
                     "revolution instead."),
        form="y += a·sin(φ/R) + b·cos(φ/R), φ/R = output angle",
        parameters=(_linear("a", "rad", "sine part"), _linear("b", "rad", "cosine part")),
        kinds=("transmission", "vibration")),
    Effect(
        name="sensor_gain",
        description=("The output angle sensor's scale is off: the measured angle grows by "
                     "(1 + g) times the true one. The ratio is exact (tooth counts), so a "
                     "slope error is the sensor's."),
        form="y += g·φ/R",
        parameters=(_linear("g", "-", "relative gain error"),),
        kinds=("transmission",)),
)}

RIG_NAMES = tuple(RIG_EFFECTS)


def applicable(kind: str) -> tuple[str, ...]:
    return tuple(n for n, e in RIG_EFFECTS.items() if kind in e.kinds)


def columns(name: str, inputs: dict[str, np.ndarray], step_position: float,
            theta: dict[str, float]) -> tuple[list[str], np.ndarray]:
    """(linear parameter names, columns) of a measurement effect on the given rows, with its
    nonlinear parameters ``theta``."""
    u = inputs["record_position"]
    if name == "thermal_drift":
        return ["d1", "d2"], np.column_stack([u, warm_up(u, theta["tau"])])
    if name == "angle_offset":
        return ["step"], (u >= step_position).astype(float)
    if name == "encoder_eccentricity":
        out = inputs["output_angle_rad"]
        return ["a", "b"], np.column_stack([np.sin(out), np.cos(out)])
    if name == "sensor_gain":
        return ["g"], inputs["output_angle_rad"]
    raise KeyError(name)


def warm_up(u: np.ndarray, tau: float) -> np.ndarray:
    """1 − exp(−(u + 1)/τ) less its least-squares line over u ∈ [−1, 1], scaled to a peak
    of 1: what a first-order warm-up from the start of the test adds to a linear drift
    (Newton's law of cooling). A warm-up that starts later in the test is not followed (a
    bend in mid-record is as much the gear's as the rig's)."""
    line, peak = _warm_up_line(float(tau))
    return (_bent(u, tau) - np.polynomial.legendre.legval(u, line)) / peak


def _bent(x: np.ndarray, tau: float) -> np.ndarray:
    return -np.expm1(-(x + 1.0) / tau)


@functools.lru_cache(maxsize=256)
def _warm_up_line(tau: float) -> tuple[np.ndarray, float]:
    """Legendre coefficients of the warm-up's line on a uniform record, and the peak of what
    is left (the fit calls this with the same τ many times)."""
    grid = np.linspace(-1.0, 1.0, 201)
    line = np.polynomial.legendre.legfit(grid, _bent(grid, tau), 1)
    rest = _bent(grid, tau) - np.polynomial.legendre.legval(grid, line)
    return line, float(np.max(np.abs(rest)))


def step_position(residual: np.ndarray, position: np.ndarray) -> float:
    """Record position u0 of the most likely single step in the residual's mean (CUSUM)."""
    r = residual - residual.mean()
    n = len(r)
    k = np.arange(1, n)
    cusum = np.cumsum(r)[:-1]
    # the change-point statistic of a mean shift: |S_k| / √(k·(n − k)/n)
    stat = np.abs(cusum) / np.sqrt(k * (n - k) / n)
    i = int(np.argmax(stat[n // 50: n - n // 50]) + n // 50) if n > 100 else int(np.argmax(stat))
    return float(0.5 * (position[i] + position[i + 1]))
