"""The columns of a model: the baseline's free columns, the measurement-chain effects' and the
gear effects', with the linear amplitudes' labels and bounds.

A model is linear in its amplitudes (a loop's saturation twist, a play's lost motion, a
spring's compliance, a harmonic's sine and cosine parts, the catalog curve's scale and
offset) and nonlinear in its shapes (widths, loop parameters, the corner width of the
catalog curve): :func:`columns` gives the design matrix at a shape ``theta``, which
:mod:`.fitting` solves for the amplitudes and searches over the shapes. The efficiency
effects scale the whole efficiency (η = η0·Ke(α)·F(t)), so they multiply every column.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from . import baseline as baselines
from . import efficiency_laws as laws
from . import effects as fx
from . import creep, duhem, plays, rig, spring_forms
from .effects import key_of
from .harmonics import (harmonic, legendre, locked_labels, locked_overtone, overtones_of,
                        sideband_labels, sidebands, te_column_labels, te_order_of)

if TYPE_CHECKING:
    from .fitting import Problem


def nonlinear(kind: str, effects: tuple[str, ...]) -> dict[str, fx.Parameter]:
    """Nonlinear parameters of a model: the baseline's nuisances and the effects' shapes."""
    out: dict[str, fx.Parameter] = {f"catalog.{p.name}": p
                                    for p in baselines.NUISANCE.get(kind, ())}
    for name in effects:
        for p in parameters_of(name, kind):
            out.setdefault(key_of(name, p.name), p)
    return out


def drift_labels(order: int) -> list[str]:
    """Labels of a play's lost motion along the record: its Legendre terms 1 … ``order``."""
    return [f"lost_motion_p{k}" for k in range(1, order + 1)]


def parameters_of(name: str, kind: str) -> tuple[fx.Parameter, ...]:
    if name in rig.RIG_EFFECTS:
        return rig.nonlinear_parameters(name, kind)
    return fx.nonlinear_parameters(name, kind)


def columns(problem: Problem, effects: tuple[str, ...], theta: dict[str, float],
            full: bool = False):
    """Design matrix, labels and linear bounds for a model with ``effects``, on every row
    (``full``) or on the fitted rows."""
    base = problem.base
    rows = slice(None) if full else problem.rows
    inp = _inputs_on(problem, full)
    branches = problem.branches if full else problem.fit_branches
    free = base.free_columns(theta, rows)
    n = free.shape[0]
    cols = [free]
    labels = [("baseline", n_) for n_ in base.free_names]
    # the compliance scale stays within the catalog's spread: beyond it the data ask for an
    # effect (or, for a stiffer gear, the nuisance report says so); left free to ask
    # whether something else than the scale is in the data, and for the reconciled model
    # of a gear the data put beyond the spread
    scale = (0.0, np.inf) if problem.scale_free else baselines.COMPLIANCE_SCALE_BOUNDS
    bounds = {"compliance_scale": scale,
              "printed_reading": (0.0, baselines.COMPLIANCE_SCALE_BOUNDS[1]),
              "scale_error": (-baselines.ANGLE_GAIN_LIMIT, baselines.ANGLE_GAIN_LIMIT)}
    lower = [bounds.get(n_, (-np.inf, np.inf))[0] for n_ in base.free_names]
    upper = [bounds.get(n_, (-np.inf, np.inf))[1] for n_ in base.free_names]

    def add(effect: str, names, block, lo=-np.inf, hi=np.inf):
        cols.append(block.reshape(n, -1))
        labels.extend((effect, n_) for n_ in names)
        lower.extend([lo] * len(names))
        upper.extend([hi] * len(names))

    factor = None
    for name in effects:
        th = {p.name: theta[key_of(name, p.name)] for p in parameters_of(name, problem.kind)}
        if name == "drive_ripple":  # through the joint as the error is, in the motor's frame
            add(name, ["a", "b"], harmonic(problem, problem.drive_order, theta, full,
                                           (0.0, None))[:, :2] if problem.drive_order
                else np.zeros((n, 2)))
        elif name in rig.RIG_EFFECTS:
            names, block = rig.columns(name, problem.kind, inp, problem.step_position, th)
            add(name, names, block)
        elif name == "hysteresis":
            if problem.hysteresis_creep != "alone":
                add(name, *_loop_columns(problem, inp, th, theta, branches, rows), 0.0)
            if problem.hysteresis_creep:
                C = _creep_states(problem, rows)
                add(name, [f"creep_{k}" for k in range(C.shape[1])], C, 0.0)
        elif name == "backlash":
            t0 = problem.scales["T0"]
            torque = inp["torque_Nm"] - problem.play_bias * t0
            held = torque - inp["branch_direction"] * (problem.play_hold * t0)
            play = fx.backlash_twist(held, 1.0, th["T_w"], math.exp(problem.play_shape))
            if problem.play_start:  # held where it was until the load first passes T_h
                start = fx.before_first_hold(torque, problem.play_hold * t0)
                play = np.where(start, 0.0, play)
            add(name, ["lost_motion"], play, 0.0)
            if problem.play_start:
                add(name, ["start_position"], start.astype(float))
            if problem.play_drift:  # the lost motion along the record: P1 … P_K of its position
                add(name, drift_labels(problem.play_drift), np.column_stack(
                    [p * play for p in legendre(inp["record_position"], problem.play_drift)[1:]]))
            if problem.play_step is not None:  # a step in the lost motion at that position
                after = inp["record_position"] >= problem.play_step
                add(name, ["lost_motion_step"], play * after)
        elif name == "housing_compliance":
            add(name, ["compliance"], spring_forms.progressive_twist(inp["torque_Nm"],
                                                           problem.housing_knee), 0.0)
            if np.isfinite(problem.housing_opening):  # the compliance the opened joint adds
                add(name, ["opening_compliance"],
                    spring_forms.opening_twist(inp["torque_Nm"], problem.housing_opening), 0.0)
        elif name in ("te_1x", "te_2x"):
            order = te_order_of(name)
            add(name, te_column_labels(problem, order), harmonic(problem, order, theta, full))
            for k in overtones_of(problem, effects, name):
                add(name, [f"sin_{k}x", f"cos_{k}x"], harmonic(problem, k, theta, full)[:, :2])
            if order == 1 and problem.te_locked_2x is not None:
                add(name, locked_labels(problem.te_order), locked_overtone(problem, theta, full))
            if order in problem.te_sidebands:
                add(name, sideband_labels(problem.te_sidebands[order][1]),
                    sidebands(problem, order, full, theta))
        elif stribeck_takes(problem, name):
            if name == next(e for e in effects if stribeck_takes(problem, e)):
                add(name, list(laws.STRIBECK_LABELS), -_stribeck(problem, inp), 0.0)
        elif name == "low_load_efficiency":
            f = laws.low_load_factor(inp["alpha"], th["c"], th["q"], inp["input_speed_rpm"],
                                     th["s"], _viscosity(problem, effects, theta, inp),
                                     problem.drag_viscosity_exponent, problem.low_load_flat)
            factor = f if factor is None else factor * f
        elif name == "temperature_dependence":
            f = laws.temperature_factor(inp["temperature_C"], th["a"], th["b"],
                                        laws.REFERENCE_TEMPERATURE_C, inp["input_speed_rpm"],
                                        th["s"], th["boundary"], problem.viscosity_C,
                                        problem.speed_loss, problem.temperature_band)
            factor = f if factor is None else factor * f
    X = np.column_stack(cols)
    if factor is not None:  # η = η0·Ke(α)·F(t): the effects scale the whole efficiency
        X = X * factor[:, None]
    return X, labels, np.array(lower), np.array(upper)


def _loop_columns(problem: Problem, inp: dict, th: dict, theta: dict, branches, rows
                  ) -> tuple[list[str], np.ndarray]:
    """Labels and columns of the friction loop: a sum of friction elements (in parallel with
    the gear or in series with it) or one Bouc–Wen or Preisach loop."""
    torque = inp["torque_Nm"]
    if problem.hysteresis_duhem is not None:  # w falls below 0 on loading: the twist lags
        w = duhem.states(torque, branches, problem.scales["T0"], *problem.hysteresis_duhem)
        if problem.hysteresis_through_gear:
            w = w * _through_gear(problem, torque, theta)
        return ["z_sat"], w
    if problem.hysteresis_plays:
        S = _stop_states(problem, torque, branches, rows)
        first = 0
        if problem.hysteresis_series:  # each element's slip adds to the gear's twist
            first = plays.series_first()
            r = plays.thresholds(problem.scales["T0"])[first:]
            S = S[:, first:] - torque[:, None] / r
        elif problem.hysteresis_through_gear:
            S = S * _through_gear(problem, torque, theta)[:, None]
        return [f"a_{k}" for k in range(first, first + S.shape[1])], -S
    z = _hysteresis_state(problem, torque, th, branches, rows)
    if problem.hysteresis_series:
        z = z - torque / th["T_s"]
    elif problem.hysteresis_through_gear:
        z = z * _through_gear(problem, torque, theta)
    return ["z_sat"], -z


def _creep_states(problem: Problem, rows) -> np.ndarray:
    """The creep elements' columns (:func:`.creep.creep_states`) on ``rows``: the lag runs
    along the whole record (the rows left out of a fit are still loaded); less their centre
    lines when the loop is drawn about the catalog curve."""
    key = ("creep", problem.creep_centred)
    if key not in problem.cache:
        torque, t0 = problem.base.inputs["torque_Nm"], problem.scales["T0"]
        time = problem.base.inputs.get("time_s")
        C = creep.creep_states(torque, creep.record_taus(len(torque), time)[0], t0, time)
        if problem.creep_centred:
            C = C - creep.centre_lines(C, torque, t0)
        problem.cache[key] = C
    return problem.cache[key][rows]


def _inputs_on(problem: Problem, full: bool) -> dict[str, np.ndarray]:
    """The record's input columns on every row or on the fitted rows (these kept until
    set_rows clears the cache: read only)."""
    inputs = {k: v for k, v in problem.base.inputs.items() if np.ndim(v) == 1}
    if full:
        return inputs
    key = ("inputs", id(problem.rows))
    if key not in problem.cache:
        problem.cache[key] = {k: v[problem.rows] for k, v in inputs.items()}
    return problem.cache[key]


def _hysteresis_state(problem: Problem, torque: np.ndarray, th: dict, branches, rows
                      ) -> np.ndarray:
    """The loop's state z (−1 … 1) on the rows: Bouc–Wen at the shape ``th``, or the
    Preisach relay sum when ``problem.hysteresis_preisach`` holds its density; less the
    loop's centre line when it is drawn about the catalog curve."""
    if problem.hysteresis_preisach is not None:
        return problem.preisach_plane.loop(torque, rows, *problem.hysteresis_preisach,
                                           problem.hysteresis_centred)
    # kept for the Jacobian's steps in the other shapes (the same loop again); the rows and
    # their branches change only with set_rows, which clears the cache
    key = (isinstance(rows, slice), problem.hysteresis_centred,
           *(float(th[k]) for k in ("T_s", "rho", "n", "z0", "first_scale")))
    kept = problem.cache.setdefault("hysteresis", {})
    if key not in kept:
        z = fx.hysteresis_state(torque, th["T_s"], th["rho"], th["n"], branches, th["z0"],
                                th["first_scale"])
        if problem.hysteresis_centred:
            z = z - fx.loop_centre(torque, th["T_s"], th["rho"], th["n"],
                                   problem.scales["T0"])
        if len(kept) >= _LOOPS_KEPT:
            del kept[next(iter(kept))]
        kept[key] = z
    return kept[key]


_LOOPS_KEPT = 8


def _through_gear(problem: Problem, torque: np.ndarray, theta: dict) -> np.ndarray:
    """K1 × the catalog curve's local compliance [-]: a friction torque's twist through the
    gear's spring, relative to its twist on the first segment."""
    return problem.base.curve.K1 * baselines.catalog_compliance(
        problem.base.curve, torque, theta.get("catalog.corner_width", 0.0))


def _stop_states(problem: Problem, torque: np.ndarray, branches, rows) -> np.ndarray:
    """The friction elements' states s/R (n × K) on the rows (:mod:`.plays`, their slip
    torques growing with the torque carried by ``problem.plays_load_share``), less their
    centre lines when the loop is drawn about the catalog curve; kept until set_rows."""
    mu, t0 = problem.plays_load_share, problem.scales["T0"]
    key = ("plays", isinstance(rows, slice), problem.hysteresis_centred, mu)
    if key not in problem.cache:
        for other in [k for k in problem.cache
                      if isinstance(k, tuple) and k[0] == "plays" and k[3] != mu]:
            del problem.cache[other]  # one load share at a time: each is n × 16
        r = plays.thresholds(t0)
        S = plays.stop_states(torque, r, branches, mu, t0)
        if problem.hysteresis_centred:
            S = S - plays.centre_lines(torque, r, t0, mu)
        problem.cache[key] = S
    return problem.cache[key]


def stribeck_takes(problem: Problem, effect: str) -> bool:
    """Whether the problem's Stribeck law stands in for the effect's factor: the low-load
    one when its pressure exponent r > 0, the temperature law when its slope b > 0."""
    if problem.hersey is None:
        return False
    return {"low_load_efficiency": problem.hersey[1] > 0,
            "temperature_dependence": problem.hersey[2] > 0}.get(effect, False)


def _stribeck(problem: Problem, inp: dict) -> np.ndarray:
    """The Stribeck law's loss terms on the rows of ``inp`` at the problem's Hersey shapes
    (boundary scale H_b, pressure exponent r, viscosity slope b [1/K]; r = 0 where the
    law does not take the load, b = 0 where it does not take the temperature)."""
    scale, load, slope = problem.hersey
    g = (laws.viscosity_ratio(inp["temperature_C"], slope, laws.REFERENCE_TEMPERATURE_C,
                              problem.viscosity_C) if slope else 1.0)
    return laws.stribeck_terms(laws.hersey_number(inp["input_speed_rpm"], inp["alpha"], g,
                                                  load), scale)


def _viscosity(problem: Problem, effects: tuple[str, ...], theta: dict, inp: dict
               ) -> np.ndarray | None:
    """ν(t)/ν(20 °C) of the named temperature law on the rows of ``inp``, for a drag that
    grows with viscosity; the Stribeck law's own when it stands in for the temperature law
    (one viscosity in the model)."""
    if not problem.drag_viscosity_exponent or "temperature_dependence" not in effects:
        return None
    if stribeck_takes(problem, "temperature_dependence"):
        return laws.viscosity_ratio(inp["temperature_C"], problem.hersey[2],
                                    laws.REFERENCE_TEMPERATURE_C, problem.viscosity_C)
    return laws.temperature_ratio(inp["temperature_C"],
                                  theta[key_of("temperature_dependence", "b")],
                                  laws.REFERENCE_TEMPERATURE_C, problem.viscosity_C,
                                  problem.temperature_band)
