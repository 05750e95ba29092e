"""The form of a named hysteresis loop, chosen once the effect is named: the Bouc–Wen loop
(with which it is named) about its own backbone or about the catalog curve, with a constant
compliance or through the gear's, and a Preisach relay sum (:mod:`.preisach`).

None changes which effects are named; each is kept when it follows the data more closely,
and says so in the notes.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from scipy.optimize import least_squares

from . import effects as fx
from .fitting import Fit, Problem, columns, finish, fit_model, solve
from .gates import bic_best, effective_n

THROUGH_GEAR = ("hysteresis: a friction torque in parallel with the gear's spring (its twist "
                "the torque × the catalog curve's local compliance)")


CENTRED = ("hysteresis: a loop about the catalog curve (the curve is the mean of loading "
           "and unloading; the loop's own centre line taken out)")


def refine_hysteresis(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis in whichever combination of the loop's forms fits best (same
    parameters):

    - about the catalog curve (:data:`CENTRED`): the catalog's curve is the mean of loading
      and unloading, so the loop adds no backbone of its own;
    - as a friction torque in parallel with the gear's spring (:data:`THROUGH_GEAR`): its
      twist is the torque times the catalog curve's local compliance, so the loop narrows
      past T1 and T2 where the gear stiffens.

    References: Seyfferth, W., Maghzal, A. J., Angeles, J. (1995) "Nonlinear modeling and
    parameter identification of harmonic drive robotic transmissions", Proc. IEEE ICRA;
    Tjahjowidodo, T., Al-Bender, F., Van Brussel, H. (2006) ISMA, Leuven.
    """
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.hysteresis_series):
        return fit
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear)
    best, form = fit, named
    for trial_form in itertools.product((False, True), repeat=2):
        if trial_form == named:
            continue
        problem.hysteresis_centred, problem.hysteresis_through_gear = trial_form
        trial = fit_model(problem, fit.effects, fit.theta)
        if trial.rss < best.rss:
            best, form = trial, trial_form
    problem.hysteresis_centred, problem.hysteresis_through_gear = form
    for used, was, text, than in zip(form, named, (CENTRED, THROUGH_GEAR),
                                     ("a loop with its own backbone", "a constant compliance")):
        if used and not was:
            problem.notes.append(f"{text} fits {math.sqrt(fit.rss / best.rss):.2f}× closer "
                                 f"than {than}")
    return best


PREISACH = ("hysteresis: a Preisach relay sum (slip torques lognormal about {w:.3g} N·m, "
            "log-spread {s:.2f}; relay centres spread {c:.3g} N·m)")
# bounds of the Preisach density: median slip torque and centre spread as shares of T0,
# the log-spread of the slip torques
_PREISACH_BOUNDS = np.array([(0.01, 1.5), (0.1, 1.5), (0.005, 3.0)])
_PREISACH_STARTS = list(itertools.product((0.03, 0.1, 0.3, 0.8), (0.3, 1.0), (0.03, 0.3, 2.0)))
_PREISACH_EVALUATIONS = 60


def preisach_forms(problem: Problem, fit: Fit) -> list[tuple[Fit, tuple, tuple]]:
    """(fit, density, (centred, through the gear)) of the hysteresis in ``fit`` as a
    Preisach relay sum in each of its four forms, its other shapes held; leaves the
    problem's loop form as it found it."""
    t0 = problem.scales["T0"]
    scale = np.array([t0, 1.0, t0])
    # the fit's shapes in use (a play's holding torque included), the loop's five Bouc–Wen
    # shapes replaced by the density's three
    bw_shapes = len(fx.nonlinear_parameters("hysteresis", problem.kind))
    shapes = fit.n_params - int(np.count_nonzero(fit.beta)) - bw_shapes + len(scale)
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear,
             problem.hysteresis_preisach)
    trials = []
    try:
        for form in itertools.product((False, True), repeat=2):
            problem.hysteresis_centred, problem.hysteresis_through_gear = form
            trials.append((*_fit_density(problem, fit, scale, shapes), form))
    finally:
        (problem.hysteresis_centred, problem.hysteresis_through_gear,
         problem.hysteresis_preisach) = named
    return trials


def use_preisach(problem: Problem, density: tuple, form: tuple) -> None:
    """Set the problem's loop to the Preisach relay sum ``density`` in ``form``."""
    (problem.hysteresis_centred, problem.hysteresis_through_gear) = form
    problem.hysteresis_preisach = density


def refine_preisach(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as a Preisach relay sum (:class:`.preisach.PreisachPlane`: three
    density parameters instead of the Bouc–Wen loop's five) about its own backbone or about
    the catalog curve, kept when BIC (effective sample size N/τ) prefers it; leaves
    ``problem.hysteresis_preisach`` at its density, or None.

    The Bouc–Wen loop has no memory of earlier turning points: under cycles of several
    amplitudes its minor loops neither close nor follow the major loop's branches, which
    the friction of many tooth contacts (a Preisach system) does.

    References: Mayergoyz, I. D. (1991) *Mathematical Models of Hysteresis*, Springer;
    Della Torre, E. (1999) *Magnetic Hysteresis*, IEEE Press.
    """
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.hysteresis_series
            or problem.hysteresis_preisach is not None):  # named in that form already
        return fit
    best, density, form = min(preisach_forms(problem, fit), key=lambda t: t[0].rss)
    n_eff = effective_n(problem, best.residual(problem))
    if not bic_best({False: (fit.rss, fit.n_params), True: (best.rss, best.n_params)}, n_eff):
        return fit
    use_preisach(problem, density, form)
    w, s, c = density
    problem.notes.append(PREISACH.format(w=w, s=s, c=c)
                         + (", about the catalog curve" if form[0] else "")
                         + (", through the gear's compliance" if form[1] else "")
                         + f", fits {math.sqrt(fit.rss / best.rss):.2f}× closer than the "
                         "Bouc–Wen loop (BIC)")
    return best


def _fit_density(problem: Problem, fit: Fit, scale: np.ndarray, shapes: int
                 ) -> tuple[Fit, tuple[float, float, float]]:
    """The Preisach density (bounded least squares in its logarithms from the best of a
    few starts) with the other shapes held at ``fit``'s, and its :class:`Fit`."""
    lo, hi = np.log(_PREISACH_BOUNDS[:, 0]), np.log(_PREISACH_BOUNDS[:, 1])
    unit = math.sqrt(fit.rss / len(problem.rows)) or 1.0

    def residual(x):
        problem.hysteresis_preisach = tuple(np.exp(x) * scale)
        X, _, low, high = columns(problem, fit.effects, fit.theta)
        return (problem.y - X @ solve(X, problem.y, low, high)) / unit

    starts = [np.log(np.array(x0)) for x0 in _PREISACH_STARTS]
    x0 = min(starts, key=lambda x: float(np.sum(residual(x) ** 2)))
    found = least_squares(residual, x0, bounds=(lo, hi), max_nfev=_PREISACH_EVALUATIONS,
                          diff_step=1e-3)
    density = tuple(float(v) for v in np.exp(found.x) * scale)
    problem.hysteresis_preisach = density
    return finish(problem, fit.effects, fit.theta, shapes), density
