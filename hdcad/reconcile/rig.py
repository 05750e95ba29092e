"""Measurement-chain effects: what the test rig adds to the data, not the gear.

They are fitted like the gear effects but reported apart (``measurement_effects``), so a
reviewer knows whether to fix the rig or the model. Effects of the rig that are exactly a
nuisance of the catalog model are not separable and are said so instead: a twist sensor's
gain in torsion reads as the stiffness scale (a torque channel's gain or zero moves the catalog
curve's corners and is fitted), a torque sensor's gain in efficiency as the level.
Channels in the wrong unit are found before any fit (:mod:`.units`); an encoder's
interpolation ripple's period and signatures are in :mod:`.encoder_ripple`.

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

from .drive import DRIVE_RIPPLE
from .effects import Effect, Parameter, key_of


# Time constant of a warm-up drift [half-records]: from a tenth of the record (a rig that
# settles early in the test) to ten records (a slow curvature).
WARM_UP_TAU = (0.2, 20.0)

# Largest torque-channel gain error read as the rig's [-]: a shunt or calibration constant
# tens of per cent off; kgf·m against N·m (×9.81) is a unit, found before the fit.
TORQUE_GAIN_LIMIT = 0.3

# Largest zero offset of the torque channel read as the rig's [T0]: a bridge left untared
# or a tare taken under a load.
TORQUE_OFFSET_LIMIT = 0.1

# Time constant of a drift that restarts at each test block [block lengths]: from a twentieth
# of the block (a sensor that settles within a few rows) to three blocks (a creep that stays
# nearly straight over the block).
BLOCK_TAU = (0.05, 3.0)

# Blocks a per-block drift is looked for in: runs of one temperature set-point in row order
# (an oven block), at least BLOCKS_MIN of them with BLOCK_ROWS_MIN rows or more each (fewer
# rows do not show a shape that restarts).
BLOCKS_MIN = 2
BLOCK_ROWS_MIN = 8

# Harmonics of an encoder's interpolation error: read at the measured angle y = θ + e(θ),
# the error is still periodic in y, its k-th harmonic (2π·e/p)^(k−1) of the first.
INTERPOLATION_HARMONICS = 3


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
        name="block_drift",
        description=("A drift that restarts at each test block (the torque or speed channel "
                     "re-zeroed as each oven block starts, then warming or creeping as the "
                     "block runs): the same shape in every block, in row order within the "
                     "block, unrelated to the load, speed or temperature of the rows."),
        form=("y += d1·v + d2·(1 − exp(−v/τ)), v = rows since the block's first row over "
              "the median block's rows, blocks = runs of one temperature in row order"),
        parameters=(_linear("d1", "%", "linear drift over a median block"),
                    _linear("d2", "%", "settling part of the drift"),
                    Parameter("tau", "-", "settling time constant in median block lengths",
                              BLOCK_TAU[0], BLOCK_TAU[1], "1")),
        kinds=("efficiency",)),
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
        name="encoder_interpolation",
        description=("An angle encoder's interpolation error: a ripple that repeats once "
                     "per signal period of its grating (an encoder of 9 000 – 36 000 lines "
                     "reads a few per cent of a 36 – 144 arc-second period wrong), periodic "
                     "in the measured angle (the twist in torsion, the output angle in "
                     "transmission), not in the torque nor in the wave generator's angle."),
        form=("y += Σ_k [a_k·sin(2πk·y/p) + b_k·cos(2πk·y/p)], k = 1 … 3, y the measured "
              "angle, p the signal period (started at the peak of the residual's "
              "periodogram over the measured angle, away from the wave generator's orders "
              "in transmission, then fitted within ±10 %); the harmonics are the error's "
              "own and those of reading it at the measured, not the true, angle"),
        parameters=(*(_linear(f"{ab}{k}", "rad", f"{part} part of harmonic {k}")
                      for k in range(1, INTERPOLATION_HARMONICS + 1)
                      for ab, part in (("a", "sine"), ("b", "cosine"))),
                    Parameter("period", "rad", "signal period of the encoder", 0.9, 1.1,
                              "angle_period", start=1.0)),
        kinds=("torsion", "transmission")),
    Effect(
        name="sensor_play",
        description=("The twist sensor's body turns in the play of its anti-rotation slot "
                     "(or of a measuring arm's coupling): the reading steps by the play each "
                     "time the twist changes direction, at the torque's extremes, at "
                     "constant torque, which no friction or play of the gear does (those "
                     "act while the torque changes, a play at zero torque)."),
        form="y += p·s, s = +1 on loading branches and −1 on unloading ones",
        parameters=(_linear("p", "rad", "half the step at each reversal"),),
        kinds=("torsion",)),
    Effect(
        name="sensor_gain",
        description=("A channel's scale is off. Transmission: the output angle sensor reads "
                     "(1 + g) times the true angle (the ratio is exact, tooth counts, so a "
                     "slope error is the sensor's). Torsion: the torque channel reads "
                     "(1 + g_T) times the true torque (a shunt or calibration constant), so "
                     "the catalog curve's corners T1 and T2 sit at (1 + g_T)·T1 and "
                     "(1 + g_T)·T2 of the recorded torque; a twist sensor's gain scales "
                     "every segment alike and reads as the stiffness scale instead. "
                     "Efficiency: a gain is the level's; a gain that changes once during "
                     "the test (a torque channel's range switched, a recalibration) is a "
                     "step of the efficiency at one row, in row order."),
        form=("transmission: y += g·φ/R; torsion: y = s·θ_catalog(T/(1 + g_T)) + …; "
              "efficiency: y += s·[u ≥ u0], u0 at the residual's largest cumulative-sum "
              "excursion"),
        parameters=(_linear("g", "-", "relative gain error of the output angle"),
                    Parameter("torque_gain", "-", "relative gain error of the torque channel",
                              -TORQUE_GAIN_LIMIT, TORQUE_GAIN_LIMIT, "1", start=0.0),
                    _linear("gain_step", "%", "step of the efficiency where a gain changed")),
        kinds=("transmission", "torsion", "efficiency")),
    Effect(
        name="torque_offset",
        description=("The torque channel's zero is off (a bridge left untared, a tare taken "
                     "under load): the gear carries the recorded torque less the offset, so "
                     "the catalog curve's corners sit at T_off ± T1 and T_off ± T2 of the "
                     "recorded torque, no longer symmetric about zero; a twist sensor's "
                     "zero is the baseline's offset instead."),
        form="torsion: y = s·θ_catalog((T − T_off)/(1 + g_T)) + …",
        parameters=(Parameter("T_off", "N·m", "zero offset of the torque channel",
                              -TORQUE_OFFSET_LIMIT, TORQUE_OFFSET_LIMIT, "T0", start=0.0),),
        kinds=("torsion",)),
    DRIVE_RIPPLE,
)}

RIG_NAMES = tuple(RIG_EFFECTS)


# Measurement effects that the baseline already fits in a kind, so not searched there: a
# transmission test's output-angle gain is the baseline's slope (the ratio is exact), and
# is reported from it (rig_entries.output_gain_entry).
IN_BASELINE = {("sensor_gain", "transmission")}


def applicable(kind: str, inputs: dict[str, np.ndarray] | None = None) -> tuple[str, ...]:
    """The measurement effects searched for in ``kind`` (a per-block drift only where the
    ``inputs`` have blocks)."""
    blocks = inputs is not None and inputs.get("block_position") is not None
    return tuple(n for n, e in RIG_EFFECTS.items()
                 if kind in e.kinds and (n, kind) not in IN_BASELINE
                 and (n != "block_drift" or blocks))


# What a measurement effect fits in a kind, where that differs by kind: a sensor's gain is
# the output angle's in transmission (a column) and the torque channel's in torsion (read
# through the catalog curve's corners by the baseline, at TORQUE_GAIN_KEY).
KIND_PARAMETERS = {("sensor_gain", "transmission"): ("g",),
                   ("sensor_gain", "torsion"): ("torque_gain",),
                   ("sensor_gain", "efficiency"): ("gain_step",)}

# Measurement effects placed at a step in record order (rig.step_position) in a kind.
STEPPED = {("angle_offset", k) for k in ("torsion", "transmission", "vibration")} | {
    ("sensor_gain", "efficiency")}
TORQUE_GAIN_KEY = key_of("sensor_gain", "torque_gain")
TORQUE_OFFSET_KEY = key_of("torque_offset", "T_off")


def _in_kind(name: str, kind: str, params: tuple[Parameter, ...]) -> tuple[Parameter, ...]:
    names = KIND_PARAMETERS.get((name, kind))
    return params if names is None else tuple(p for p in params if p.name in names)


def nonlinear_parameters(name: str, kind: str) -> tuple[Parameter, ...]:
    """The measurement effect's parameters fitted by nonlinear least squares for this kind."""
    return _in_kind(name, kind, RIG_EFFECTS[name].nonlinear)


def columns(name: str, kind: str, inputs: dict[str, np.ndarray], step_position: float,
            theta: dict[str, float]) -> tuple[list[str], np.ndarray]:
    """(linear parameter names, columns) of a measurement effect in ``kind`` on the given
    rows, with its nonlinear parameters ``theta`` (none when the effect acts only through
    the baseline in that kind)."""
    u = inputs["record_position"]
    if not any(p.linear for p in _in_kind(name, kind, RIG_EFFECTS[name].parameters)):
        return [], np.zeros((len(u), 0))
    if name == "thermal_drift":
        return ["d1", "d2"], np.column_stack([u, warm_up(u, theta["tau"])])
    if name == "block_drift":
        v = inputs["block_position"]
        return ["d1", "d2"], np.column_stack([v, -np.expm1(-v / theta["tau"])])
    if (name, kind) in STEPPED:  # the linear amplitude of a step at step_position
        label = next(p.name for p in _in_kind(name, kind, RIG_EFFECTS[name].parameters)
                     if p.linear)
        return [label], (u >= step_position).astype(float)
    if name == "encoder_eccentricity":
        out = inputs["output_angle_rad"]
        return ["a", "b"], np.column_stack([np.sin(out), np.cos(out)])
    if name == "sensor_gain":
        return ["g"], inputs["output_angle_rad"]
    if name == "sensor_play":
        return ["p"], inputs["branch_direction"]
    if name == "encoder_interpolation":
        phase = 2.0 * np.pi * inputs["measured_rad"] / theta["period"]
        orders = range(1, INTERPOLATION_HARMONICS + 1)
        return ([f"{ab}{k}" for k in orders for ab in "ab"],
                np.column_stack([f(k * phase) for k in orders for f in (np.sin, np.cos)]))
    raise KeyError(name)


# A reading's play steps at the torque's extremes: the branches stay apart there by as much
# as at zero torque, where a loop of the gear (friction, microslip, Masing branches) closes
# at its tips. The residual's branch separation among the rows beyond TIP_SHARE of the
# largest torque must be at least TIP_RATIO_MIN of that below MID_SHARE.
TIP_SHARE, MID_SHARE, TIP_RATIO_MIN = 0.8, 0.3, 0.5


def apart_at_the_tips(residual: np.ndarray, torque: np.ndarray,
                      direction: np.ndarray) -> bool:
    """Whether the loading and unloading branches of ``residual`` [rad] stay apart at the
    torque's extremes (a reading's play) rather than meet there (a loop of the gear);
    ``direction`` is +1 on loading rows and −1 on unloading ones."""
    share = np.abs(torque) / np.max(np.abs(torque))
    tip, mid = share >= TIP_SHARE, share <= MID_SHARE
    if not (tip.any() and mid.any()):
        return False
    at_mid = float(np.mean(residual[mid] * direction[mid]))
    at_tip = float(np.mean(residual[tip] * direction[tip]))
    return at_mid != 0.0 and at_tip / at_mid >= TIP_RATIO_MIN


def block_position(setting: np.ndarray) -> np.ndarray | None:
    """Each row's position within its block: rows since the block's first row over the
    median block's rows (a rig's warm-up runs in time, and each row takes about as long),
    where blocks are runs of one ``setting`` (a temperature set-point) in row order; None
    when fewer than ``BLOCKS_MIN`` blocks of ``BLOCK_ROWS_MIN`` rows or more."""
    starts = np.concatenate([[0], np.flatnonzero(np.diff(setting) != 0) + 1])
    lengths = np.diff(np.append(starts, len(setting)))
    if np.count_nonzero(lengths >= BLOCK_ROWS_MIN) < BLOCKS_MIN:
        return None
    first = np.repeat(starts, lengths)
    return (np.arange(len(setting)) - first) / float(np.median(lengths))


def block_starts(position: np.ndarray) -> np.ndarray:
    """Indices where a block starts in ``block_position`` values, on every row or on the fit
    rows (where a block's first row may be left out as an outlier): the position falls or
    stays."""
    return np.flatnonzero(np.diff(position, prepend=np.inf) <= 0)


def same_in_blocks(residual: np.ndarray, drift: np.ndarray, position: np.ndarray) -> bool:
    """A drift that restarts at each block has its shape in most blocks, not in one or two:
    within each block long enough to show it, the fitted ``drift`` and the ``residual`` it
    takes, each less its block mean, go the same way (positive product) in at least
    ``SAME_SIGN_SHARE`` of the blocks."""
    starts = block_starts(position)
    ends = np.append(starts[1:], len(position))
    alike = [np.dot(drift[a:b] - drift[a:b].mean(), residual[a:b] - residual[a:b].mean()) > 0
             for a, b in zip(starts, ends) if b - a >= BLOCK_ROWS_MIN]
    return bool(alike) and float(np.mean(alike)) >= SAME_SIGN_SHARE


SAME_SIGN_SHARE = 2.0 / 3.0


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

