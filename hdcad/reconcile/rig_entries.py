"""The measurement effects as reported: their parameters, a sentence where one number says
what to fix on the rig, and the rig's readings the baseline holds (a transmission test's
output gain, a torsion test's twist zero), reported where they are significant."""

from __future__ import annotations

import math

import numpy as np

from .drive import crossing_rpm
from .fitting import Fit, Problem
from .gates import BIC_MIN, EXPLAINED_MIN, rss_bic_gain
from .params import linear_of
from .rig import RIG_EFFECTS, STEPPED, TORQUE_GAIN_KEY, TORQUE_OFFSET_KEY, block_starts
from .rig import columns as rig_columns


def rig_params(problem: Problem, fit: Fit, effect: str) -> dict[str, dict]:
    """A measurement effect's parameters [unit of the data unless stated]."""
    b = linear_of(fit, effect)
    unit = problem.base.unit
    out = {k: {"value": v, "unit": p.unit if p.unit == "-" else unit}
           for k, v in b.items() for p in RIG_EFFECTS[effect].parameters if p.name == k}
    if (effect, problem.kind) in STEPPED:
        out["at_record_position"] = {"value": problem.step_position, "unit": "-"}
    if effect == "thermal_drift":
        out["tau"] = {"value": fit.theta["thermal_drift.tau"], "unit": "half-records"}
    if effect == "block_drift":
        out["tau"] = {"value": fit.theta["block_drift.tau"], "unit": "median block lengths"}
    if effect == "encoder_interpolation":
        out["period"] = {"value": fit.theta["encoder_interpolation.period"], "unit": unit}
        out["amplitude"] = {"value": math.hypot(b["a1"], b["b1"]), "unit": unit}
    if effect == "drive_ripple":
        stiffness = fit.theta.get("stiffness_scale", 1.0)
        out["order"] = {"value": problem.drive_order, "unit": "per input revolution"}
        out["amplitude"] = {"value": math.hypot(b["a"], b["b"]), "unit": unit}
        out["resonance_speed"] = {"value": crossing_rpm(problem, problem.drive_order,
                                                        stiffness), "unit": "r/min"}
        out["damping_ratio"] = {"value": fit.theta["damping_ratio"], "unit": "-"}
        out["stiffness_scale"] = {"value": stiffness, "unit": "-"}
    if effect == "encoder_eccentricity":
        out["amplitude"] = {"value": math.hypot(b["a"], b["b"]), "unit": unit}
    if effect == "sensor_gain" and TORQUE_GAIN_KEY in fit.theta:
        out["torque_gain"] = {"value": fit.theta[TORQUE_GAIN_KEY], "unit": "-"}
    if effect == "torque_offset":
        out["T_off"] = {"value": fit.theta[TORQUE_OFFSET_KEY], "unit": "N·m"}
    return out


def rig_entry(problem: Problem, fit: Fit, effect: str) -> dict:
    """A measurement effect as reported: its parameters and, where one number says what to
    fix on the rig, a sentence (a torque channel's gain)."""
    params = rig_params(problem, fit, effect)
    entry = {"effect": effect, "params": params}
    if "torque_gain" in params:
        g = params["torque_gain"]["value"]
        entry["reading"] = (f"the torque channel reads {abs(g):.1%} {'high' if g > 0 else 'low'} "
                            f"(torque_gain = {g:.4g}; a shunt or calibration constant): the "
                            f"catalog curve's corners sit at {1 + g:.3f} × T1 and T2 of the "
                            "recorded torque")
    if effect == "drive_ripple":
        entry["reading"] = (
            f"an excitation {problem.drive_order} times per input revolution (amplitude "
            f"{params['amplitude']['value']:.3g} rad at the output) meets the load's "
            f"resonance at {params['resonance_speed']['value']:.4g} r/min: the drive's "
            "torque ripple (a motor's cogging or electrical ripple), or a harmonic of the "
            "gear's own error the catalog does not name; check the motor and coupling")
    if effect == "block_drift":
        entry["reading"] = _block_drift_reading(problem, params)
    if "gain_step" in params:
        row = int(np.searchsorted(problem.base.inputs["record_position"], problem.step_position))
        entry["reading"] = (f"the efficiency reads {params['gain_step']['value']:+.3g} %-points "
                            f"from row {row + 1} on: a channel's gain changed during the test "
                            "(a torque range switched, a recalibration)")
    if "T_off" in params:
        entry["reading"] = (f"the torque channel's zero is off by {params['T_off']['value']:.4g} "
                            "N·m (an untared bridge, a tare taken under load): the gear "
                            "carries the recorded torque less that")
    return entry


def _block_drift_reading(problem: Problem, params: dict[str, dict]) -> str:
    """What a per-block drift says: how far it goes within a block, in how many blocks."""
    v = problem.base.inputs["block_position"]
    grid = np.linspace(0.0, float(v.max()), 201)
    labels, cols = rig_columns("block_drift", problem.kind, {"record_position": grid,
                                                             "block_position": grid},
                               problem.step_position, {"tau": params["tau"]["value"]})
    drift = cols @ np.array([params[k]["value"] for k in labels])
    peak = float(drift[np.argmax(np.abs(drift))])
    unit = "%-points" if problem.base.unit == "%" else problem.base.unit
    return (f"the reading drifts by up to {peak:+.3g} {unit} within each of the "
            f"{len(block_starts(v))} temperature blocks and starts again at each "
            "(a channel re-zeroed as each block starts, then warming or creeping): let the "
            "rig settle, or zero it, before each block's first point")


# A steady-speed test: the WG angle and the record's time this closely in line make a drift
# of the output angle with time read as a gain of its sensor.
STEADY_SPEED_CORRELATION = 0.99


def output_gain_entry(problem: Problem, fit: Fit, sigma: float, tau: float) -> list[dict]:
    """Transmission: the output angle sensor's gain as a measurement effect (``sensor_gain``),
    where it is significant. The ratio is exact (tooth counts), so the baseline fits the
    output's slope error (``scale_error``) with the offset; it is reported when leaving it
    out raises the BIC by more than ``BIC_MIN`` (effective sample size N/τ, τ [rows]) and
    the residual by more than ``EXPLAINED_MIN`` noise variances (σ [rad]), and not beside
    a named eccentricity of the output encoder (over an arc of the output the two trade).
    The reading says when an eccentric output encoder or, at a steady speed, a drift with
    time reads the same. Empty otherwise."""
    label = ("baseline", "scale_error")
    if (problem.kind != "transmission" or label not in fit.labels or fit.columns is None
            or "encoder_eccentricity" in fit.effects):  # over an arc the two trade
        return []
    i = fit.labels.index(label)
    if not significant(problem, fit.columns, i, sigma, tau):
        return []
    inputs = problem.base.inputs
    out = inputs["output_angle_rad"][problem.rows]  # the output's turn [rad]
    eccentric = np.column_stack([fit.columns, np.sin(out), np.cos(out)])
    alike = not significant(problem, eccentric, i, sigma, tau)
    g = float(fit.beta[i])
    steady = abs(np.corrcoef(inputs["wg_angle_rad"], inputs["record_position"])[0, 1])
    text = (f"the output angle reads {abs(g) * 1e6:.0f} ppm {'high' if g > 0 else 'low'} "
            f"(g = {g:.3g}; the ratio is exact, so a slope error of the output is its "
            "sensor's: a scale constant, line count or roller diameter)")
    if alike:
        text += (f"; over the {math.degrees(float(np.ptp(out))):.0f}° of output this test "
                 "turns, an output encoder mounted off-centre (once per output revolution) "
                 "reads about the same")
    if steady > STEADY_SPEED_CORRELATION:
        text += ("; at this test's steady speed a drift of the output angle with test time "
                 "reads the same")
    reads_as = ["encoder_eccentricity"] * int(alike) + ["thermal_drift"] * int(
        steady > STEADY_SPEED_CORRELATION)
    return [{"effect": "sensor_gain", "params": {"g": {"value": g, "unit": "-"}},
             "reading": text, **({"reads_as": reads_as} if reads_as else {})}]


def twist_zero_entry(problem: Problem, fit: Fit, sigma: float, tau: float) -> list[dict]:
    """Torsion: the twist's zero off as a measurement effect (``angle_offset``, constant),
    where it is significant (as :func:`output_gain_entry`'s gain: leaving the baseline's
    offset out raises the BIC by more than ``BIC_MIN`` and the residual by
    ``EXPLAINED_MIN`` noise variances). The catalog curve passes through zero twist at zero
    torque, so a twist that reads otherwise there was zeroed under load or not zeroed. Only
    where no other effect is named: beside a gear effect the offset is as much the effect's
    (a play not centred, a loop that starts on one branch), beside a drift or a step of the
    angle the zero moves and the offset is its mean, beside a torque zero offset the twist
    follows the torque's. Empty otherwise."""
    label = ("baseline", "offset")
    if (problem.kind != "torsion" or label not in fit.labels or fit.columns is None
            or fit.effects):
        return []
    i = fit.labels.index(label)
    if not significant(problem, fit.columns, i, sigma, tau):
        return []
    offset = float(fit.beta[i])
    return [{"effect": "angle_offset", "params": {"offset": {"value": offset, "unit": "rad"}},
             "reading": f"the twist reads {offset:.3g} rad at zero torque, where the catalog "
                        "curve passes through zero: the twist was zeroed under load or not "
                        "at all (a tare taken under a preload, an encoder not homed)"}]


def significant(problem: Problem, columns: np.ndarray, i: int | list[int], sigma: float,
                 tau: float) -> bool:
    """Whether column(s) ``i`` of the design ``columns`` earn their place: leaving them out
    raises the BIC by more than ``BIC_MIN`` and the residual by ``EXPLAINED_MIN`` noise
    variances."""
    def rss(a: np.ndarray) -> float:
        beta = np.linalg.lstsq(a, problem.y, rcond=None)[0]
        return float(np.sum((problem.y - a @ beta) ** 2))

    n = len(problem.rows)
    n_eff = max(n / tau, 2.0)
    full, without = rss(columns), rss(np.delete(columns, i, axis=1))
    delta_bic = rss_bic_gain(without, full, int(np.size(i)), n_eff)
    explained = (without - full) / n / sigma ** 2 if sigma > 0 else math.inf
    return delta_bic > BIC_MIN and explained > EXPLAINED_MIN
