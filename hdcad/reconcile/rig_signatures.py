"""A measurement effect's own signature, beyond a better fit.

A rig effect is named only where the data show what makes it the rig's: an encoder's
interpolation ripple is the same over the whole span of the angle it reads; a reading's play
keeps the branches apart at the torque's extremes, where a loop of the gear closes; a torque
channel's gain moves the catalog curve's corners; a drive's ripple is what rings where its
resonance crossing is; a gain that changed once is a sharp step, not a drift; a drift that
restarts in each temperature block goes the residual's way in most blocks. The search
(:mod:`.search`) weighs every candidate with its signature first.
"""

from __future__ import annotations

import numpy as np

from . import drive, encoder_ripple, rig
from . import effects as fx
from .fitting import Fit, Problem, fit_model
from .gates import BIC_MIN, bic_gain, effective_n
from .noise import noise_rms


# measurement effects whose signature may not show, so that its absence does not tell
# against them: a torque channel's gain within the stiffness spread moves the catalog
# curve's corners too little to see (a play of the reading that does not stay apart at the
# tips, or an interpolation ripple that is not everywhere, is told apart by its absence)
UNSEEN = {("torsion", "sensor_gain")}


def own_signature(problem: Problem, name: str, without: Fit, fit: Fit) -> bool:
    """A measurement effect's own signature, beyond a better fit: an encoder's
    interpolation ripple is the same over the whole span of the angle; a reading's play
    keeps the branches apart at the torque's extremes, where a loop of the gear closes; a
    torque channel's gain moves the catalog curve's corners; a drive's ripple is what rings
    where its resonance crossing is."""
    inputs, rows = problem.base.inputs, problem.rows
    if name == "sensor_gain" and problem.kind == "torsion":
        return _corners_moved(problem, without, fit)
    if name == "sensor_play":
        return rig.apart_at_the_tips(without.residual(problem), inputs["torque_Nm"][rows],
                                     inputs["branch_direction"][rows])
    if name == "drive_ripple":
        return drive.coherent_at_crossing(problem, without, fit)
    if name == "sensor_gain" and problem.kind == "efficiency":
        return _sharp_step(problem, without, fit)
    if name == "block_drift":
        own = np.array([e == name for e, _ in fit.labels])
        return rig.same_in_blocks(without.residual(problem), fit.columns[:, own] @ fit.beta[own],
                                  inputs["block_position"][rows])
    if name != "encoder_interpolation":
        return True
    angle = inputs["measured_rad"][rows]
    if problem.kind == "transmission" and not _output_ripple(problem, without, fit, angle):
        return False
    return encoder_ripple.ripple_everywhere(without.residual(problem), fit.residual(problem), angle)


# A gain step explains at least this many noise variances (its place is chosen where the
# residual's cumulative sum strays furthest, which a short record's correlated noise also
# offers: suite C's clean AR(1) grid of 72 rows gave a step of 0.73).
STEP_EXPLAINED_MIN = 1.0


def _sharp_step(problem: Problem, without: Fit, fit: Fit) -> bool:
    """A gain that changed at one row is a step, not a slow drift or the noise: the step
    (``fit``) explains ``STEP_EXPLAINED_MIN`` noise variances and beats a drift with test
    time in its place by more than ``BIC_MIN``."""
    residual = fit.residual(problem)
    sigma = noise_rms(residual)
    if not (without.rss - fit.rss) / len(residual) >= STEP_EXPLAINED_MIN * sigma ** 2:
        return False
    if "thermal_drift" in without.effects:  # a drift is in the model already
        return True
    drift = fit_model(problem, without.effects + ("thermal_drift",), without.theta)
    return bic_gain(drift, fit, effective_n(problem, residual)) > BIC_MIN


def _output_ripple(problem: Problem, without: Fit, fit: Fit, angle: np.ndarray) -> bool:
    """An output encoder's ripple in transmission: away from the wave generator's orders
    (there it is as much the gear's error) and a line in the periodogram over the output
    angle, which runs one way over many of its periods (a drift with time is a continuum)."""
    period = fit.theta[fx.key_of("encoder_interpolation", "period")]
    return (encoder_ripple.off_the_gear_orders(period, problem.base.figures["ratio"][0],
                                    float(np.ptp(angle)))
            and encoder_ripple.is_line(without.residual(problem), angle, period))


def gear_orders_of(problem: Problem) -> tuple[tuple[float, ...], float, bool]:
    """The WG orders an output encoder's ripple is kept from in transmission, and that its
    period is looked for finely there (the output angle runs one way over many periods);
    neither in torsion, where the measured angle is the twist."""
    if problem.kind != "transmission":
        return (), 0.0, False
    angle = problem.base.inputs["measured_rad"][problem.rows]
    return encoder_ripple.gear_orders(problem.base.figures["ratio"][0], float(np.ptp(angle))) + (True,)


def _corners_moved(problem: Problem, without: Fit, fit: Fit) -> bool:
    """A curve only softer or stiffer than the catalog beyond its spread (a twist sensor's
    gain, a gear out of its scatter) is fitted by a torque gain too, which then moves the
    corners as little as it can: with the compliance scale left free in both, the gain
    (``fit``) must still lower the BIC by more than ``BIC_MIN`` below ``without``."""
    problem.scale_free = True
    try:
        free = fit_model(problem, without.effects, without.theta)
        gained = fit_model(problem, fit.effects, fit.theta)
    finally:
        problem.scale_free = False
    return bic_gain(free, gained, effective_n(problem, gained.residual(problem))) > BIC_MIN
