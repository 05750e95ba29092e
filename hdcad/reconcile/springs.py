"""Housing springs: one that stiffens, weighed against a backlash taken up slowly, and a
linear one named by its shape.

A clearance closing over a wide torque band and a series spring whose stiffness grows with
torque (contact that closes gradually, bolted joints) bend the torque–twist curve alike.
Two readings follow from it once the gear effects are named:

- a backlash named alone, or one beside another effect whose tanh width is wide
  (> ``TAKEUP_MAX``·T0), is weighed against the stiffening spring (:func:`slow_backlash`);
- a named backlash may have a stiffening spring as its second (:func:`stiffening_second`):
  a linear series spring is mostly the catalog compliance's own scatter (the stiffness scale
  takes its size), a stiffening one bends the curve.

A linear spring, alone or beside a backlash, may be named by its shape (:func:`by_its_shape`):
it adds the same compliance at every torque, where the stiffness scale adds in proportion to
the gear's own.

References
----------
Rivin, E. I. (1999) *Stiffness and Damping in Mechanical Design*, Marcel Dekker, ch. 4:
contact deformations, stiffness that grows with load.
Nordin, M., Gutman, P.-O. (2002) "Controlling mechanical systems with backlash — a survey",
Automatica 38(10): dead-zone forms of a backlash.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from scipy.optimize import minimize_scalar

from .fitting import Fit, Problem, fit_model, rss_at
from .gates import BIC_MIN, EXPLAINED_MIN, Candidate, Gate, beyond, gate

# A clearance is taken up at low torque: the catalog gives lost motion at ±3 % of the
# torque of its spring constant (FD table 314-1: ±load / load = 0.029–0.033). A backlash
# whose tanh width exceeds this share of T0 is still closing at 2·T_w = 40 % of T0 (96 %
# closed), over ten times the catalog's load: beside another effect it is read against a
# series spring that stiffens, which bends the curve the same way (:func:`slow_backlash`).
# A backlash named alone is read against it at any width: a spring soft at zero torque and
# stiffening from there (a cubic contact) was named as a backlash 0.12·T0 wide.
TAKEUP_MAX = 0.2
# T_k / T0 of the stiffening spring: a knee far below the take-up torque is a clearance's
# step (the cube root of T rises steeply from zero)
KNEE_BOUNDS = (0.1, 10.0)


def stiffening(problem: Problem, start: Fit, best: Candidate, singles: dict[str, Fit],
               sigma: float, tau: float) -> Candidate | None:
    """The candidate the named model is read as once a housing spring may stiffen, or None
    when it stays as it is."""
    if problem.kind != "torsion":
        return None
    return (slow_backlash(problem, start, best, singles, sigma, tau)
            or stiffening_second(problem, start, best, singles, sigma, tau))


def slow_backlash(problem: Problem, start: Fit, best: Candidate, singles: dict[str, Fit],
                  sigma: float, tau: float) -> Candidate | None:
    """A backlash named alone, or one beside another effect taken up only slowly (tanh
    width > ``TAKEUP_MAX``·T0), read as a housing spring that stiffens
    (:func:`.spring_forms.progressive_twist`, knee torque fitted) when the backlash does not fit
    clearly better (ΔBIC ≤ ``BIC_MIN``) and the spring passes the gates (over the other
    member alone too, in a pair) with its knee above the floor of ``KNEE_BOUNDS`` (a knee
    at the floor is a clearance's step); else None. Beside a loop a narrow backlash is not
    weighed: the loop's saturation bends the curve too, and the spring would take its
    shape.

    A lost motion not taken up by a few per cent of the rated torque is not what the
    catalog calls lost motion; the backlash is reported as the other reading.
    """
    if "backlash" not in best.effects:
        return None
    if (best.effects != ("backlash",)
            and best.fit.theta["backlash.T_w"] <= TAKEUP_MAX * problem.scales["T0"]):
        return None
    named = tuple(dict.fromkeys("housing_compliance" if e == "backlash" else e
                                for e in best.effects))
    spring = _knee_fit(problem, start.effects + named, best.fit.theta)
    g = gate(problem, start, spring, sigma, tau)
    other = [e for e in named if e != "housing_compliance"]
    if (not _knee_at_floor(problem) and g.passes()
            and gate(problem, spring, best.fit, sigma, tau).delta_bic <= BIC_MIN
            and all(gate(problem, singles[e], spring, sigma, tau).passes(second=True)
                    for e in other)):
        return Candidate(named, spring, g, True, progressive=True)
    problem.housing_knee = math.inf
    return None


def stiffening_second(problem: Problem, start: Fit, best: Candidate, singles: dict[str, Fit],
                      sigma: float, tau: float) -> Candidate | None:
    """A named backlash with a housing spring that stiffens as its second, when that spring
    earns its place over the backlash alone; else None. A linear spring named beside the
    backlash by its shape only (:func:`by_its_shape`) is weighed the same way: one that
    stiffens and passes the full gates is the better reading.

    A linear series spring is mostly the catalog compliance's own scatter (the stiffness
    scale takes its size; :func:`by_its_shape` weighs the rest); a stiffening one bends the curve
    away from zero torque, where a clearance is already closed. Not after a hysteresis: its
    loop's own saturation bends the curve too, and a stiffening spring would take the loop
    formula's shape mismatch (suite B's Bouc–Wen and Dahl singles, 2 of 12 at seed 7).
    """
    named = ("backlash", "housing_compliance")
    if best.effects == ("backlash",):
        alone = best.fit
    elif best.by_shape and set(best.effects) == set(named):
        alone = singles["backlash"]
    else:
        return None
    pair = _knee_fit(problem, start.effects + named, alone.theta)
    g = gate(problem, start, pair, sigma, tau)
    if g.passes() and gate(problem, alone, pair, sigma, tau).passes(second=True):
        return Candidate(named, pair, g, True)
    problem.housing_knee = math.inf
    return None


def by_its_shape(member: str, beside: str | None, over: Gate) -> bool:
    """Whether the housing spring ``member`` earns its place alone (``beside`` None) or
    beside a backlash by its shape: ΔBIC > ``BIC_MIN`` over the model without it and a
    blocked cross-validated error that falls, however little of the noise variance it explains.

    The stiffness scale takes a series spring's compliance only in proportion to the gear's,
    which falls from K1 to K3; the spring adds the same at every torque. The catalog curve's
    own misfits do not take that shape: alone over the scale, the spring lowered the BIC by
    7.2 at most on the 206 clean and separable-decoy torsion cases of the truth suites
    (seed 7); beside a true backlash with no spring, by 11.2 once (a wrong second). True
    springs that the scale's spread would take explain only 0.02–0.09 noise variances, short
    of ``EXPLAINED_MIN``, with ΔBIC up to 25 alone and 78 beside a backlash (whose dead zone
    acts about zero torque). A loop has a backbone that a spring stands in for: not beside
    one. The search names a spring alone by its shape only when nothing else passes.
    """
    return (member == "housing_compliance" and beside in (None, "backlash")
            and over.delta_bic > BIC_MIN and over.cv_gain > 0)


def _knee_at_floor(problem: Problem) -> bool:
    """The fitted knee at the lowest its bounds allow: the spring would stiffen as steeply
    as it can, a clearance's step rather than a spring."""
    return problem.housing_knee <= 1.05 * KNEE_BOUNDS[0] * problem.scales["T0"]


def _knee_fit(problem: Problem, effects: tuple[str, ...], theta: dict[str, float]) -> Fit:
    """The model with the housing spring's knee torque fitted, the knee counting as one
    more parameter; leaves the knee set on ``problem``. The knee is searched (bounded, on its
    logarithm) with the other shapes held at ``theta``, then all are fitted at that knee."""
    _search_torque(problem, "housing_knee", KNEE_BOUNDS, effects, theta, 0.05, 20)
    fit = fit_model(problem, effects, theta)
    return replace(fit, n_params=fit.n_params + 1)


def _search_torque(problem: Problem, attribute: str, shares: tuple[float, float],
                   effects: tuple[str, ...], theta: dict[str, float], xatol: float,
                   maxiter: int) -> None:
    """Set the spring's torque ``problem.attribute`` [N·m] to the one within ``shares`` of T0
    that leaves the least residual with the shapes held at ``theta`` (bounded search on its
    logarithm, to ``xatol`` in it)."""
    t0 = problem.scales["T0"]

    def held(log_share: float) -> float:
        setattr(problem, attribute, t0 * math.exp(log_share))
        return rss_at(problem, effects, theta)

    lo, hi = (math.log(b) for b in shares)
    found = minimize_scalar(held, bounds=(lo, hi), method="bounded",
                            options={"xatol": xatol, "maxiter": maxiter})
    setattr(problem, attribute, t0 * math.exp(found.x))


# T_o / T0 of a joint that opens: below a tenth of the test's torque the opened joint's
# compliance is the linear spring's own, and one that opens only past 95 % bends nothing
OPENING_BOUNDS = (0.1, 0.95)
OPENING = ("housing_compliance: the joint opens past {t:.3g} N·m (T/T0 = {share:.2f}) and "
           "its compliance grows from {c1:.3g} to {c2:.3g} rad/(N·m), a bolted flange's "
           "interface separating at its edge (fits {closer:.2f}× closer than a linear spring, "
           "BIC)")


def refine_opening(problem: Problem, fit: Fit) -> Fit:
    """A named linear housing spring whose joint opens past a torque T_o and softens
    (:func:`.spring_forms.opening_twist`, the opened joint's compliance an amplitude, T_o
    searched on its logarithm), kept when it lowers the BIC by more than ``BIC_MIN`` and
    explains ``EXPLAINED_MIN`` noise variances more (:func:`.gates.beyond`). The catalog
    curve stiffens with load; a series joint that softens bends it the other way, which
    neither the stiffness scale nor a linear spring follows. Leaves
    ``problem.housing_opening`` set when it is kept."""
    if (problem.kind != "torsion" or "housing_compliance" not in fit.effects
            or math.isfinite(problem.housing_knee) or math.isfinite(problem.housing_opening)):
        return fit
    _search_torque(problem, "housing_opening", OPENING_BOUNDS, fit.effects, fit.theta, 0.02, 30)
    opened = fit_model(problem, fit.effects, fit.theta)
    # the shapes in use as ``fit`` counts them (its loop's form, its refinements' terms),
    # the opened joint's compliance if it is used, and T_o
    opened = replace(opened, n_params=fit.shapes + int(np.count_nonzero(opened.beta)) + 1)
    if not beyond(problem, fit, opened, explained_min=EXPLAINED_MIN):
        problem.housing_opening = math.inf
        return fit
    b = {n: v for (e, n), v in zip(opened.labels, opened.beta) if e == "housing_compliance"}
    problem.notes.append(OPENING.format(
        t=problem.housing_opening, share=problem.housing_opening / problem.scales["T0"],
        c1=b["compliance"],
        c2=b["compliance"] + b.get("opening_compliance", 0.0),
        closer=math.sqrt(fit.rss / opened.rss)))
    return opened
