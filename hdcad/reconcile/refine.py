"""Refinements of the named model once the effects are chosen: how closely the transmission
error follows its slow modulation, the joint's spring on the catalog curve, the
temperature law's viscosity law and speed term, and a low-load drag that grows with the
oil's viscosity.

None changes which effects are named; each makes the reconciled model follow the data as
closely as the physics and the noise allow, and says what it chose in the notes.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

import numpy as np
from scipy.optimize import least_squares, minimize_scalar

from . import effects as fx
from . import joint
from .baseline import STIFFNESS_SPREAD
from .fitting import (TE_ORDER_MAX, Fit, Problem, columns, finish, fit_model, nonlinear,
                      te_basis)
from .noise import ar1_time, noise_model

# relative step of the finite differences in ln ζ and the stiffness scale
_FD_STEP = 1e-4
_MAX_EVALUATIONS = 12
_SCREEN_EVALUATIONS = 4
_SCAN_STEP = 0.02  # stiffness scale
_SPEED_LOSS_BOUNDS = (-0.5, 0.9)  # as the viscous share a of the temperature law
# exponent k of a drag ∝ ν^k: 0 (no coupling) … 2 (Petroff's viscous torque is ∝ ν; a
# rolling bearing's no-load torque ∝ ν^(2/3), Palmgren)
_DRAG_VISCOSITY_BOUNDS = (0.0, 2.0)
_PLAY_HOLD_BOUNDS = (0.0, 0.3)  # holding torque of a play, as a share of the largest torque


def refine_te_order(problem: Problem, fit: Fit) -> Fit:
    """The named transmission errors with the Legendre order of their slowly varying
    amplitude and phase chosen by BIC (effective sample size N/τ, τ from the most flexible
    fit's residual), from the naming order up to ``TE_ORDER_MAX``; leaves
    ``problem.te_order`` at it.

    Effects are named at a low order (a flexible TE would take what a second effect
    explains); once named, a modulated error (amplitude or phase varying over the record)
    is followed as closely as the data support.
    """
    if not any(e.startswith("te_") for e in fit.effects):
        return fit
    shapes = len(nonlinear(problem.kind, fit.effects))
    fits = {}
    # the widest first: the lower orders' columns are its first ones (cached)
    for order in [TE_ORDER_MAX, *range(problem.te_order, TE_ORDER_MAX)]:
        problem.te_order = order
        fits[order] = finish(problem, fit.effects, fit.theta, shapes)
    best = _bic_best({o: (f.rss, f.n_params) for o, f in fits.items()},
                     _effective_n(problem, fits[TE_ORDER_MAX].residual(problem)))
    problem.te_order = best
    return fits[best]


def _effective_n(problem: Problem, residual: np.ndarray) -> float:
    """N/τ of the fitted rows, τ from the AR(1) noise of ``residual``."""
    return len(problem.rows) / ar1_time(noise_model(residual)[1])


def _bic_best(fits: dict, n_eff: float):
    """The key of ``fits`` ({key: (rss, parameters)}) with the lowest BIC at n_eff."""
    return min(fits, key=lambda k: n_eff * math.log(max(fits[k][0], 1e-300))
               + fits[k][1] * math.log(n_eff))


class CurveFit(Fit):
    """A fit whose prediction is not linear in its amplitudes (the joint on the catalog
    curve); ``columns`` holds its Jacobian at the fit."""

    def residual(self, problem: Problem) -> np.ndarray:
        return problem.base.y[problem.rows] - self.prediction[problem.rows]


def refine(problem: Problem, fit: Fit) -> Fit:
    """The named model's final form: the joint on the catalog curve where the twist leaves
    its first segment (vibration), the TE modulation's order, the viscosity law, the
    hysteresis through the gear's compliance."""
    curved = refine_spring(problem, fit)
    if curved is fit:
        return refine_play(problem, refine_hysteresis(problem, refine_viscosity(
            problem, refine_te_order(problem, fit))))
    return curved


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


def refine_play(problem: Problem, fit: Fit) -> Fit:
    """A named backlash whose play friction holds at one side until the load passes a
    holding torque T_h in the new direction (a loop at zero torque of area b·2T_h), one
    parameter more, kept when BIC prefers it (:func:`_one_more`)."""
    if "backlash" not in fit.effects or problem.branches is None:
        return fit
    t0 = problem.scales["T0"]
    return _one_more(problem, fit, "play_hold", _PLAY_HOLD_BOUNDS, lambda h: (
        f"backlash: the play is held by friction until the load passes {h * t0:.3g} N·m "
        "in the new direction"))


def refine_viscosity(problem: Problem, fit: Fit) -> Fit:
    """The viscosity–temperature law of a named temperature dependence: Reynolds'
    exponential (used to name it), Andrade's or Vogel–Cameron's, whichever fits best (the
    same parameters; the laws differ in how the viscosity curves over the temperatures)."""
    if "temperature_dependence" not in fit.effects:
        return fit
    best, law = fit_viscosity_law(problem, fit)
    problem.notes.append(f"viscosity law: {law} (C = {problem.viscosity_C:g} °C), the best "
                         f"of {', '.join(fx.VISCOSITY_LAWS_C)} on these data")
    return _viscous_drag(problem, _speed_loss(problem, best))


def fit_viscosity_law(problem: Problem, fit: Fit) -> tuple[Fit, str]:
    """(fit, law name): ``fit`` (at Reynolds' exponential) or its refit under Andrade's or
    Vogel–Cameron's law, whichever leaves the least residual; ``problem.viscosity_C`` is
    left at that law."""
    best, law = fit, "Reynolds"
    for name, constant in fx.VISCOSITY_LAWS_C.items():
        if math.isinf(constant):
            continue
        problem.viscosity_C = constant
        trial = fit_model(problem, fit.effects, fit.theta)
        if trial.rss < best.rss:
            best, law = trial, name
    problem.viscosity_C = fx.VISCOSITY_LAWS_C[law]
    return best, law


def _speed_loss(problem: Problem, fit: Fit) -> Fit:
    """The temperature law with its viscous loss at t_ref growing with speed as well
    (``speed_loss`` u, one parameter more), kept when BIC with the effective sample size
    prefers it: the law then has one reference point (t_ref, n_ref) instead of t_ref at
    every speed."""
    if fit.theta.get("temperature_dependence.s", 0.0) == 0.0:
        return fit  # no speed in the law: u would have nothing to act on
    return _one_more(problem, fit, "speed_loss", _SPEED_LOSS_BOUNDS, lambda u: (
        f"temperature law: the viscous loss at {fx.REFERENCE_TEMPERATURE_C:g} °C grows with "
        f"speed too (u = {u:.3g} of the input power at {fx.KE_REFERENCE_SPEED_RPM:g} r/min, "
        "× (n/n_ref)^s − 1)"))


def _viscous_drag(problem: Problem, fit: Fit) -> Fit:
    """A named low-load factor whose drag grows with the oil's viscosity (× g^k, the
    temperature law's g; ``drag_viscosity_exponent`` k, one parameter more), kept when BIC
    prefers it. A drag torque is a viscous loss too (Palmgren: ∝ (ν·n)^(2/3)), so the
    efficiency at low load falls further in a cold gear: the two effects do not multiply
    independently."""
    if not {"low_load_efficiency", "temperature_dependence"} <= set(fit.effects):
        return fit
    return _one_more(problem, fit, "drag_viscosity_exponent", _DRAG_VISCOSITY_BOUNDS,
                     lambda k: "low-load factor: its drag grows with the oil's viscosity "
                               f"(no-load loss × (ν/ν(20 °C))^{k:.3g}; Palmgren)")


def _one_more(problem: Problem, fit: Fit, attribute: str, bounds: tuple[float, float],
              note) -> Fit:
    """``fit`` with one more term, the scalar ``problem.attribute`` searched within
    ``bounds`` with the shapes refitted, kept (and ``note(value)`` added) when BIC with the
    effective sample size prefers it; else ``fit`` with the attribute back at 0."""

    def trial(value: float) -> Fit:
        setattr(problem, attribute, float(value))
        return fit_model(problem, fit.effects, fit.theta)

    found = minimize_scalar(lambda v: trial(v).rss, bounds=bounds, method="bounded",
                            options={"xatol": 1e-3, "maxiter": 20})
    wider = trial(found.x)
    n_eff = _effective_n(problem, wider.residual(problem))
    if _bic_best({False: (fit.rss, 0), True: (wider.rss, 1)}, n_eff) is False:
        setattr(problem, attribute, 0.0)
        return fit
    problem.notes.append(note(found.x))
    return replace(wider, n_params=wider.n_params + 1)


def refine_spring(problem: Problem, fit: Fit) -> Fit:
    """Vibration: the joint on the catalog's three-segment spring (:mod:`.joint`) when the
    linear joint's twist passes T1/K1, kept when it fits the data better (same parameters).

    The excitation amplitudes, offsets and measurement effects, ζ and the stiffness scale
    are fitted together by bounded Gauss–Newton from the linear joint's fit, at the naming
    order of the error's modulation; the order is then chosen by BIC on the curve's
    linearisation (:func:`_curve_order`).
    """
    base = problem.base
    te = [e for e in fit.effects if e.startswith("te_")]
    if problem.kind != "vibration" or not te or not joint.has_curve(base.spring):
        return fit
    step = np.diff(base.inputs["time_s"])
    if np.ptp(step) > 1e-6 * step.mean():
        problem.notes.append("joint spring: linear K1 (the catalog curve needs even time "
                             "steps)")
        return fit
    model = _CurveModel(problem, fit, te, float(step.mean()))
    if model.linear_twist <= model.theta1(fit.theta["stiffness_scale"]):
        return fit  # the joint stays on the curve's first segment: it is the linear one
    # a few steps from each start (model.starts), then the best one on to convergence
    result = min((model.solve(x0, _SCREEN_EVALUATIONS) for x0 in model.starts(fit)),
                 key=lambda r: r.cost)
    result = model.solve(result.x)
    if 2 * result.cost >= fit.rss:
        problem.notes.append("joint spring: linear K1 (the catalog curve fits no better)")
        return fit
    twist = model.peak_twist(result.x) / model.theta1(result.x[-1])
    refined = _curve_order(problem, model, result.x)
    problem.notes.append(f"joint spring: the catalog's three-segment curve (the twist reaches "
                         f"{twist:.2f}× T1/K1 near resonance; the linear K1 joint left "
                         f"{math.sqrt(fit.rss / (2 * result.cost)):.2f}× the residual)")
    return refined


def _curve_order(problem: Problem, model: "_CurveModel", x: np.ndarray) -> Fit:
    """The TE modulation's order on the curve: BIC over one Gauss–Newton step from ``x``
    with the tangents of every order's columns, then the chosen order fitted in full."""
    base_order = problem.te_order
    problem.te_order = TE_ORDER_MAX
    U = model.basis()
    tangent = model.tangents(x, U)[problem.rows]
    r = model.residual(x)
    per_effect = U.shape[1] // len(model.te)
    width = lambda o: 2 * (o + 1)
    fits = {}
    for order in range(base_order, TE_ORDER_MAX + 1):
        keep = [k * per_effect + j for k in range(len(model.te)) for j in range(width(order))]
        D = np.column_stack([tangent[:, keep], model.X_add[problem.rows]])
        delta = np.linalg.lstsq(D, r, rcond=None)[0]
        rr = r - D @ delta
        fits[order] = (float(rr @ rr), D.shape[1] + 2)
    # τ from the most flexible order's residual, as for the linear joint
    best = _bic_best(fits, _effective_n(problem, rr))
    problem.te_order = best
    shapes = len(nonlinear(problem.kind, model.fit.effects))
    linear = finish(problem, model.fit.effects, model.theta_at(x), shapes)
    wider = _CurveModel(problem, linear, model.te, model.dt)
    start = wider.widen(x, model, base_order)
    result = wider.solve(start)
    return wider.fit_at(result.x)


class _CurveModel:
    """The named vibration model with the joint on the catalog curve, as a function of
    x = [excitation amplitudes, additive amplitudes, ln ζ, stiffness scale]."""

    def __init__(self, problem: Problem, fit: Fit, te: list[str], dt: float):
        self.problem, self.fit, self.te, self.dt = problem, fit, te, dt
        base = problem.base
        self.J = float(base.inputs["J_kgm2"])
        self.K1 = float(base.spring.K1)
        self.te_index = [i for i, (e, _) in enumerate(fit.labels) if e in te]
        self.add_index = [i for i in range(len(fit.labels)) if i not in self.te_index]
        self.U = self.basis()
        X = columns(problem, fit.effects, fit.theta, full=True)[0]
        self.X_add = X[:, self.add_index]
        self.linear_twist = joint.peak_twist(X[:, self.te_index] @ fit.beta[self.te_index],
                                             self.U @ fit.beta[self.te_index])
        self.y = base.y - base.fixed
        self._cache: tuple | None = None

    def theta1(self, scale: float) -> float:
        return joint.Spring.from_curve(self.problem.base.spring, scale).theta1

    def peak_twist(self, x) -> float:
        """|θ − e| [rad] of the joint on the curve at ``x``."""
        return joint.peak_twist(self.response(x)[0], self.U @ self._split(x)[0])

    def basis(self) -> np.ndarray:
        return np.column_stack([c for e in self.te for c in te_basis(self.problem, int(e[3]))])

    def solve(self, x0: np.ndarray, evaluations: int = _MAX_EVALUATIONS):
        # least_squares' gradient tolerance is absolute: put it in the start residual's
        # units (micro-radians would otherwise stop it at the start)
        unit = float(np.mean(self.residual(x0) ** 2)) or 1.0
        return least_squares(self.residual, x0, jac=self.jacobian, bounds=self.bounds,
                             x_scale="jac", max_nfev=evaluations, gtol=1e-8 * unit)

    def theta_at(self, x) -> dict[str, float]:
        _, _, zeta, scale = self._split(x)
        return {**self.fit.theta, "damping_ratio": zeta, "stiffness_scale": float(scale)}

    def widen(self, x, narrow: "_CurveModel", order: int) -> np.ndarray:
        """``narrow``'s solution ``x`` (error at ``order``) as a start of this model."""
        a, b, zeta, scale = narrow._split(x)
        per_narrow = len(a) // len(narrow.te)
        per = len(self.te_index) // len(self.te)
        wide = np.zeros(len(self.te_index))
        for k in range(len(self.te)):
            wide[k * per:k * per + per_narrow] = a[k * per_narrow:(k + 1) * per_narrow]
        return np.concatenate([wide, b, [math.log(zeta), scale]])

    def starts(self, fit: Fit) -> list[np.ndarray]:
        """The linear joint's solution, and the same at the catalog's stiffness and at the
        best of a scan over the stiffness (amplitudes held): where a stiffening joint
        jumps off its resonance moves with the stiffness, so the fit's error has a local
        minimum at each jump position."""
        th = fit.theta
        x0 = np.concatenate([fit.beta[self.te_index], fit.beta[self.add_index],
                             [math.log(th["damping_ratio"]), th["stiffness_scale"]]])
        lo, hi = 1 - 2 * STIFFNESS_SPREAD, 1 + 2 * STIFFNESS_SPREAD
        scan = np.linspace(lo, hi, int(round((hi - lo) / _SCAN_STEP)) + 1)
        cost = [self._cost_at(np.concatenate([x0[:-1], [s]])) for s in scan]
        out = [x0]
        for s in (1.0, float(scan[int(np.argmin(cost))])):
            if all(abs(x[-1] - s) > 1e-3 for x in out):
                out.append(np.concatenate([x0[:-1], [s]]))
        return out

    def _cost_at(self, x) -> float:
        r = self.residual(x)
        return float(r @ r)

    @property
    def bounds(self):
        p = {q.name: q for q in nonlinear("vibration", self.fit.effects).values()}
        zeta, scale = p["damping_ratio"], p["stiffness_scale"]
        n = len(self.te_index) + len(self.add_index)
        lo = np.concatenate([np.full(n, -np.inf), [math.log(zeta.lower), scale.lower]])
        hi = np.concatenate([np.full(n, np.inf), [math.log(zeta.upper), scale.upper]])
        return lo, hi

    # --------------------------------------------------------------- response
    def _split(self, x):
        m = len(self.te_index)
        return x[:m], x[m:-2], math.exp(x[-2]), x[-1]

    def _joint(self, x) -> tuple[joint.Spring, float, float]:
        """The spring, J [kg·m²] and c [N·m·s/rad] at ``x`` (the arguments of
        :func:`.joint.respond` after dt)."""
        _, _, zeta, scale = self._split(x)
        spring = joint.Spring.from_curve(self.problem.base.spring, scale)
        return spring, self.J, 2 * zeta * math.sqrt(scale * self.K1 * self.J)

    def response(self, x) -> tuple[np.ndarray, np.ndarray]:
        """θ [rad] on every row and the twist's segments at ``x`` (the last one kept)."""
        key = x.tobytes()
        if self._cache is None or self._cache[0] != key:
            a = self._split(x)[0]
            self._cache = (key, *joint.respond(self.U @ a, self.dt, *self._joint(x)))
        return self._cache[1], self._cache[2]

    def prediction(self, x) -> np.ndarray:
        return self.response(x)[0] + self.X_add @ self._split(x)[1]

    def tangents(self, x, U: np.ndarray | None = None) -> np.ndarray:
        """∂θ/∂a at ``x`` for the columns of ``U`` (default: this model's error basis)."""
        segments = self.response(x)[1]
        return joint.tangents(self.U if U is None else U, segments, self.dt, *self._joint(x))

    def residual(self, x) -> np.ndarray:
        return (self.y - self.prediction(x))[self.problem.rows]

    def jacobian(self, x) -> np.ndarray:
        rows = self.problem.rows
        pred = self.prediction(x)
        tangent = self.tangents(x)
        shapes = []
        for i in (len(x) - 2, len(x) - 1):  # ln ζ and the stiffness scale
            h = _FD_STEP * max(1.0, abs(x[i]))
            up = x.copy()
            up[i] += h
            theta = joint.respond(self.U @ self._split(up)[0], self.dt, *self._joint(up))[0]
            shapes.append((theta + self.X_add @ self._split(up)[1] - pred)[rows] / h)
        return -np.column_stack([tangent[rows], self.X_add[rows], *shapes])

    def fit_at(self, x) -> CurveFit:
        pred, tangent = self.prediction(x), self.tangents(x)
        a, b, zeta, scale = self._split(x)
        fit = self.fit
        beta = fit.beta.copy()
        beta[self.te_index] = a
        beta[self.add_index] = b
        full = self.problem.base.fixed + pred
        r = (self.problem.base.y - full)[self.problem.rows]
        columns = np.empty((len(self.problem.rows), len(beta)))
        columns[:, self.te_index] = tangent[self.problem.rows]
        columns[:, self.add_index] = self.X_add[self.problem.rows]
        return CurveFit(fit.effects, {**fit.theta, "damping_ratio": zeta,
                                      "stiffness_scale": float(scale)},
                        beta, fit.labels, full, float(r @ r), fit.n_params, fit.cv_mse,
                        columns)
