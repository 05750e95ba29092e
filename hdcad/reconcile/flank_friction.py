"""A named hysteresis as friction whose slip torque grows with the torque the gear carries.

The teeth of a strain wave gear slide on their flanks under a normal load that the
transmitted torque sets, so the friction torque that holds the flexspline back is not a
constant: it is r + μ·|T|, a Coulomb friction on flanks pressed together by the load. A
loop of such friction is narrow at small torque and widens towards the test's largest; a
friction element of fixed slip torque saturates instead, and its loop keeps one width once
every element slips. The friction elements of :mod:`.plays` take the load-dependent
threshold r_k + μ·|T| (one share μ for all, found over a few values); their weights stay
amplitudes, fitted by bounded linear least squares as before, in any of the parallel loop's
forms (about its own backbone or the catalog curve, with a constant compliance or through
the gear's).

References
----------
Tuttle, T. D.; Seering, W. P. (1996) "A nonlinear model of a harmonic drive gear
transmission", IEEE Trans. Robotics and Automation 12(3): 368-374 (mesh friction that
grows with the transmitted torque).
Taghirad, H. D.; Bélanger, P. R. (1998) "Modeling and parameter identification of harmonic
drive systems", J. Dyn. Sys., Meas., Control 120(4): 439-444.
Brokate, M.; Sprekels, J. (1996) *Hysteresis and Phase Transitions*, Springer, ch. 2 (play
operators with a threshold that depends on the input).
"""

from __future__ import annotations

import itertools

from . import plays
from .fitting import Fit, Problem, finish
from .gates import EXPLAINED_MIN, beyond
from .loops import FLANK, _parametric_loop_shapes, _replace_loop_notes, _set_plays_form

# shares μ of the carried torque added to every slip torque, about 2 per decade: a flank
# friction coefficient (0.05–0.15 for lubricated steel on steel) times the ratio of the
# flanks' normal load to the tangential, from a loop that barely widens to one that is nearly
# all the load's (μ < 1: past that the friction would hold any torque)
LOAD_SHARES = (0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8)
# the share at which the loop's form is chosen (11 fits in place of 32, the same choices on
# suites B–L)
FORM_SHARE = 0.1

def refine_flank_friction(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as friction elements whose slip torques grow with the torque
    carried (:data:`LOAD_SHARES`), in place of the loop found so far, in whichever of the
    parallel loop's four forms fits best at ``FORM_SHARE``; the share that fits best in it,
    kept when it lowers the BIC by more than ``BIC_MIN`` and explains ``EXPLAINED_MIN``
    noise variances more (:func:`.gates.beyond`). Leaves ``problem.plays_load_share`` set
    when kept."""
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.branches is None
            or problem.hysteresis_series or problem.hysteresis_creep):
        return fit
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear,
             problem.hysteresis_preisach, problem.hysteresis_plays)
    # the weights are amplitudes: a parametric loop's shapes go, the share comes
    shapes = fit.shapes - (0 if problem.hysteresis_plays else _parametric_loop_shapes(problem))
    problem.hysteresis_preisach, problem.hysteresis_plays = None, True

    def trial(mu: float, form: tuple) -> tuple[Fit, float, tuple]:
        problem.plays_load_share = mu
        _set_plays_form(problem, form)
        return finish(problem, fit.effects, fit.theta, shapes + 1), mu, form

    # the form at a middle share, then the share in that form
    _, _, form = min((trial(FORM_SHARE, f) for f in itertools.product((False, True), repeat=2)),
                     key=lambda t: t[0].rss)
    best, mu, form = min((trial(mu, form) for mu in LOAD_SHARES), key=lambda t: t[0].rss)
    if not beyond(problem, fit, best, explained_min=EXPLAINED_MIN):
        (problem.hysteresis_centred, problem.hysteresis_through_gear,
         problem.hysteresis_preisach, problem.hysteresis_plays) = named
        problem.plays_load_share = 0.0
        return fit
    problem.plays_load_share = mu
    _set_plays_form(problem, form)
    r = plays.thresholds(problem.scales["T0"])
    _replace_loop_notes(problem, FLANK.format(k=len(r), mu=mu, lo=r[0], hi=r[-1]), form, fit,
                        best, "the loop of fixed slip torques")
    return best

