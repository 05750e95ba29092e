"""Vibration: the joint's damping in the form the data take once the excitation is named.

While effects are named the joint is damped by a viscous damper on the load's motion,
J·θ'' + c·θ' + K·θ = K·e. The gear's own damping (in the mesh and the flexspline) acts on
the joint's twist θ − e instead, so that the error drives the load through the damper as
well as through the spring; a material's loss is nearly the same at every frequency
(structural damping). Each is tried in place of the first and kept by BIC.

References
----------
Ewins, D. J. (2000) *Modal Testing: Theory, Practice and Application*, 2nd ed., ch. 2
(viscous and hysteretic, i.e. structural, damping).
Seed 000 p.021 (the load's resonance on the gear's spring).
"""

from __future__ import annotations

import math

from .fitting import Fit, Problem, fit_model
from .gates import EXPLAINED_MIN, beyond


def refine_damping(problem: Problem, fit: Fit) -> Fit:
    """Vibration: the joint's damping in the form that fits the data, kept when it lowers
    the BIC by more than ``BIC_MIN`` over the viscous damper on the load's motion (the same
    parameters) and, for structural damping, explains ``EXPLAINED_MIN`` noise variances more
    (:func:`.gates.beyond`; ``FORM_EXPLAINED_MIN``):

    - the damper on the joint's twist θ − e, the gear's own damping, which the error drives
      through it as well as through the spring (:func:`.joint.joint_response` on the twist);
    - the steady state through a spring with structural damping (:func:`.joint.steady_response`,
      loss factor η = 2ζ): a material's loss factor hardly changes with frequency, so it
      damps the resonance as a viscous ζ = η/2 does but the response off it differently,
      and it has no free vibration after the resonance (a slow sweep or order-tracked
      data carry none)."""
    # the joint is the gear's whatever excites it: the gear's own error or the drive's ripple
    excited = [e for e in fit.effects if e.startswith("te_") or e == "drive_ripple"]
    if problem.kind != "vibration" or not excited or "damping_ratio" not in fit.theta:
        return fit
    trials = {}
    for form in JOINT_FORMS:
        _set_joint(problem, form)
        trials[form] = fit_model(problem, fit.effects, fit.theta)
    kept = [f for f in sorted(trials, key=lambda f: trials[f].rss)
            if beyond(problem, fit, trials[f], explained_min=FORM_EXPLAINED_MIN[f])]
    if not kept:
        _set_joint(problem, None)
        return fit
    form = kept[0]
    best = trials[form]
    _set_joint(problem, form)
    ratio = math.sqrt(best.rss / fit.rss)
    problem.notes.append(
        f"joint: the steady-state response through a spring with structural damping (loss "
        f"factor η = {2 * best.theta['damping_ratio']:.3g}) fits better than the viscous "
        f"joint's run-up (RMSE {ratio:.2f}× of it): no free vibration after the resonance, "
        "as a material's loss or a slow sweep gives" if form == "structural" else
        f"joint: the damper on the joint's twist (the gear's own damping, ζ = "
        f"{best.theta['damping_ratio']:.3g}, which the error drives through it as well as "
        f"through the spring) fits better than a damper on the load's motion (RMSE "
        f"{ratio:.2f}× of it)")
    return best


# the joint's damping forms tried once the excitation is named (refine_damping)
JOINT_FORMS = ("relative", "structural")
# the noise variances a form must explain beyond the BIC: the twist's damper is the load's
# with the same parameter put where the gear's damping acts, so the likelihood alone picks
# between them (a run-up read with the load's damper carries ζ 1–6 % high when the gear
# damps the twist); structural damping changes the response's kind (no free vibration), and
# at thousands of rows a sliver of a viscous joint's misfit passes the BIC alone
FORM_EXPLAINED_MIN = {"relative": 0.0, "structural": EXPLAINED_MIN}


def _set_joint(problem: Problem, form: str | None) -> None:
    problem.relative_damping = form == "relative"
    problem.steady_state = form == "structural"
