"""Fitting a model (the catalog baseline plus a set of effects) to one data set.

A model is the baseline's free columns (nuisances of the catalog: offset, compliance scale,
efficiency level), the columns of the measurement-chain effects (:mod:`.rig`) and those of
the gear effects (:mod:`.effects`), put together by :mod:`.model_columns`. Amplitudes
enter linearly and are solved by linear least squares; shapes (widths, loop parameters,
damping, the corner width of the catalog curve) are fitted by
``scipy.optimize.least_squares`` over the linear solution (variable projection, its
Jacobian from :mod:`.varpro`), started from a grid and from the values of simpler models
(multi-start).

Rows flagged as gross outliers are left out of the fit (a hard-redescending robust loss).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.optimize import least_squares

from . import baseline as baselines
from . import effects as fx
from . import preisach
from .bounded import solve
from .harmonics import TE_ORDER
from .model_columns import columns, nonlinear
from .varpro import free_amplitudes, projected_jacobian, steps

# Above this many rows the fit uses this many rows drawn at random (fixed seed; time order
# kept, torque turning points added) — even steps could alias an efficiency grid sweep;
# the final prediction and the RMSE use every row.
MAX_FIT_ROWS = 5_000
GRID_POINTS = 6
REGRID_POINTS = 4        # coarser grid when earlier effects are searched again
# relative change of the RSS (and of the shapes) at which a shape fit stops: a ΔBIC of 0.1
# at 1000 effective samples, far below the gates' margins. Against 1e-5 it saves 15 % of
# the time and changes names only on ties (4 of 1548 truth cases, 2 closer to the truth);
# 1e-3 moves the rmse of a few cases by up to 8 %
POLISH_TOL = 1e-4
CV_FOLDS = 5
CV_CHUNKS = 25           # 5 contiguous chunks per fold, spread over the record
# Catalog figures that scale effect bounds, and the kinds whose effects use them.
FIGURE_KINDS = {"hysteresis_rad": ("torsion",), "backlash_rad": ("torsion",),
                "accuracy_rad": ("transmission", "vibration")}
@dataclass
class Problem:
    """One data set with its baseline and everything the effect columns need."""

    kind: str
    base: baselines.Baseline
    scales: dict[str, float]
    rows: np.ndarray
    folds: np.ndarray
    notes: list[str]
    branches: tuple[np.ndarray, int] | None = None
    fit_branches: tuple[np.ndarray, int] | None = None
    outliers: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    step_position: float = 0.0
    # order q of a drive's ripple per input revolution (drive.best_order), 0 for none
    drive_order: int = 0
    te_order: int = TE_ORDER  # Legendre order of the TE amplitude and phase
    # harmonics of the named errors at k cycles per WG revolution (a wave generator's
    # ellipse series: 4× and 6× beside 2×), each with a constant amplitude: none while
    # effects are named, chosen by BIC once they are (te_forms.refine_te_overtones)
    te_overtones: tuple[int, ...] = ()
    # transmission: a named error's periodic modulation k → (f_m [cycles per WG rev.], j):
    # sidebands k ± f_m … k ± j·f_m (te_forms.refine_te_sidebands), none while naming
    te_sidebands: dict[int, tuple[float, int]] = field(default_factory=dict)
    # the 1× error's 2× overtone locked to it: (the 1×'s phase p, the law's shift) [rad]
    # (harmonics.locked_overtone; seconds.te_2x_as_overtone), None when it carries none
    te_locked_2x: tuple[float, float] | None = None
    # hysteresis as a slip element in series with the gear (z_sat·(T/T_s − z)), not friction
    # in parallel with it (−z_sat·z): the reading a hysteresis + spring pair is tested against
    hysteresis_series: bool = False
    scale_free: bool = False  # the compliance scale beyond the catalog's spread
    # hysteresis as a friction torque in parallel with the gear's spring, its twist the torque
    # times the curve's local compliance (narrower where the gear stiffens), tried once named
    hysteresis_through_gear: bool = False
    # hysteresis as a loop about the catalog curve (its centre line taken out: the catalog
    # curve is the mean of loading and unloading) instead of a loop with its own backbone
    hysteresis_centred: bool = False
    # hysteresis as a Preisach relay sum (preisach.PreisachPlane) with this density: (median
    # slip torque [N·m], its log-spread [-], spread of the relays' centres [N·m]) instead of
    # the Bouc–Wen loop; tried once the effect is named (loops.refine_preisach)
    hysteresis_preisach: tuple[float, float, float] | None = None
    # hysteresis as friction elements with fixed slip torques, weighted freely (plays: an
    # Iwan model) instead of the Bouc–Wen loop (loops.refine_plays), their slip torques grown
    # by a share of the torque carried; or as a Duhem loop (λ, p) (widening_loops.py)
    hysteresis_plays: bool = False
    plays_load_share: float = 0.0
    hysteresis_duhem: tuple[float, float] | None = None
    # hysteresis as creep elements (creep.py): "alone" in place of the friction loop, "beside"
    # it, or None; their centre lines taken out (creep_centred) or not (loops.refine_creep)
    hysteresis_creep: str | None = None
    creep_centred: bool = False
    # constant C [°C] of the viscosity–temperature law (efficiency_laws.VISCOSITY_LAWS_C):
    # Reynolds' while effects are named, the best once they are (refine.refine_viscosity)
    viscosity_C: float = math.inf
    # (centre [°C], width [K]) of a band of temperature over which the loss changes
    # (efficiency_laws.band_ratio) in place of the viscosity law: None while effects are
    # named, tried once they are (refine.refine_viscosity)
    temperature_band: tuple[float, float] | None = None
    # share u of the viscous loss at t_ref that grows with speed: 0 while effects are named,
    # fitted once they are (refine.refine_viscosity)
    speed_loss: float = 0.0
    # efficiency: a Stribeck law's shapes (H_b, r, b) in place of factors (stribeck.py), or None
    hersey: tuple[float, float, float] | None = None
    drag_viscosity_exponent: float = 0.0  # k of the low-load drag ∝ ν^k beside a temperature law
    # the low-load factor flat at rated torque (efficiency_laws.low_load_factor), once named
    low_load_flat: bool = False
    # knee torque T_k [N·m] of a housing spring that stiffens (spring_forms.progressive_twist):
    # ∞ (linear) while effects are named, fitted once they are (springs.stiffening)
    housing_knee: float = math.inf
    # torque T_o [N·m] past which a housing spring's joint opens (springs.refine_opening)
    housing_opening: float = math.inf
    # torque that holds a play at one side until the load passes it, as a share of T0
    # (effects.backlash_twist): 0 while naming, fitted once backlash is (refine.refine_play)
    play_hold: float = 0.0
    # torque at which a play is crossed, as a share of T0 (a steady torque preloads one
    # flank: a slider's weight), 0 while naming, fitted once backlash is (refine.refine_play)
    play_bias: float = 0.0
    # ln p of a play's engagement exponent p (effects.backlash_twist): 0 (p = 1, tanh) while
    # naming, fitted once backlash is (refine.refine_play)
    play_shape: float = 0.0
    # a held play's position before the load first passes the holding torque (where the
    # last handling left it): a free twist, once the hold is kept (refine.refine_play)
    play_start: bool = False
    # a play's lost motion along the record: its Legendre order (wear, warmth) or one step's
    # position (an input locked at another angle), by BIC once named (refine_play_drift)
    play_drift: int = 0
    play_step: float | None = None
    # the member each harmonic's error turns with (k → δ: its angle k·(1 + δ)·φ, φ the WG
    # angle): δ = 0 the fixed circular spline, else the output member's (frames.frames);
    # and a second member's share at constant amplitude (frames.refine_frames)
    te_frames: dict[int, float] = field(default_factory=dict)
    te_second_frames: dict[int, float] = field(default_factory=dict)
    # vibration: the joint's response as the steady state at each instant's frequency through
    # a spring with structural damping (joint.steady_response) instead of the viscous joint's
    # run-up: the latter while effects are named, the better once they are (refine_damping)
    steady_state: bool = False
    # vibration: the viscous joint's damper on its twist θ − e (the gear's own damping)
    # instead of on the load's motion: the latter while effects are named (refine_damping)
    relative_damping: bool = False
    cache: dict = field(default_factory=dict)
    _plane: preisach.PreisachPlane | None = field(default=None, repr=False)

    @property
    def y(self) -> np.ndarray:
        """The data less the catalog's fixed part on the fitted rows (kept: read only)."""
        key = ("y", id(self.rows))
        if key not in self.cache:
            self.cache[key] = self.base.y[self.rows] - self.base.fixed[self.rows]
        return self.cache[key]

    @property
    def preisach_plane(self) -> preisach.PreisachPlane:
        """The relay plane of the record's torque (its Everett terms, listed once)."""
        if self._plane is None:
            self._plane = preisach.PreisachPlane(self.base.inputs["torque_Nm"],
                                                 self.scales["T0"])
        return self._plane


def copy_problem(problem: Problem) -> Problem:
    """``problem`` with its own notes and settings (its data and caches shared)."""
    return replace(problem, notes=list(problem.notes), scales=dict(problem.scales),
                   te_sidebands=dict(problem.te_sidebands), te_frames=dict(problem.te_frames),
                   te_second_frames=dict(problem.te_second_frames))


@dataclass
class Fit:
    effects: tuple[str, ...]
    theta: dict[str, float]
    beta: np.ndarray
    labels: list[tuple[str, str]]   # (effect or 'baseline', linear parameter name)
    prediction: np.ndarray          # on every row
    rss: float                      # on the fit rows
    n_params: int
    cv_value: float = math.nan
    columns: np.ndarray | None = None   # design matrix on the fit rows
    # (y, lower, upper, folds) of the fit rows: the cross-validation, run when first asked
    cv_inputs: tuple | None = field(default=None, repr=False, compare=False)

    def residual(self, problem: Problem) -> np.ndarray:
        """Residual on the fit rows."""
        return problem.y - self.columns @ self.beta

    @property
    def shapes(self) -> int:
        """The parameters counted besides the amplitudes in use: shapes and refinements' terms."""
        return self.n_params - int(np.count_nonzero(self.beta))

    @property
    def cv_mse(self) -> float:
        """5-fold cross-validated mean-square error with the shapes held (computed when a
        gate first asks: most fits are only compared by their RSS)."""
        if math.isnan(self.cv_value) and self.cv_inputs is not None:
            self.cv_value = _cv_mse(self.columns, *self.cv_inputs)
        return self.cv_value


def _scales(base: baselines.Baseline, notes: list[str]) -> dict[str, float]:
    """Scales of the effect bounds: catalog figures, else the range of the residual."""
    scales = {"1": 1.0}
    span = float(np.ptp(base.y - base.fixed)) or 1.0
    for key, kinds in FIGURE_KINDS.items():
        scales[key] = base.figures[key][0] if key in base.figures else span
        if key not in base.figures and base.kind in kinds:
            notes.append(f"{key.removesuffix('_rad')} not in the catalog for this model: "
                         "effect bounds scaled by the range of the residual instead")
    if "torque_Nm" in base.inputs:
        scales["T0"] = float(np.max(np.abs(base.inputs["torque_Nm"])))
    if "K1_Nm_per_rad" in base.figures:
        scales["1/K1"] = 1.0 / base.figures["K1_Nm_per_rad"][0]
    if "T1_Nm" in base.figures:
        scales["T1"] = base.figures["T1_Nm"][0]
    return scales


def make_problem(kind: str, base: baselines.Baseline) -> Problem:
    n = len(base.y)
    rows = np.arange(n)
    if n > MAX_FIT_ROWS:  # spread at random (fixed seed): even steps can alias a grid sweep
        rows = np.sort(np.random.default_rng(0).choice(n, MAX_FIT_ROWS, replace=False))
    branches = None
    if kind == "torsion":
        torque = base.inputs["torque_Nm"]
        branches = fx.turning_points(torque, fx.TURN_FRACTION * np.ptp(torque))
        # the turning points stay in the fitted rows: the hysteresis state of every later
        # row depends on the torque reached there
        rows = np.union1d(rows, branches[0])
    if n > MAX_FIT_ROWS:
        base.notes.append(f"{n} rows: fitted on {len(rows)} rows spread over the record, "
                          "RMSE on every row")
    notes = list(base.notes)
    problem = Problem(kind, base, _scales(base, notes), rows, np.zeros(0), notes)
    if kind == "vibration":  # the response to a steady error names the effects
        problem.te_order = 0
    problem.branches = branches
    if branches is not None:  # the sign of each row's branch (a reading's play steps with it)
        base.inputs["branch_direction"] = fx.branch_direction(n, branches)
    set_rows(problem, rows)
    return problem


def set_rows(problem: Problem, rows: np.ndarray) -> None:
    """Fit on ``rows``: contiguous cross-validation chunks and the torsion branch starts."""
    problem.rows = rows
    chunk = np.minimum((np.arange(len(rows)) * CV_CHUNKS) // len(rows), CV_CHUNKS - 1)
    problem.folds = chunk % CV_FOLDS
    if problem.branches is not None:
        problem.fit_branches = (np.searchsorted(rows, problem.branches[0]),
                                problem.branches[1])
    problem.cache.clear()


# --------------------------------------------------------------------------- fitting
def _transform(p: fx.Parameter, scale: float):
    lo, hi = p.lower * scale, p.upper * scale
    log = lo > 0 and hi / lo >= 10
    return log, lo, hi


def _grid(p: fx.Parameter, scale: float, points: int = GRID_POINTS) -> np.ndarray:
    log, lo, hi = _transform(p, scale)
    if log:
        return np.geomspace(lo, hi, points + 2)[1:-1]
    return np.linspace(lo, hi, points + 2)[1:-1]


def _evaluate(problem: Problem, effects, theta):
    Xf, labels, lo, hi = columns(problem, effects, theta)
    beta = solve(Xf, problem.y, lo, hi)
    return Xf, beta, labels, lo, hi


def fit_model(problem: Problem, effects: tuple[str, ...],
              start: dict[str, float] | None = None) -> Fit:
    """Fit ``effects`` on top of the baseline; ``start`` holds known nonlinear values."""
    params = nonlinear(problem.kind, effects)
    keys = list(params)
    scale = {k: problem.scales[params[k].scale] for k in keys}
    theta = {k: v for k, v in (start or {}).items() if k in params}
    new = [k for k in keys if k not in theta]
    for k in keys:
        start_value = params[k].start
        theta.setdefault(k, float(_grid(params[k], scale[k])[GRID_POINTS // 2])
                         if start_value is None else start_value * scale[k])
    searched = [k for k in new if params[k].start is None]

    def rss_of(th):
        return rss_at(problem, effects, th)

    def grid_search(th, names, points):
        """Best of a grid over ``names`` with the other shape parameters held."""
        grids = np.meshgrid(*[_grid(params[k], scale[k], points) for k in names],
                            indexing="ij")
        best, out = math.inf, th
        for values in zip(*[g.ravel() for g in grids]):
            trial = {**th, **dict(zip(names, map(float, values)))}
            rss = rss_of(trial)
            if rss < best:
                best, out = rss, trial
        return out

    if searched:
        theta = grid_search(theta, searched, GRID_POINTS)
    if keys:
        theta = _polish(problem, effects, theta, keys, params, scale)
    old = [k for k in keys if k not in new and params[k].start is None]
    if new and old:
        # the earlier shapes were fitted without the new effect and may have bent to mimic
        # it: search them again with the new effect in place and keep the better fit
        again = _polish(problem, effects, grid_search(theta, old, REGRID_POINTS), keys,
                        params, scale)
        if rss_of(again) < rss_of(theta):
            theta = again
    return finish(problem, effects, theta, shapes_in_use(problem, effects, theta))


def shapes_in_use(problem: Problem, effects: tuple[str, ...], theta: dict[str, float]) -> int:
    """The shapes of ``effects`` in use at ``theta``: one held at a lower bound of 0 (a speed
    exponent of 0) is the simpler model's value, not a parameter."""
    params = nonlinear(problem.kind, effects)
    return sum(1 for k, p in params.items()
               if not (p.lower == 0.0 and theta[k] <= 1e-6 * problem.scales[p.scale] * p.upper))


def best_setting(problem: Problem, fit: Fit, current, settings, apply) -> tuple[Fit, object]:
    """(fit, setting): ``fit``, made at the problem's setting ``current``, or its refit under
    whichever of ``settings`` leaves the least residual (the forms a named effect can take
    with the same shapes: a viscosity law, a loop's form, the low-load curve's shape);
    ``apply(setting)`` puts one in the problem, which is left at the winner's."""
    best, chosen = fit, current
    for setting in settings:
        if setting == current:
            continue
        apply(setting)
        trial = fit_model(problem, fit.effects, fit.theta)
        if trial.rss < best.rss:
            best, chosen = trial, setting
    apply(chosen)
    return best, chosen


def rss_at(problem: Problem, effects: tuple[str, ...], theta: dict[str, float]) -> float:
    """The residual sum of squares on the fitted rows at the shape ``theta`` (amplitudes
    solved; what comparing shapes needs, without the prediction and the CV of a Fit)."""
    Xf, beta, *_ = _evaluate(problem, effects, theta)
    r = problem.y - Xf @ beta
    return float(r @ r)


def finish(problem: Problem, effects: tuple[str, ...], theta: dict[str, float],
           n_shapes: int) -> Fit:
    """The :class:`Fit` of a model at the shape ``theta``: amplitudes, prediction, CV."""
    Xf, beta, labels, lo, hi = _evaluate(problem, effects, theta)
    r = problem.y - Xf @ beta
    X = columns(problem, effects, theta, full=True)[0]
    # a bounded amplitude held at its bound (a play operator's weight at 0) is not in use
    fit = Fit(effects, theta, beta, labels, problem.base.fixed + X @ beta, float(r @ r),
              int(np.count_nonzero(beta)) + n_shapes, columns=Xf,
              cv_inputs=(problem.y, lo, hi, problem.folds))
    return fit


def _polish(problem, effects, theta, keys, params, scale):
    """All shape parameters together by bounded nonlinear least squares."""
    forms = [_transform(params[k], scale[k]) for k in keys]
    to_x = lambda th: np.array([math.log(th[k]) if f[0] else th[k] for k, f in zip(keys, forms)])
    lo = np.array([math.log(f[1]) if f[0] else f[1] for f in forms])
    hi = np.array([math.log(f[2]) if f[0] else f[2] for f in forms])

    def from_x(x):
        return {**theta, **{k: (math.exp(v) if f[0] else float(v))
                            for k, v, f in zip(keys, x, forms)}}

    last: dict = {}

    def at(x):
        """The model at ``x``, kept for the Jacobian that least_squares asks for next."""
        if last.get("x") is None or not np.array_equal(last["x"], x):
            Xf, beta, _, b_lo, b_hi = _evaluate(problem, effects, from_x(x))
            last.update(x=x.copy(), Xf=Xf, beta=beta, free=free_amplitudes(beta, b_lo, b_hi))
        return last

    def raw(x):
        m = at(x)
        return problem.y - m["Xf"] @ m["beta"]

    def derivative(x):
        def columns_at(xk):
            return columns(problem, effects, from_x(xk))[0]
        J = projected_jacobian(problem.y, at(x), x, lo, hi, columns_at)
        if J is None:  # collinear amplitudes: differences of the whole residual
            J = np.column_stack([(raw(xk) - raw(x)) / h for xk, h in steps(x, lo, hi)])
        return J / unit

    x0 = np.clip(to_x(theta), lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo))
    # in the start's RMS: least_squares' gradient tolerance is absolute, and a residual of
    # micro-radians would otherwise stop it at the start
    unit = float(np.sqrt(np.mean(raw(x0) ** 2))) or 1.0
    residual = lambda x: raw(x) / unit
    result = least_squares(residual, x0, jac=derivative, bounds=(lo, hi),
                           x_scale=np.maximum(hi - lo, 1e-9), max_nfev=40 * len(keys),
                           ftol=POLISH_TOL, xtol=POLISH_TOL)
    return from_x(result.x)


def _cv_mse(Xf, y, lo, hi, folds) -> float:
    """5-fold cross-validated mean-square error (shape parameters held)."""
    err = 0.0
    for k in range(CV_FOLDS):
        test = folds == k
        beta = solve(Xf[~test], y[~test], lo, hi)
        r = y[test] - Xf[test] @ beta
        err += float(r @ r)
    return err / len(y)
