"""The named efficiency effects as one Stribeck law in Hersey's number, chosen once they are
named: the loss of a lubricated contact depends on load, speed and temperature through the
film's one parameter H = ν·N/P, so a loss that changes with load at one speed changes with
speed and temperature too, which the product η0·Ke(α)·F(t) of separate factors does not
follow.

η = η0 + η_n·ln(n/n_ref) − d_b·exp(−H/H_b) − d_f·√H − d_v·H
(:func:`.efficiency_laws.stribeck_terms`): the level and its speed slope are the baseline's,
the three losses are amplitudes, and the shapes are the boundary scale H_b, the pressure
exponent r (P ∝ α^r) where the law takes the load and the viscosity slope b where it takes
the temperature (the viscosity law chosen for it); a factor the law does not take still
multiplies. The form (both factors, or either) is chosen by BIC, and kept when it lowers
the BIC by more than ``BIC_MIN`` and explains ``EXPLAINED_MIN`` noise variances more than
the factors (:func:`.gates.beyond`).

References
----------
Stribeck, R. (1902) Z. VDI 46; Hersey, M. D. (1914) J. Wash. Acad. Sci. 4, 542–552;
Schipper, D. J. (1988) *Transitions in the lubrication of concentrated contacts*, PhD
thesis, University of Twente (Stribeck curves in the lubrication number).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from scipy.optimize import least_squares

from . import efficiency_laws as laws
from .bounded import solve
from .effects import key_of, nonlinear_parameters
from .fitting import POLISH_TOL, Fit, Problem, finish, shapes_in_use
from .gates import EXPLAINED_MIN, beyond, bic_choice
from .model_columns import columns, stribeck_takes

# bounds of the shapes: H_b (in log), the pressure exponent r, the viscosity slope b [1/K]
# (the temperature dependence's own bounds)
BOUNDARY_SCALE = (0.02, 50.0)
PRESSURE_EXPONENT = (0.3, 1.0)
_STARTS_H = (0.1, 0.4, 1.5, 6.0)
_STARTS_R = (0.5, 1.0)
_EVALUATIONS = 80
TEXT = ("efficiency: a Stribeck law in Hersey's number H = {h} in place of {named}'s "
        "factors (boundary friction fading as exp(−H/{hb:.3g}), film shear ∝ √H and H), "
        "fits {closer:.2f}× closer (BIC): the loss follows {what} through the lubricant "
        "film's one parameter")


def refine_hersey(problem: Problem, fit: Fit) -> Fit:
    """The named efficiency effects, both or either, as a Stribeck law in Hersey's number
    when it fits better than their factors (module docstring); leaves ``problem.hersey``
    at its shapes (r > 0 where it replaces the low-load factor, b > 0 the temperature
    law), or None."""
    named = [e for e in fit.effects if e in laws.HERSEY_EFFECTS]
    if problem.kind != "efficiency" or not named or problem.hersey is not None:
        return fit
    trials = []
    for form in _forms(named):
        x, count = _fit_shapes(problem, fit, *form)
        problem.hersey = x
        replaced = sum(_shapes_of(problem, fit, e) for e in named if stribeck_takes(problem, e))
        trials.append((finish(problem, fit.effects, fit.theta,
                              max(fit.shapes - replaced, 0) + count), x, form))
    best, problem.hersey, (load, warm) = trials[bic_choice(problem, [t[0] for t in trials])]
    if not beyond(problem, fit, best, explained_min=EXPLAINED_MIN):
        problem.hersey = None
        return fit
    what = [e for e in named if stribeck_takes(problem, e)]
    problem.notes.append(TEXT.format(h=_hersey_text(problem.hersey, load, warm),
                                     named=" and ".join(what), hb=problem.hersey[0],
                                     closer=math.sqrt(fit.rss / best.rss),
                                     what="load, speed and temperature" if load and warm
                                     else "load and speed" if load else "speed and temperature"))
    return best


def _forms(named: list[str]) -> list[tuple[bool, bool]]:
    """(the law takes the load, the temperature): both named effects, or either alone."""
    load, warm = "low_load_efficiency" in named, "temperature_dependence" in named
    return [f for f in ((True, True), (True, False), (False, True))
            if (f[0] <= load and f[1] <= warm)]


def _fit_shapes(problem: Problem, fit: Fit, load: bool, warm: bool
                ) -> tuple[tuple[float, float, float], int]:
    """The law's shapes (H_b, r, b) fitted by bounded least squares from the best of a few
    starts, with the other shapes of ``fit`` held and its amplitudes refitted; and how
    many were fitted."""
    b_lo, b_hi = _slope_bounds()
    b0 = float(np.clip(fit.theta.get(key_of("temperature_dependence", "b"), b_lo), b_lo, b_hi))

    def shapes(x: np.ndarray) -> tuple[float, float, float]:
        return (float(math.exp(x[0])), float(x[1]) if load else 0.0,
                float(x[-1]) if warm else 0.0)

    unit = math.sqrt(fit.rss / len(problem.rows)) or 1.0

    def residual(x: np.ndarray) -> np.ndarray:
        problem.hersey = shapes(x)
        X, _, low, high = columns(problem, fit.effects, fit.theta)
        return (problem.y - X @ solve(X, problem.y, low, high)) / unit

    lo = [math.log(BOUNDARY_SCALE[0])] + [PRESSURE_EXPONENT[0]] * load + [b_lo] * warm
    hi = [math.log(BOUNDARY_SCALE[1])] + [PRESSURE_EXPONENT[1]] * load + [b_hi] * warm
    starts = [np.array([math.log(h)] + [r] * load + [b0] * warm)
              for h, r in itertools.product(_STARTS_H, _STARTS_R if load else (0.0,))]
    x0 = min(starts, key=lambda x: float(np.sum(residual(x) ** 2)))
    found = least_squares(residual, x0, bounds=(lo, hi), max_nfev=_EVALUATIONS,
                          diff_step=1e-3, ftol=POLISH_TOL, xtol=POLISH_TOL)
    return shapes(found.x), len(lo)


def _shapes_of(problem: Problem, fit: Fit, effect: str) -> int:
    """The shapes ``fit`` spends on a factor the law takes the place of: its parameters in
    use (one held at a lower bound of 0 is not, as :func:`.fitting.fit_model` counts) and
    the terms its refinements added (a temperature band's two, a speed term; the low-load
    drag's viscosity exponent)."""
    used = (shapes_in_use(problem, (effect,), fit.theta)
            - shapes_in_use(problem, (), fit.theta))  # the baseline's nuisances are kept
    if effect == "temperature_dependence":
        return used + 2 * (problem.temperature_band is not None) + (problem.speed_loss != 0.0)
    return used + (problem.drag_viscosity_exponent != 0.0)


def _slope_bounds() -> tuple[float, float]:
    """The temperature dependence's bounds of the viscosity slope b [1/K]."""
    b = next(p for p in nonlinear_parameters("temperature_dependence", "efficiency")
             if p.name == "b")
    return b.lower, b.upper


def _hersey_text(hersey: tuple[float, float, float], load: bool, warm: bool) -> str:
    """Hersey's number as fitted, in words."""
    _, r, b = hersey
    return (("ν(t)/ν(20 °C)·" if warm else "") + "(n/1000 r/min)"
            + (f"/α^{r:.2f}" if load else "") + (f" (viscosity slope {b:.3g}/K)" if warm
                                                 else ""))


def hersey_params(problem: Problem, fit: Fit, effect: str) -> dict[str, tuple[float, str]]:
    """The Stribeck law's figures for one of the effects it stands in for: the boundary
    scale, the effect's own shape (the pressure exponent for the low-load loss, the
    viscosity slope for the temperature law) and, on the effect that carries them, the
    losses [% points]: the boundary loss as H → 0, the film losses at H = 1."""
    h_b, r, b = problem.hersey
    out = {"boundary_scale_H_b": (h_b, "-")}
    if effect == "low_load_efficiency":
        out["pressure_exponent_r"] = (r, "-")
    else:
        out["viscosity_slope_b"] = (b, "1/K")
    for (e, n), v in zip(fit.labels, fit.beta):
        if e == effect and n in laws.STRIBECK_LABELS:
            out[n] = (float(v), "%")
    return out
