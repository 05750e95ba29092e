"""A named hysteresis whose loop widens with the torque or with the amplitude: two forms a
named loop may take once named, each kept only where BIC pays for it.

Friction whose slip torque grows with the torque carried. The teeth of a strain wave gear
slide on their flanks under a normal load that the transmitted torque sets, so the friction
torque that holds the flexspline back is not a constant: it is r + μ·|T|, a Coulomb friction
on flanks pressed together by the load. A loop of such friction is narrow at small torque
and widens towards the test's largest; a friction element of fixed slip torque saturates
instead, and its loop keeps one width once every element slips. The friction elements of
:mod:`.plays` take the load-dependent threshold r_k + μ·|T| (one share μ for all, found over
a few values); their weights stay amplitudes, fitted by bounded linear least squares as
before, in any of the parallel loop's forms (about its own backbone or the catalog curve,
with a constant compliance or through the gear's).

A Duhem loop whose height follows the last excursion (:mod:`.duhem`): the loss per cycle
grows with the amplitude, a memory of one half-cycle that neither the friction elements nor
a Preisach loop (whose minor loops close on their turning points) has.

References
----------
Tuttle, T. D.; Seering, W. P. (1996) "A nonlinear model of a harmonic drive gear
transmission", IEEE Trans. Robotics and Automation 12(3): 368-374 (mesh friction that
grows with the transmitted torque; a loss that grows with the amplitude).
Taghirad, H. D.; Bélanger, P. R. (1998) "Modeling and parameter identification of harmonic
drive systems", J. Dyn. Sys., Meas., Control 120(4): 439-444.
Brokate, M.; Sprekels, J. (1996) *Hysteresis and Phase Transitions*, Springer, ch. 2 (play
operators with a threshold that depends on the input).
Dhaouadi, R.; Ghorbel, F. H.; Gandhi, P. S. (2003) "A new dynamic model of hysteresis in
harmonic drives", IEEE Trans. Industrial Electronics 50(6): 1165-1171.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from scipy.optimize import minimize

from . import plays
from .fitting import Fit, Problem, finish, rss_at
from .gates import EXPLAINED_MIN, beyond
from .loops import DUHEM, FLANK, _replace_loop_notes, _set_plays_form, _shapes_beside_loop

# shares μ of the carried torque added to every slip torque (1-2-5 steps, then 0.2 apart):
# a flank friction coefficient (0.05–0.15 for lubricated steel on steel) times the ratio of
# the flanks' normal load to the tangential, from a loop that barely widens to one that is
# nearly all the load's (μ < 1: past that the friction would hold any torque)
LOAD_SHARES = (0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8)
# the share at which the loop's form is chosen (11 fits in place of 32, the same choices on
# suites B–L)
FORM_SHARE = 0.1
# the problem's settings that make the loop's form
_FORM = ("hysteresis_centred", "hysteresis_through_gear", "hysteresis_preisach",
         "hysteresis_plays", "plays_load_share", "hysteresis_duhem")


def _named_form(problem: Problem, fit: Fit) -> tuple[tuple, int] | None:
    """(the loop's form as named, to restore when a new one is not kept; the fit's shapes
    other than its loop's), or None when the loop may not take another form here: not
    torsion, no catalog curve or turning points, a slip element in series, creep."""
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.branches is None
            or problem.hysteresis_series or problem.hysteresis_creep):
        return None
    return tuple(getattr(problem, a) for a in _FORM), _shapes_beside_loop(problem, fit)


def _kept(problem: Problem, fit: Fit, found: Fit, named: tuple) -> bool:
    """Whether ``found`` lowers the BIC by more than ``BIC_MIN`` and explains
    ``EXPLAINED_MIN`` noise variances more than ``fit`` (:func:`.gates.beyond`); the loop's
    ``named`` form is restored when not."""
    if beyond(problem, fit, found, explained_min=EXPLAINED_MIN):
        return True
    for attribute, value in zip(_FORM, named):
        setattr(problem, attribute, value)
    return False


def refine_flank_friction(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as friction elements whose slip torques grow with the torque
    carried (:data:`LOAD_SHARES`), in place of the loop found so far, in whichever of the
    parallel loop's four forms fits best at ``FORM_SHARE``; the share that fits best in it,
    kept when it lowers the BIC by more than ``BIC_MIN`` and explains ``EXPLAINED_MIN``
    noise variances more (:func:`.gates.beyond`). Leaves ``problem.plays_load_share`` set
    when kept."""
    named = _named_form(problem, fit)
    if named is None:
        return fit
    named, shapes = named  # the weights are amplitudes: the share is the one shape more
    problem.hysteresis_preisach, problem.hysteresis_plays = None, True

    def trial(mu: float, form: tuple) -> tuple[Fit, float, tuple]:
        problem.plays_load_share = mu
        _set_plays_form(problem, form)
        return finish(problem, fit.effects, fit.theta, shapes + 1), mu, form

    # the form at a middle share, then the share in that form
    _, _, form = min((trial(FORM_SHARE, f) for f in itertools.product((False, True), repeat=2)),
                     key=lambda t: t[0].rss)
    best, mu, form = min((trial(mu, form) for mu in LOAD_SHARES), key=lambda t: t[0].rss)
    if not _kept(problem, fit, best, named):
        return fit
    problem.plays_load_share = mu
    _set_plays_form(problem, form)
    r = plays.thresholds(problem.scales["T0"])
    _replace_loop_notes(problem, FLANK.format(k=len(r), mu=mu, lo=r[0], hi=r[-1]), form, fit,
                        best, "the loop of fixed slip torques")
    return best


# the Duhem loop's relaxation rate λ [per T0 of travel] and height exponent p: a coarse grid
# (a branch that bends over half of T0 … an eighth), then a bounded simplex search from its
# best point, on log λ in (log 0.2, log 50) and p in (0.3, 4)
RATES = (0.5, 2.0, 8.0)
POWERS = (0.75, 1.5, 3.0)
DUHEM_BOUNDS = ((math.log(0.2), math.log(50.0)), (0.3, 4.0))
DUHEM_EVALUATIONS = 40


def refine_duhem(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as a Duhem loop whose height follows the last excursion
    (:mod:`.duhem`), about the catalog curve with a constant compliance or through the
    gear's (the form at the grid's middle point), in place of the loop found so far: the
    rate and power from a grid and a bounded simplex search, kept when it lowers the BIC by
    more than ``BIC_MIN`` and explains ``EXPLAINED_MIN`` noise variances more
    (:func:`.gates.beyond`). Leaves ``problem.hysteresis_duhem`` set when kept."""
    named = _named_form(problem, fit)
    if named is None:
        return fit
    named, shapes = named
    problem.hysteresis_preisach, problem.hysteresis_plays = None, False
    problem.hysteresis_centred, problem.plays_load_share = False, 0.0

    def rss(x: np.ndarray, through: bool) -> float:
        problem.hysteresis_duhem = (math.exp(x[0]), float(x[1]))
        problem.hysteresis_through_gear = through
        return rss_at(problem, fit.effects, fit.theta)

    middle = np.array([math.log(RATES[1]), POWERS[1]])
    through = min((False, True), key=lambda t: rss(middle, t))
    start = min((np.array([math.log(r), p]) for r in RATES for p in POWERS),
                key=lambda x: rss(x, through))
    x = minimize(rss, start, args=(through,), method="Nelder-Mead", bounds=DUHEM_BOUNDS,
                 options={"maxfev": DUHEM_EVALUATIONS, "xatol": 0.01, "fatol": 0.0}).x
    rss(x, through)
    found = finish(problem, fit.effects, fit.theta, shapes + 2)
    if not _kept(problem, fit, found, named):
        return fit
    rate, power = problem.hysteresis_duhem
    _replace_loop_notes(problem, DUHEM.format(rate=rate, power=power), (False, through), fit,
                        found, "the loop found before")
    return found
