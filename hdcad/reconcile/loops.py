"""The form of a named hysteresis loop, chosen once the effect is named: the Bouc–Wen loop
(with which it is named) about its own backbone or about the catalog curve, with a constant
compliance or through the gear's, a Preisach relay sum (:mod:`.preisach`) and a sum of
friction elements (:mod:`.plays`) in parallel with the gear or in series with it.

None of these refinements changes which effects are named; each is kept when it follows the
data more closely, and says so in the notes. Two readings are the search's
(:func:`series_slip` for the Bouc–Wen loop, :func:`series_plays` for friction elements): a
loop beside a housing spring that is only the loop's own compliance past its slip torques
is named as the hysteresis alone, in series with the gear.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

import numpy as np
from scipy.optimize import least_squares

from . import effects as fx
from . import creep, plays
from .bounded import solve
from .fitting import POLISH_TOL, Fit, Problem, best_setting, copy_problem, finish
from .model_columns import columns, nonlinear
from .gates import (BIC_MIN, EXPLAINED_MIN, Candidate, beyond, bic_best, bic_choice,
                    effective_n, gate)

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

    def apply(form):
        problem.hysteresis_centred, problem.hysteresis_through_gear = form
    best, form = best_setting(problem, fit, named, itertools.product((False, True), repeat=2),
                              apply)
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
# forms fitted after the screen at the starts (the suites B–H name the same effects with the
# same rmse at 2 as with all 4)
_PREISACH_POLISHED = 2


def preisach_forms(problem: Problem, fit: Fit) -> list[tuple[Fit, tuple, tuple]]:
    """(fit, density, (centred, through the gear)) of the hysteresis in ``fit`` as a
    Preisach relay sum, its other shapes held: the four forms are screened at a few
    starting densities (they share the relay sum, so a start costs one Everett sum) and
    the :data:`_PREISACH_POLISHED` best are fitted. Leaves the problem's loop form as it
    found it."""
    t0 = problem.scales["T0"]
    scale = np.array([t0, 1.0, t0])
    shapes = _shapes_beside_loop(problem, fit) + len(scale)  # the density's three
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear,
             problem.hysteresis_preisach)
    residual = _density_residual(problem, fit, scale)
    forms = list(itertools.product((False, True), repeat=2))
    try:
        screened = {}
        for x in (np.log(np.array(x0)) for x0 in _PREISACH_STARTS):
            for form in forms:
                rss = float(np.sum(residual(x, form) ** 2))
                if form not in screened or rss < screened[form][0]:
                    screened[form] = (rss, x)
        ranked = sorted(forms, key=lambda f: screened[f][0])[:_PREISACH_POLISHED]
        return [(*_fit_density(problem, fit, residual, screened[form][1], form, scale, shapes),
                 form) for form in ranked]
    finally:
        (problem.hysteresis_centred, problem.hysteresis_through_gear,
         problem.hysteresis_preisach) = named


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
    _replace_loop_notes(problem, PREISACH.format(w=w, s=s, c=c), form, fit, best,
                        "the Bouc–Wen loop")
    return best


def _shapes_beside_loop(problem: Problem, fit: Fit) -> int:
    """The parameters of ``fit`` other than its amplitudes and its loop's shapes
    (:func:`_parametric_loop_shapes`): the other effects' shapes in use and the terms a
    refinement added (a play's holding torque)."""
    return fit.shapes - _parametric_loop_shapes(problem)


def _parametric_loop_shapes(problem: Problem) -> int:
    """The shapes of the problem's loop besides its amplitudes: friction elements' none (or
    their load share, when their slip torques grow with the torque), the Duhem loop's two
    (rate, power), the Preisach density's three, else the Bouc–Wen loop's five."""
    if problem.hysteresis_plays:
        return 1 if problem.plays_load_share else 0
    if problem.hysteresis_duhem is not None:
        return 2
    return (3 if problem.hysteresis_preisach is not None
            else len(fx.nonlinear_parameters("hysteresis", problem.kind)))


def _replace_loop_notes(problem: Problem, text: str, form: tuple, fit: Fit, best: Fit,
                        than: str) -> None:
    """Note the loop's new form ``text`` in ``form`` and how much closer ``best`` fits than
    ``fit``; the earlier form's notes describe a loop no longer in the model."""
    earlier = (f"{CENTRED} fits", f"{THROUGH_GEAR} fits", PREISACH.split("(")[0],
               PLAYS.split("{")[0], FLANK.split("(")[0], DUHEM.split("(")[0])
    problem.notes[:] = [n for n in problem.notes if not n.startswith(earlier)
                        and _SERIES_PLAYS_MARK not in n]
    problem.notes.append(text + (", about the catalog curve" if form[0] else "")
                         + (", through the gear's compliance" if form[1] else "")
                         + f", fits {math.sqrt(fit.rss / best.rss):.2f}× closer than "
                         f"{than} (BIC)")


PLAYS = ("hysteresis: a sum of {k} friction elements (an Iwan model: slip torques "
         "{lo:.3g} … {hi:.3g} N·m, weights fitted)")
SERIES_PLAYS = ("hysteresis: {k} friction elements in series with the gear (slip torques "
                "{lo:.3g} … {hi:.3g} N·m, weights fitted): past its slip torques the loop "
                "adds a compliance of its own")
_SERIES_PLAYS_MARK = " friction elements in series with the gear (slip torques"
DUHEM = ("hysteresis: a Duhem loop whose height follows the last excursion (relaxation "
         "rate {rate:.3g} per T0, height ∝ amplitude^{power:.2f}: a loss that grows with the "
         "amplitude, Dhaouadi, Ghorbel & Gandhi 2003)")
FLANK = ("hysteresis: friction elements whose slip torques grow with the torque carried ({k} "
         "elements, r_k + {mu:g}·|T|, r_k {lo:.3g} … {hi:.3g} N·m, weights fitted: friction on "
         "flanks the load presses together, a loop that widens with the torque)")
SERIES_CLOSE = ("housing_compliance beside the loop: friction elements in series with the "
                "gear, without the spring, read almost the same (the spring's ΔBIC over them "
                "{gain:.1f}, under the {limit:g} an effect is named at); check the housing's "
                "stiffness before stiffening it")


def refine_plays(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as a sum of friction elements with fixed slip torques, weighted
    freely (:mod:`.plays`), in whichever of the loop's forms (in parallel with the gear,
    about its own backbone or the catalog curve, with a constant compliance or through the
    gear's; or in series with it, softening past its slip torques) fits best, kept in place
    of the loop found so far (Bouc–Wen or Preisach) when BIC (effective sample size N/τ)
    prefers it. The weights are amplitudes, so no shape is fitted: a loop whose
    branches follow none of the parametric forms is followed as closely as the slip torques
    resolve it. A loop named as one slip element in series keeps to the series form. Leaves
    ``problem.hysteresis_plays`` set when it is kept."""
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.hysteresis_plays
            or problem.branches is None):
        return fit
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear,
             problem.hysteresis_preisach, problem.hysteresis_series)
    shapes = _shapes_beside_loop(problem, fit)  # the weights are amplitudes, counted by finish
    problem.hysteresis_preisach, problem.hysteresis_plays = None, True
    trials = []
    # in parallel with the gear in the loop's four forms, or in series with it
    forms = ([] if problem.hysteresis_series else list(itertools.product((False, True),
                                                                           repeat=2)))
    for form in [*forms, "series"]:
        _set_plays_form(problem, form)
        trials.append((finish(problem, fit.effects, fit.theta, shapes), form))
    best, form = min(trials, key=lambda t: t[0].rss)
    n_eff = effective_n(problem, best.residual(problem))
    if not bic_best({False: (fit.rss, fit.n_params), True: (best.rss, best.n_params)}, n_eff):
        (problem.hysteresis_centred, problem.hysteresis_through_gear,
         problem.hysteresis_preisach, problem.hysteresis_series) = named
        problem.hysteresis_plays = False
        return fit
    _set_plays_form(problem, form)
    _replace_loop_notes(problem, _plays_text(problem),
                        (problem.hysteresis_centred, problem.hysteresis_through_gear), fit,
                        best, "the parametric loop")
    return best


CREEP = ("hysteresis: creep elements {where}(standard linear solids; relaxation times "
         "{lo:.3g} … {hi:.3g} {unit}, delayed compliances fitted): a loop that lags the "
         "torque in time and would widen with the loading rate, as a grease film's or an "
         "elastomer's does")
CREEP_READING = ("creep: at the rates of this test the creep elements may also stand for a "
                 "friction loop's shape; loops measured at another loading rate tell a "
                 "viscous loss from friction")
NO_CLOCK = ("; the record has no time_s column: its rows are taken as equally spaced in "
            "time, relaxation times given in rows")
_CREEP_FORMS = tuple(itertools.product(("alone", "beside"), (False, True)))


def refine_creep(problem: Problem, fit: Fit) -> Fit:
    """A named hysteresis as creep elements with fixed relaxation times, weighted freely
    (:mod:`.creep`), in place of the loop found so far or beside it, about the catalog
    curve or not (the form by BIC: beside the loop holds the loop alone too), kept when it
    lowers the BIC by more than ``BIC_MIN`` and explains ``EXPLAINED_MIN`` noise variances
    more (:func:`.gates.beyond`): a loop whose width follows the loading rate, which no
    friction loop does over several rates (at one rate the two may read alike). Leaves
    ``problem.hysteresis_creep`` set when it is kept."""
    if (problem.kind != "torsion" or "hysteresis" not in fit.effects
            or problem.base.curve is None or problem.hysteresis_creep):
        return fit
    beside = _shapes_beside_loop(problem, fit)  # without the loop, its shapes go
    trials = []
    for where, centred in _CREEP_FORMS:
        problem.hysteresis_creep, problem.creep_centred = where, centred
        shapes = beside if where == "alone" else fit.shapes
        trials.append((finish(problem, fit.effects, fit.theta, shapes), where, centred))
    best, where, centred = trials[bic_choice(problem, [t[0] for t in trials])]
    if not beyond(problem, fit, best, explained_min=EXPLAINED_MIN):
        problem.hysteresis_creep, problem.creep_centred = None, False
        return fit
    problem.hysteresis_creep, problem.creep_centred = where, centred
    weights = np.array([w for (e, n), w in zip(best.labels, best.beta)
                        if e == "hysteresis" and n.startswith("creep_")])
    taus, unit = creep.record_taus(len(problem.base.y), problem.base.inputs.get("time_s"))
    taus = taus[weights > 0] if weights.any() else np.zeros(1)
    text = CREEP.format(where="" if where == "alone" else "beside the friction loop ",
                        lo=taus.min(), hi=taus.max(), unit=unit)
    if where == "alone":
        _replace_loop_notes(problem, text, (centred, False), fit, best, "the friction loop")
    else:
        problem.notes.append(text + (", about the catalog curve" if centred else "")
                             + f", fits {math.sqrt(fit.rss / best.rss):.2f}× closer (BIC)")
    problem.notes.append(CREEP_READING + (NO_CLOCK if unit == "rows" else ""))
    return best


def _plays_text(problem: Problem) -> str:
    """The note on the sum of friction elements in the problem's form: in parallel with the
    gear (:data:`PLAYS`) or in series with it (:data:`SERIES_PLAYS`)."""
    series = problem.hysteresis_series
    r = plays.thresholds(problem.scales["T0"])[plays.series_first() if series else 0:]
    return (SERIES_PLAYS if series else PLAYS).format(k=len(r), lo=r[0], hi=r[-1])


def _set_plays_form(problem: Problem, form: tuple | str) -> None:
    """The friction elements in series with the gear (``"series"``) or in parallel with it
    in ``form`` (about the catalog curve, through the gear's compliance)."""
    problem.hysteresis_series = form == "series"
    problem.hysteresis_centred, problem.hysteresis_through_gear = (
        (False, False) if form == "series" else form)


def series_slip(problem: Problem, start: Fit, best: Candidate, sigma: float, tau: float
                ) -> Fit | None:
    """The fit of one slip element in series with the gear when a hysteresis +
    housing_compliance pair reads the same as it (its spring is the loop's own slip
    compliance); else None.

    Friction in parallel with the gear (Bouc–Wen, −z_sat·z) plus a spring of compliance
    z_sat/T_s is, term for term, a slip element in series (z_sat·(T/T_s − z): Iwan,
    Preisach, Masing–Ramberg–Osgood loops add their slip to the gear's twist). At the pair's
    own shape the compliance is tied to z_sat/T_s; when BIC does not prefer the free spring
    to the tie (ΔBIC ≤ 0) the data read the same both ways: the simpler reading, one
    hysteresis, is named and the report gives the other.
    """
    if set(best.effects) != {"hysteresis", "housing_compliance"}:
        return None
    effects = start.effects + ("hysteresis",)
    problem.hysteresis_series = True
    try:
        tied = finish(problem, effects, best.fit.theta, len(nonlinear(problem.kind, effects)))
    finally:
        problem.hysteresis_series = False
    return tied if gate(problem, tied, best.fit, sigma, tau).delta_bic <= 0.0 else None


def series_plays(problem: Problem, start: Fit, pair: Fit, sigma: float, tau: float
                 ) -> Fit | None:
    """The hysteresis alone as friction elements in series with the gear (:mod:`.plays`)
    when it reads the same as the hysteresis + housing spring ``pair``, as it is and with
    the same elements in parallel (in whichever of the loop's four forms fits best) beside a
    spring of free compliance: the pair's ΔBIC over it ≤ 0 in both, as for the Bouc–Wen
    loop's slip element (:func:`series_slip`); else None. A loop that softens past its slip
    torques (a kinematic-hardening slider, a joint in microslip) is then one effect, the
    spring its own compliance, and the pair is reported as the other reading. A spring that
    beats the series loop by less than ``BIC_MIN`` stays named, with a note that the series
    loop reads almost the same. Leaves the problem's loop in series when it returns a fit."""
    if (problem.kind != "torsion" or problem.base.curve is None or problem.branches is None
            or set(pair.effects) - set(start.effects) != {"hysteresis", "housing_compliance"}):
        return None
    shapes = _shapes_beside_loop(problem, pair)
    named = (problem.hysteresis_centred, problem.hysteresis_through_gear)
    problem.hysteresis_plays = True
    trials = []
    for form in itertools.product((False, True), repeat=2):
        _set_plays_form(problem, form)
        trials.append(finish(problem, pair.effects, pair.theta, shapes))
    parallel = min(trials, key=lambda f: f.rss)
    _set_plays_form(problem, "series")
    effects = start.effects + ("hysteresis",)
    spring = len(fx.nonlinear_parameters("housing_compliance", problem.kind))
    tied = finish(problem, effects, pair.theta, shapes - spring)
    spring_gain = max(gate(problem, tied, f, sigma, tau).delta_bic for f in (parallel, pair))
    if spring_gain <= 0.0:
        problem.notes.append(_plays_text(problem))
        return tied
    if spring_gain <= BIC_MIN:
        problem.notes.append(SERIES_CLOSE.format(gain=spring_gain, limit=BIC_MIN))
    problem.hysteresis_plays = problem.hysteresis_series = False
    problem.hysteresis_centred, problem.hysteresis_through_gear = named
    return None


def without_spring_in_series(problem: Problem, fit: Fit) -> Fit | None:
    """``fit`` (a loop named beside a housing spring, in its final form) without the spring,
    its loop as friction elements in series with the gear (:mod:`.plays`), fitted on a copy
    of ``problem``; None when the loop is not a friction loop beside a spring. The series
    elements soften past their slip torques, so they carry a compliance of their own."""
    if (problem.kind != "torsion" or problem.base.curve is None or problem.branches is None
            or problem.hysteresis_series or problem.hysteresis_creep
            or problem.hysteresis_duhem is not None
            or not {"hysteresis", "housing_compliance"} <= set(fit.effects)):
        return None
    trial = replace(copy_problem(problem), hysteresis_preisach=None, hysteresis_plays=True,
                    plays_load_share=0.0)
    shapes = _shapes_beside_loop(problem, fit) - len(
        fx.nonlinear_parameters("housing_compliance", problem.kind))
    _set_plays_form(trial, "series")
    effects = tuple(e for e in fit.effects if e != "housing_compliance")
    return finish(trial, effects, fit.theta, shapes)


def _density_residual(problem: Problem, fit: Fit, scale: np.ndarray):
    """The residual of ``fit``'s effects (its other shapes held, linear terms refitted)
    against the Preisach density's logarithms (shares of ``scale``) in a loop form."""
    unit = math.sqrt(fit.rss / len(problem.rows)) or 1.0

    def residual(x: np.ndarray, form: tuple) -> np.ndarray:
        problem.hysteresis_centred, problem.hysteresis_through_gear = form
        problem.hysteresis_preisach = tuple(np.exp(x) * scale)
        X, _, low, high = columns(problem, fit.effects, fit.theta)
        return (problem.y - X @ solve(X, problem.y, low, high)) / unit
    return residual


def _fit_density(problem: Problem, fit: Fit, residual, x0: np.ndarray, form: tuple,
                 scale: np.ndarray, shapes: int) -> tuple[Fit, tuple[float, float, float]]:
    """The Preisach density in ``form`` (bounded least squares in its logarithms from
    ``x0``) and its :class:`Fit`."""
    lo, hi = np.log(_PREISACH_BOUNDS[:, 0]), np.log(_PREISACH_BOUNDS[:, 1])
    found = least_squares(residual, x0, args=(form,), bounds=(lo, hi),
                          max_nfev=_PREISACH_EVALUATIONS, diff_step=1e-3, ftol=POLISH_TOL,
                          xtol=POLISH_TOL)
    density = tuple(float(v) for v in np.exp(found.x) * scale)
    problem.hysteresis_centred, problem.hysteresis_through_gear = form
    problem.hysteresis_preisach = density
    return finish(problem, fit.effects, fit.theta, shapes), density
