"""The catalog's nuisances as fitted, and readings of the data that cannot be told apart.

A nuisance (stiffness scale, efficiency level, damping) is never reported as a missing
effect; one outside the catalog's spread is reported as what it is ("stiffness 14 % below
catalog"). Some effects are data-equivalent to a nuisance or to the rig: a much softer gear
reads exactly like a series housing spring, a once-per-input-revolution transmission error
like an eccentric input encoder, a temperature effect in a test that warms steadily like a
drift with test time. The report then gives both readings.
"""

from __future__ import annotations

import math

import numpy as np

from . import tips
from .baseline import STIFFNESS_SPREAD, catalog_twist
from .fitting import Fit, Problem
from .gates import BIC_MIN
from .rig import RIG_EFFECTS

# |correlation| of temperature with test time above which a temperature effect and a drift
# of the rig with time cannot be told apart.
TIME_TEMPERATURE_CORRELATION = 0.8

# A gear that reads softer than the catalog by at least this share without a housing spring
# is also read as a series spring, or a named spring as that softer gear, within the spread
# or beyond it (a spring of under 1 % of the gear's compliance is not worth a line in the
# report).
SOFTER_READING_MIN = 0.01

# Rig readings that a test of this kind cannot tell from the named gear effect, whatever the
# data: the same physics sits in the rig's torque or angle path (Seed 000 p.020: the twist
# is measured with the input locked, so friction, play and compliance of the lock and the
# couplings add to the gear's; p.023: efficiency from input and output torque includes any
# drag between the sensors and the gear). Given with every such effect so that the reviewer
# knows what to check on the rig before changing the model.
RIG_READINGS = {
    ("torsion", "hysteresis"): (
        "rig_friction", "friction in the input lock, bearings or couplings between the torque "
        "sensor and the gear makes the same loop: the gear's hysteresis, or the rig's"),
    ("torsion", "backlash"): (
        "rig_play", "play in a coupling, key or the input lock reads the same as the gear's "
        "lost motion"),
    ("efficiency", "low_load_efficiency"): (
        "rig_drag", "a drag torque in the rig's input path (bearings, seals, coupling) lowers "
        "the measured efficiency at low load the same way"),
    ("efficiency", "temperature_dependence"): (
        "torque_sensor_temperature", "a torque sensor whose gain changes with temperature "
        "reads the same as an efficiency that changes with it"),
    ("vibration", "te_1x"): (
        "drive_once_per_revolution", "an excitation of the drive once per input revolution "
        "(motor or coupling misalignment, unbalance) excites the resonance the same way"),
    ("vibration", "te_2x"): (
        "drive_twice_per_revolution", "a torque ripple of the drive twice per input revolution "
        "(a universal joint, the motor) excites the resonance the same way"),
}


def _beta(fit: Fit, name: str) -> float | None:
    for (effect, label), value in zip(fit.labels, fit.beta):
        if effect == "baseline" and label == name:
            return float(value)
    return None


def _scale_entry(name: str, value: float, what: str) -> dict:
    within = abs(value - 1.0) <= STIFFNESS_SPREAD
    side = "above" if value > 1 else "below"
    text = (f"{what} {abs(value - 1):.1%} {side} catalog "
            + ("(within" if within else "(outside") + f" the assumed ±{STIFFNESS_SPREAD:.0%})")
    return {"name": name, "value": value, "unit": "-", "spread": STIFFNESS_SPREAD,
            "within_spread": within, "text": text}


def free_scale(problem: Problem, fit: Fit) -> float | None:
    """Compliance scale of ``fit`` refitted without the spread's bounds and without a series
    spring (which would take the same share): what the data say about the gear's stiffness.
    None where the baseline has no compliance scale (every kind but torsion)."""
    names = [label for label in fit.labels]
    if ("baseline", "compliance_scale") not in names:
        return None
    keep = [i for i, (e, _) in enumerate(names) if e != "housing_compliance"]
    beta = np.linalg.lstsq(fit.columns[:, keep], problem.y, rcond=None)[0]
    return float(beta[[names[i] for i in keep].index(("baseline", "compliance_scale"))])


def nuisances(problem: Problem, fit: Fit) -> list[dict]:
    """Fitted nuisance parameters of the catalog model, each with a sentence."""
    out = []
    s = free_scale(problem, fit)
    if s is not None and s > 0:
        entry = _scale_entry("stiffness_scale", 1.0 / s, "stiffness")
        out.append({**entry, "reads_as": ["sensor_gain"],  # every segment scaled alike
                    "text": entry["text"] + "; a twist sensor's gain reads the same"})
        printed = _beta(fit, "printed_reading")
        if printed is not None:
            share = printed / _beta(fit, "compliance_scale")
            out.append({"name": "printed_reading", "value": share, "unit": "-",
                        "text": f"catalog curve {share:.0%} of the way from the T/K data to "
                                "the printed θ1/θ2"})
        width = fit.theta.get("catalog.corner_width")
        if width is not None:
            out.append({"name": "corner_width", "value": width, "unit": "N·m",
                        "text": f"curve corners at T1/T2 spread over {width:.3g} N·m"})
    if "stiffness_scale" in fit.theta:
        out.append(_scale_entry("stiffness_scale", fit.theta["stiffness_scale"],
                                "joint stiffness"))
    if "damping_ratio" in fit.theta and problem.steady_state:
        eta = 2.0 * fit.theta["damping_ratio"]
        out.append({"name": "loss_factor", "value": eta, "unit": "-",
                    "text": f"structural loss factor η = {eta:.3g} (damps the resonance as a "
                            f"viscous ζ = {eta / 2:.3g})"})
    elif "damping_ratio" in fit.theta:
        where = " (a damper on the joint's twist)" if problem.relative_damping else ""
        out.append({"name": "damping_ratio", "value": fit.theta["damping_ratio"], "unit": "-",
                    "text": f"damping ratio {fit.theta['damping_ratio']:.3g}{where}"})
    eta = _beta(fit, "eta0")
    if eta is not None:
        out.append({"name": "efficiency_level", "value": eta, "unit": "%",
                    "text": f"efficiency level η0 = {eta:.3g} % (the catalog's curves are "
                            "lost: the level is not compared); a torque or speed channel's "
                            "gain reads the same", "reads_as": ["sensor_gain"]})
    slope = _beta(fit, "eta_speed")
    if slope is not None:
        per_doubling = slope * np.log(2.0)
        out.append({"name": "efficiency_speed", "value": per_doubling, "unit": "%",
                    "text": f"efficiency {'rises' if per_doubling > 0 else 'falls'} by "
                            f"{abs(per_doubling):.3g} %-points per doubling of input speed "
                            "(the catalog's efficiency curves per speed are lost: not "
                            "compared)"})
    return out


def series_slip(problem: Problem, final: Fit, tied: bool) -> list[dict]:
    """The other reading of a hysteresis named as slip in series with the gear: friction
    in parallel plus a housing spring of the loop's own slip compliance; with where the
    final model's loop puts its turning points against the catalog curve (:mod:`.tips`)."""
    if not tied:
        return []
    out = {"alternative": ["hysteresis", "housing_compliance"], "reading": "series_slip",
           "text": "the loop is read as slip in series with the gear (Iwan, Preisach): "
                   "friction in parallel with the gear plus a housing spring of the loop's "
                   "own slip compliance (slip_compliance) reads the same; check the "
                   "housing's stiffness before stiffening it"}
    # a spring named beside the loop as well would be left out of the figure: none then
    scale = None if "housing_compliance" in final.effects else tips.tip_scale(problem, final)
    if scale is not None:
        out["stiffness_at_turning_points"] = {"value": 1.0 / scale, "unit": "-"}
        out["text"] += "; " + tips.text(scale)
    return [out]


def loop_in_series(added: dict[str, float] | None) -> list[dict]:
    """The other reading of a housing spring named beside a loop when it adds too little
    over the loop alone in series with the gear (``added``: its ΔBIC and explained noise
    variances there): one loop that carries its own compliance."""
    if added is None:
        return []
    return [{"alternative": ["hysteresis"], "reading": "loop_in_series",
             "text": f"the loop alone, as friction elements in series with the gear that "
                     f"soften past their slip torques, reads almost the same: the spring "
                     f"adds ΔBIC {added['delta_bic']:.1f} and {added['explained']:.2f}× the "
                     "noise variance over it, less than a second effect must; the spring may "
                     "be the loop's own compliance (a slider that hardens, a joint in "
                     "microslip): check the housing's stiffness before stiffening it"}]


def held_play(found: dict | None) -> list[dict]:
    """The other reading of a named loop that a play held by friction reads about as well
    as (``found``: the model's effects with the play in the loop's place, the play's ΔBIC
    over the loop, its holding torque [N·m] and lost motion [rad])."""
    if found is None:
        return []
    gear = [e for e in found["effects"] if e not in RIG_EFFECTS]
    return [{"alternative": gear, "reading": "held_play",
             "text": f"a play held by friction in place of the loop reads about the same "
                     f"(ΔBIC {found['delta_bic']:+.1f}): lost motion "
                     f"{found['lost_motion']:.3g} rad, held until the load passes "
                     f"{found['hold']:.3g} N·m in the new direction, a loop as wide at every "
                     "torque; a loop that narrows towards its turning points tells friction "
                     "in the gear, one that keeps its width a play (the Oldham coupling's "
                     "clearance, held by the back-driving friction)"}]


def progressive_spring(read: bool) -> list[dict]:
    """The other reading of a housing spring named for its stiffening: a backlash taken up
    slowly."""
    if not read:
        return []
    return [{"alternative": ["backlash"], "reading": "progressive_spring",
             "text": "the extra twist grows ever more slowly with torque up to T0: read as a "
                     "series spring that stiffens (contact closing gradually, bolted joints); "
                     "a clearance taken up over the same wide torque band reads about the "
                     "same, but the catalog's lost motion is taken up within ±3 % of the "
                     "torque its spring constant is given at (FD table 314-1)"}]


def undecided(named: tuple[str, ...], rivals: tuple[str, ...], rmse: dict[str, float],
              sigma: float, unit: str) -> list[dict]:
    """The reading of a second effect left unnamed because two fit about equally, with the
    RMSE [``unit``] each leaves beside ``named`` (``rmse``, by rival) and that RMSE over
    the noise RMS ``sigma`` [``unit``]: how much of what is left either would explain."""
    if not rivals:
        return []
    rmse = {r: v for r, v in rmse.items() if r in rivals and math.isfinite(v)}

    def each(rival: str) -> str:
        if rival not in rmse:
            return rival
        ratio = (f", {rmse[rival] / sigma:.2f}× the noise" if sigma > 0 and
                 math.isfinite(sigma) else "")
        return f"{rival} (RMSE {rmse[rival]:.3g}{' ' + unit if unit else ''}{ratio})"

    return [{"undecided": list(rivals), "beside": list(named), "rmse": rmse,
             "text": f"what {' + '.join(named)} leaves is explained about equally well by "
                     f"{each(rivals[0])} or by {each(rivals[1])}: neither is named (the "
                     f"shape {' + '.join(named)}'s formula misses, or either effect; a test "
                     "that separates them decides)"}]


def rig_near(rows: list[dict], named: tuple[str, ...], alone: dict[str, float],
             given: list[dict]) -> list[dict]:
    """A measurement effect of the rig search's last round (``rows``) that passed the gates
    and came within ``BIC_MIN`` below the best gear effect alone, or above it without its
    own signature (a torque channel's gain whose corners do not move beyond the spread),
    given beside the first gear effect named (ΔBIC alone over the same model, ``alone``)
    unless a reading ``given`` already offers it: the gear's reading is kept by less than
    the naming margin, so the reviewer checks the rig before changing the model (a drift
    driven by the test's own work builds up on each loading and can read as a loop)."""
    if not named or named[0] not in alone:
        return []
    first = named[0]
    offered = {r.get("measurement") for r in given if first in r.get("effects", ())}
    out = []
    for row in rows:
        if not row.get("near_gear") or row["effect"] in offered:
            continue
        words = _first_clause(row["effect"])
        out.append({"effects": [first], "measurement": row["effect"],
                    "text": f"the rig's {row['effect']} ({words}) explains about as much as "
                            f"{first} (ΔBIC {row['delta_bic']:.1f} against "
                            f"{alone[first]:.1f}, closer than the naming margin "
                            f"{BIC_MIN:g}, or more without the rig effect's own signature): "
                            "check the rig before changing the model"})
    return out


def twin_set_aside(set_aside: dict[str, float], named: tuple[str, ...]) -> list[dict]:
    """The other reading of the gear effects named in place of a measurement effect that
    they beat by less than ``BIC_MIN`` (``set_aside``: the effect and the ΔBIC the gear
    effects won by): a torque channel's gain that reads nearly as a series spring."""
    if not named:
        return []
    return [{"effects": list(named), "measurement": effect,
             "text": f"the rig's {effect} ({_first_clause(effect)}) was set aside for "
                     f"{' + '.join(named)}, which fit better by ΔBIC {gain:.1f} only, closer "
                     f"than the naming margin {BIC_MIN:g}: the rig's reading stays open; "
                     "check its calibration before changing the model"}
            for effect, gain in set_aside.items()]


def _first_clause(effect: str) -> str:
    """The first clause of a measurement effect's description, lower-cased."""
    words = RIG_EFFECTS[effect].description
    cuts = [i for i in (words.find(c) for c in (":", ";", ". ")) if i > 0]
    words = words[:min(cuts)] if cuts else words
    return f"{words[0].lower()}{words[1:]}"


def _spring_reading(problem: Problem, stiffness: float, within: bool, named: bool) -> dict:
    """A gear softer than the catalog, read as a gear at its catalog stiffness with a series
    spring that adds the same twist at the test's largest torque (the spring's compliance is
    the same at every torque, the scale's follows the curve: at these data the two read
    alike). A spring named while the gear without it reads within the spread is told from
    that gear only by its shape, which the text says."""
    out = {"effects": ["housing_compliance"], "nuisance": "stiffness_scale"}
    if named and within:
        return {**out, "text": f"without the spring the gear reads {1 - stiffness:.1%} softer "
                "than the catalog, within its spread: that gear with no spring is the other "
                "reading, told apart only by how the compliance runs with the torque (a "
                "linear spring's is the same at every torque, a softer gear's follows the "
                "curve); the housing's own stiffness decides"}
    torque = float(np.max(np.abs(problem.base.inputs["torque_Nm"])))
    secant = float(catalog_twist(problem.base.curve, np.array([torque]), 0.0)[0]) / torque
    spring = stiffness / ((1 - stiffness) * secant)
    return {**out, "text": f"the gear reads {1 - stiffness:.1%} softer than the catalog"
                           + (", within its spread" if within else "")
                           + "; a gear at its catalog stiffness with a series spring (housing, "
                           f"shafts) of about {spring:.3g} N·m/rad reads the same: the "
                           "housing's own stiffness decides"}


def equivalent(problem: Problem, fit: Fit, named: tuple[str, ...], found: list[dict]
               ) -> list[dict]:
    """Readings the data cannot tell apart from what was named or fitted."""
    out = []
    stiffness = next((n for n in found if n["name"] == "stiffness_scale"), None)
    if problem.kind == "torsion" and stiffness and problem.base.curve is not None:
        # a named spring may be a gear softer, beyond the spread or (but for the spring's
        # shape) within it; a gear softer within it may be a spring not named
        if stiffness["value"] < 1 - SOFTER_READING_MIN:
            out.append(_spring_reading(problem, stiffness["value"], stiffness["within_spread"],
                                       "housing_compliance" in named))
    if problem.kind == "transmission" and "te_1x" in named:
        out.append({"effects": ["te_1x"], "measurement": "encoder_eccentricity",
                    "text": "once per WG revolution: the gear's transmission error, or an "
                            "eccentric input encoder (the data read the same)"})
    if problem.kind == "transmission" and "te_2x" in named:
        out.append({"effects": ["te_2x"], "measurement": "sensor_gain",
                    "text": "twice per WG revolution: the gear's transmission error, or the "
                            "input angle sensor's own 2× error (a resolver's sine/cosine gain "
                            "imbalance, an elliptical encoder disc; the data read the same)"})
    # both ways: a temperature law named, or a drift with time named in its place
    if problem.kind == "efficiency" and ("temperature_dependence" in named
                                         or "thermal_drift" in fit.effects):
        t = problem.base.inputs["temperature_C"]
        u = problem.base.inputs["record_position"]
        if np.ptp(t) > 0 and abs(np.corrcoef(t, u)[0, 1]) > TIME_TEMPERATURE_CORRELATION:
            out.append({"effects": ["temperature_dependence"], "measurement": "thermal_drift",
                        "text": "the temperature rose with test time: the efficiency's "
                                "change with temperature, or a drift of the rig with time "
                                "(the data read the same)"})
    for effect in named:
        if (problem.kind, effect) in RIG_READINGS:
            rig, text = RIG_READINGS[(problem.kind, effect)]
            out.append({"effects": [effect], "measurement": rig,
                        "text": text + " (this test alone cannot tell them apart: check the rig)"})
    return out
