"""Vibration: the joint on the catalog's three-segment spring, fitted once the effects are
named (the linear joint names them): the excitation amplitudes, offsets, ζ and the stiffness
scale together by bounded Gauss–Newton, then the order of the error's modulation by BIC.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from . import joint
from .baseline import STIFFNESS_SPREAD
from .fitting import Fit, Problem, finish
from .model_columns import columns, nonlinear
from .harmonics import TE_ORDER_MAX, te_basis, te_order_of, te_width
from .gates import bic_best, effective_n

# relative step of the finite differences in ln ζ and the stiffness scale
_FD_STEP = 1e-4
_MAX_EVALUATIONS = 12
_SCREEN_EVALUATIONS = 4
_SCAN_STEP = 0.02  # stiffness scale


class CurveFit(Fit):
    """A fit whose prediction is not linear in its amplitudes (the joint on the catalog
    curve); ``columns`` holds its Jacobian at the fit."""

    def residual(self, problem: Problem) -> np.ndarray:
        return problem.base.y[problem.rows] - self.prediction[problem.rows]


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
    # a drive's ripple excites the same joint, but its columns are not run through the
    # curve's integration: the joint stays linear beside it
    if (problem.kind != "vibration" or not te or "drive_ripple" in fit.effects
            or not joint.has_curve(base.spring)):
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
    starts = _block_starts(problem, model.te)
    fits = {}
    for order in range(base_order, TE_ORDER_MAX + 1):
        problem.te_order = order
        widths = [te_width(problem, te_order_of(e)) for e in model.te]
        keep = [s + j for s, w in zip(starts, widths) for j in range(w)]
        D = np.column_stack([tangent[:, keep], model.X_add[problem.rows]])
        delta = np.linalg.lstsq(D, r, rcond=None)[0]
        rr = r - D @ delta
        fits[order] = (float(rr @ rr), D.shape[1] + 2)
    # τ from the most flexible order's residual, as for the linear joint
    best = bic_best(fits, effective_n(problem, rr))
    problem.te_order = best
    shapes = len(nonlinear(problem.kind, model.fit.effects))
    linear = finish(problem, model.fit.effects, model.theta_at(x), shapes)
    wider = _CurveModel(problem, linear, model.te, model.dt)
    start = wider.widen(x, model, base_order)
    result = wider.solve(start)
    return wider.fit_at(result.x)


def _block_starts(problem: Problem, te: list[str]) -> list[int]:
    """First column of each named error's block in the basis at the problem's order."""
    widths = [te_width(problem, te_order_of(e)) for e in te]
    return [int(v) for v in np.cumsum([0] + widths[:-1])]


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
        return np.column_stack([c for e in self.te for c in te_basis(self.problem, te_order_of(e))])

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
        saved = self.problem.te_order
        self.problem.te_order = order
        narrow_starts = _block_starts(self.problem, self.te)
        widths = [te_width(self.problem, te_order_of(e)) for e in self.te]
        self.problem.te_order = saved
        wide = np.zeros(len(self.te_index))
        for s, s_narrow, w in zip(_block_starts(self.problem, self.te), narrow_starts, widths):
            wide[s:s + w] = a[s_narrow:s_narrow + w]
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
