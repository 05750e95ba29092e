"""Reconcile a catalog model with measured data.

1. Simulate the baseline (catalog model, its free offset refitted), compute the residual and
   estimate the noise from the data (:mod:`.noise`).
2. Locate the disagreement: bins of the operating range and harmonics of the WG angle whose
   residual exceeds the noise significantly.
3. Fit every applicable effect together with the baseline's free parameters (the same for
   every candidate): amplitudes by linear least squares, shapes by
   ``scipy.optimize.least_squares`` (variable projection), started from a grid.
4. Accept the best candidate when it passes both gates (below); repeat on top of it; stop
   when no candidate passes. Name leftover structure no candidate explains.
5. Report RMSE before/after, overall and per region, and the parameters with units.

Ranking: by ΔBIC among the candidates that pass the gates (it charges each shape parameter,
so a 1-parameter series spring beats a 4-parameter loop that mimics it).

The gates. Noise is coloured, so a naive χ² overstates the evidence: the information
criterion uses the effective number of samples N/τ, τ the correlation time of the residual
of all the round's candidates together (:func:`_round_tau`),
ΔBIC = (N/τ)·ln(RSS_before/RSS_after) − Δk·ln(N/τ), and must exceed BIC_MIN. The candidate
must also predict data it was not fitted to: the 5-fold cross-validated mean-square error
(folds of contiguous chunks, so correlated neighbours are held out together) must fall by
CV_GAIN_MIN, and the variance it explains must be at least EXPLAINED_MIN of the noise
variance (an effect far below the noise is not worth naming).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares, lsq_linear

from ..catalog import Catalog
from ..models import GearModel
from . import baseline as baselines
from .units import check_units
from . import effects as fx
from .data import validate_data
from .noise import correlation_time, noise_rms

# Kass & Raftery (1995), J. Am. Stat. Assoc. 90: ΔBIC > 10 is "very strong" evidence.
BIC_MIN = 10.0
# Cross-validated mean-square error must fall by 5 %: a real effect of 1× the noise RMS cuts
# it by ~50 %; spurious fits to coloured noise do not carry over to held-out chunks.
CV_GAIN_MIN = 0.05
# Variance explained by an accepted effect, in units of the noise variance (0.1 ≙ an effect
# RMS of 0.32× the noise RMS): below this an effect changes no engineering conclusion.
EXPLAINED_MIN = 0.1
GATE_NOTE = (f"an effect is added when ΔBIC > {BIC_MIN:g} (effective sample size N/τ), the "
             f"5-fold cross-validated error falls by ≥ {CV_GAIN_MIN:.0%} and it explains ≥ "
             f"{EXPLAINED_MIN:g}× the noise variance")
MAX_EFFECTS = 3          # the issue asks for a second effect; a third is allowed, no more
CV_FOLDS = 5
CV_CHUNKS = 25           # 5 contiguous chunks per fold, spread over the record
# Above this many rows the fit uses this many rows drawn at random (fixed seed; time order
# kept, torque turning points added) — even steps could alias an efficiency grid sweep;
# the final prediction and the RMSE use every row.
MAX_FIT_ROWS = 5_000
GRID_POINTS = 6
REGRID_POINTS = 4        # coarser grid when earlier effects are searched again
# Significance of a region or a harmonic: z-score against the noise, and a floor relative
# to the noise so that negligible structure is not reported.
REGION_Z = 4.0
REGION_RMS_MIN = 1.2     # region RMS / noise RMS
HARMONIC_Z = 5.0
HARMONIC_RMS_MIN = 0.3   # harmonic RMS / noise RMS
HARMONIC_ORDERS = range(1, 7)


# --------------------------------------------------------------------------- problem
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
    cache: dict = field(default_factory=dict)

    @property
    def y(self) -> np.ndarray:
        return self.base.y[self.rows] - self.base.fixed[self.rows]


@dataclass
class Fit:
    effects: tuple[str, ...]
    theta: dict[str, float]
    beta: np.ndarray
    labels: list[tuple[str, str]]   # (effect or 'baseline', linear parameter name)
    prediction: np.ndarray          # on every row
    rss: float                      # on the fit rows
    n_params: int
    cv_mse: float = math.nan
    columns: np.ndarray | None = None   # design matrix on the fit rows


# Catalog figures that scale effect bounds, and the kinds whose effects use them.
FIGURE_KINDS = {"hysteresis_rad": ("torsion",), "backlash_rad": ("torsion",),
                "accuracy_rad": ("transmission", "vibration")}


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
    return scales


def _problem(kind: str, base: baselines.Baseline) -> Problem:
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
    chunk = np.minimum((np.arange(len(rows)) * CV_CHUNKS) // len(rows), CV_CHUNKS - 1)
    notes = list(base.notes)
    problem = Problem(kind, base, _scales(base, notes), rows, chunk % CV_FOLDS, notes)
    problem.branches = branches
    if branches is not None:
        problem.fit_branches = (np.searchsorted(rows, branches[0]), branches[1])
    return problem


# --------------------------------------------------------------------------- columns
def _key(effect: str, param: str) -> str:
    return "damping_ratio" if param == "damping_ratio" else f"{effect}.{param}"


def _nonlinear(kind: str, effects: tuple[str, ...]) -> dict[str, fx.Parameter]:
    out: dict[str, fx.Parameter] = {}
    for name in effects:
        for p in fx.nonlinear_parameters(name, kind):
            out.setdefault(_key(name, p.name), p)
    return out


def _harmonic(problem: Problem, order: int, zeta: float | None, full: bool = True
              ) -> np.ndarray:
    """sin/cos of k·φ, or the joint's response to them (vibration), on every row (``full``)
    or on the fitted rows."""
    key = (order, zeta, full)
    if key not in problem.cache:
        inp = problem.base.inputs
        if zeta is not None:  # the joint's response needs the whole time history
            phi = inp["wg_angle_rad"]
            cols = np.column_stack([
                fx.joint_response(inp["time_s"], c, float(inp["K_Nm_per_rad"]),
                                  float(inp["J_kgm2"]), zeta)
                for c in (np.sin(order * phi), np.cos(order * phi))])
            cols = cols if full else cols[problem.rows]
        else:
            phi = inp["wg_angle_rad"] if full else inp["wg_angle_rad"][problem.rows]
            cols = np.column_stack([np.sin(order * phi), np.cos(order * phi)])
        if len(problem.cache) > 64:
            problem.cache.clear()
        problem.cache[key] = cols
    return problem.cache[key]


def _columns(problem: Problem, effects: tuple[str, ...], theta: dict[str, float],
             full: bool = False):
    """Design matrix, labels and linear bounds for a model with ``effects``, on every row
    (``full``) or on the fitted rows."""
    base = problem.base
    pick = (lambda a: a) if full else (lambda a: a[problem.rows])
    inp = {k: pick(v) for k, v in base.inputs.items() if np.ndim(v) == 1}
    branches = problem.branches if full else problem.fit_branches
    n = len(base.y) if full else len(problem.rows)
    cols = [pick(base.free)]
    labels = [("baseline", n_) for n_ in base.free_names]
    lower, upper = [-np.inf] * len(labels), [np.inf] * len(labels)

    def add(effect: str, names, block, lo=-np.inf, hi=np.inf):
        cols.append(block.reshape(n, -1))
        labels.extend((effect, n_) for n_ in names)
        lower.extend([lo] * len(names))
        upper.extend([hi] * len(names))

    factor = None
    for name in effects:
        th = {p.name: theta[_key(name, p.name)]
              for p in fx.nonlinear_parameters(name, problem.kind)}
        if name == "hysteresis":
            z = fx.hysteresis_state(inp["torque_Nm"], th["T_s"], th["rho"], th["n"], branches,
                                    th["z0"], th["first_scale"])
            add(name, ["z_sat"], -z, 0.0)
        elif name == "backlash":
            add(name, ["lost_motion"], fx.backlash_twist(inp["torque_Nm"], 1.0, th["T_w"]), 0.0)
        elif name == "housing_compliance":
            add(name, ["compliance"], inp["torque_Nm"], 0.0)
        elif name in ("te_1x", "te_2x"):
            add(name, ["sin", "cos"], _harmonic(problem, int(name[3]), th.get("damping_ratio"),
                                                full))
        elif name == "low_load_efficiency":
            f = fx.low_load_factor(inp["alpha"], th["c"], th["q"], inp["input_speed_rpm"],
                                   th["s"])
            factor = f if factor is None else factor * f
        elif name == "temperature_dependence":
            f = fx.temperature_factor(inp["temperature_C"], th["a"], th["b"],
                                      fx.REFERENCE_TEMPERATURE_C)
            factor = f if factor is None else factor * f
    X = np.column_stack(cols)
    if factor is not None:  # η = η0·Ke(α)·F(t): the effects scale the whole efficiency
        X = X * factor[:, None]
    return X, labels, np.array(lower), np.array(upper)


def _solve(X: np.ndarray, y: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Linear least squares with bounds, on columns scaled to unit RMS."""
    norm = np.sqrt(np.mean(X * X, axis=0))
    norm[norm == 0] = 1.0
    Xs = X / norm
    beta = np.linalg.lstsq(Xs, y, rcond=None)[0]
    lo, hi = lower * norm, upper * norm
    if np.any(beta < lo) or np.any(beta > hi):
        beta = lsq_linear(Xs, y, bounds=(lo, hi), method="bvls").x
    return beta / norm


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
    Xf, labels, lo, hi = _columns(problem, effects, theta)
    beta = _solve(Xf, problem.y, lo, hi)
    return Xf, beta, labels, lo, hi


def fit_model(problem: Problem, effects: tuple[str, ...],
              start: dict[str, float] | None = None) -> Fit:
    """Fit ``effects`` on top of the baseline; ``start`` holds known nonlinear values."""
    params = _nonlinear(problem.kind, effects)
    keys = list(params)
    scale = {k: problem.scales[params[k].scale] for k in keys}
    theta = dict(start or {})
    new = [k for k in keys if k not in theta]
    for k in keys:
        start_value = params[k].start
        theta.setdefault(k, float(_grid(params[k], scale[k])[GRID_POINTS // 2])
                         if start_value is None else start_value * scale[k])
    searched = [k for k in new if params[k].start is None]

    def rss_of(th):
        Xf, beta, *_ = _evaluate(problem, effects, th)
        r = problem.y - Xf @ beta
        return float(r @ r)

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
    old = [k for k in keys if k not in new]
    if new and old:
        # the earlier effects' shapes were fitted without the new one and may have bent to
        # mimic it: search them again with the new effect in place and keep the better fit
        old_searched = [k for k in old if params[k].start is None]
        again = _polish(problem, effects, grid_search(theta, old_searched, REGRID_POINTS)
                        if old_searched else theta, keys, params, scale)
        if rss_of(again) < rss_of(theta):
            theta = again
    Xf, beta, labels, lo, hi = _evaluate(problem, effects, theta)
    r = problem.y - Xf @ beta
    X = _columns(problem, effects, theta, full=True)[0]
    fit = Fit(effects, theta, beta, labels, problem.base.fixed + X @ beta, float(r @ r),
              len(beta) + len(keys), columns=Xf)
    fit.cv_mse = _cv_mse(Xf, problem.y, lo, hi, problem.folds)
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

    def residual(x):
        Xf, beta, *_ = _evaluate(problem, effects, from_x(x))
        return problem.y - Xf @ beta

    x0 = np.clip(to_x(theta), lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo))
    result = least_squares(residual, x0, bounds=(lo, hi), x_scale=np.maximum(hi - lo, 1e-9),
                           diff_step=1e-4, max_nfev=40 * len(keys))
    return from_x(result.x)


def _cv_mse(Xf, y, lo, hi, folds) -> float:
    """5-fold cross-validated mean-square error (shape parameters held)."""
    err = 0.0
    for k in range(CV_FOLDS):
        test = folds == k
        beta = _solve(Xf[~test], y[~test], lo, hi)
        r = y[test] - Xf[test] @ beta
        err += float(r @ r)
    return err / len(y)


# --------------------------------------------------------------------------- regions
def _regions(problem: Problem) -> list[tuple[str, np.ndarray]]:
    """(label, mask) of the operating-range bins where residuals are compared with noise."""
    inp, kind = problem.base.inputs, problem.kind
    if kind == "torsion":
        torque = inp["torque_Nm"]
        direction = _directions(problem)
        loading = direction * np.sign(torque) > 0
        out = []
        for lo, hi, mask in _bins(torque, 6):
            for name, m in (("loading", loading), ("unloading", ~loading)):
                out.append((f"torque {lo:.4g}…{hi:.4g} N·m, {name}", mask & m))
        return out
    if kind == "efficiency":
        out = []
        for col, label, unit in (("input_speed_rpm", "input speed", "r/min"),
                                 ("alpha", "load ratio α", ""),
                                 ("temperature_C", "temperature", "°C")):
            for lo, hi, mask in _bins(inp[col], 4):
                span = f"{lo:.4g}" if lo == hi else f"{lo:.4g}…{hi:.4g}"
                out.append((f"{label} {span} {unit}".rstrip(), mask))
        return out
    if kind == "vibration":
        return [(f"input speed {lo:.4g}…{hi:.4g} r/min", mask)
                for lo, hi, mask in _bins(inp["input_speed_rpm"], 8)]
    return []  # transmission: the harmonics of the WG angle are its regions (_harmonics)


def _directions(problem: Problem) -> np.ndarray:
    starts, first = problem.branches
    direction = np.empty(len(problem.base.y))
    bounds = list(starts) + [len(direction)]
    d = first
    for s, e in zip(bounds[:-1], bounds[1:]):
        direction[s:e] = d
        d = -d
    return direction


def _bins(x: np.ndarray, count: int):
    """(low, high, mask): the distinct values when there are few, else equal-width bins."""
    values = np.unique(x)
    if len(values) <= count:
        return [(v, v, x == v) for v in values]
    edges = np.linspace(x.min(), x.max(), count + 1)
    index = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, count - 1)
    return [(edges[i], edges[i + 1], index == i) for i in range(count)]


def _region_table(problem, before, after, sigma, tau):
    """Rows (label, rms before, rms after, significant) for every region."""
    rows = []
    for label, mask in _regions(problem):
        n = int(mask.sum())
        if n < 10:
            continue
        ms = float(np.mean(before[mask] ** 2))
        dof = max(n / tau, 1.0)
        z = (ms / sigma ** 2 - 1.0) / math.sqrt(2.0 / dof)
        rms = math.sqrt(ms)
        rows.append((label, rms, math.sqrt(float(np.mean(after[mask] ** 2))),
                     z > REGION_Z and rms > REGION_RMS_MIN * sigma))
    return rows


def _harmonics(problem, residual, sigma, tau, zeta=None):
    """(order, rms, significant) of the residual at k cycles per WG revolution."""
    out = []
    if "wg_angle_rad" not in problem.base.inputs:
        return out
    rows = problem.rows
    n_eff = max(len(rows) / tau, 3.0)
    for k in HARMONIC_ORDERS:
        X = np.column_stack([np.ones(len(rows)), _harmonic(problem, k, zeta, full=False)])
        beta = np.linalg.lstsq(X, residual[rows], rcond=None)[0]
        part = X[:, 1:] @ beta[1:]
        rms = float(np.sqrt(np.mean(part ** 2)))
        # each of the sin/cos coefficients has a standard error ≈ σ·√(2/N_eff) when the
        # basis is balanced, so the harmonic's RMS has an error ≈ σ/√N_eff
        z = rms / (sigma / math.sqrt(n_eff))
        out.append((k, rms, z > HARMONIC_Z and rms > HARMONIC_RMS_MIN * sigma))
    return out


# --------------------------------------------------------------------------- result
@dataclass
class Step:
    """One accepted effect: its parameters in the final model, the ΔBIC and CV gain when it
    was added and the RMSE [unit of the data] after adding it."""

    effect: str
    params: dict[str, dict]
    criterion_gain: float
    cv_gain: float
    rmse: float


@dataclass
class Reconciliation:
    """Result of :func:`reconcile`; ``as_dict()`` is the JSON of ``hdcad reconcile``."""

    kind: str
    model: str
    disagreements: list[dict]
    missing_effects: list[str]
    rmse_before: float
    rmse_after: float
    steps: list[Step]
    unexplained: list[str]
    noise_rms: float = math.nan
    unit: str = "rad"
    baseline_params: dict[str, dict] = field(default_factory=dict)
    regions: list[dict] = field(default_factory=list)
    candidates: list[list[dict]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    series: dict[str, np.ndarray] = field(default_factory=dict, repr=False)

    def as_dict(self) -> dict:
        return {"kind": self.kind, "model": self.model, "disagreements": self.disagreements,
                "missing_effects": list(self.missing_effects),
                "rmse_before": self.rmse_before, "rmse_after": self.rmse_after,
                "steps": [{"effect": s.effect, "params": s.params,
                           "criterion_gain": s.criterion_gain, "rmse": s.rmse}
                          for s in self.steps],
                "unexplained": list(self.unexplained)}


def _rmse(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x * x)))


def _round_tau(problem: Problem, fits: list[Fit]) -> float:
    """Correlation time [fitted rows] of the noise for one round of candidates.

    Taken from the residual of all this round's candidates together (their columns at their
    own fitted shapes, one linear least squares): the residual of a single candidate still
    holds the effects it lacks, whose slow structure would pass for strongly coloured noise
    and deflate every candidate's evidence alike (the issue's pair te_1x + te_2x).
    """
    X = np.column_stack([f.columns for f in fits])
    beta = np.linalg.lstsq(X, problem.y, rcond=None)[0]
    return correlation_time(problem.y - X @ beta)


def _gains(problem: Problem, current: Fit, candidate: Fit, sigma: float,
           tau: float) -> tuple[float, float, float]:
    """(ΔBIC with the effective sample size N/τ, relative CV gain, explained variance / σ²)."""
    n = len(problem.rows)
    n_eff = n / tau
    dk = candidate.n_params - current.n_params
    ratio = current.rss / max(candidate.rss, 1e-300)
    bic = n_eff * math.log(ratio) - dk * math.log(n_eff)
    cv = (current.cv_mse - candidate.cv_mse) / current.cv_mse if current.cv_mse > 0 else 0.0
    explained = (current.rss - candidate.rss) / n / sigma ** 2
    return bic, cv, explained


def _params(problem: Problem, fit: Fit, effect: str) -> dict[str, dict]:
    """The effect's parameters with units (amplitudes, shapes and derived figures)."""
    b = {name: v for (e, name), v in zip(fit.labels, fit.beta) if e == effect}
    th = {p.name: fit.theta[_key(effect, p.name)]
          for p in fx.nonlinear_parameters(effect, problem.kind)}
    out: dict[str, tuple[float, str]] = {}
    if effect == "hysteresis":
        t0 = problem.scales["T0"]
        out = {"z_sat": (b["z_sat"], "rad"), "T_s": (th["T_s"], "N·m"), "rho": (th["rho"], "-"),
               "n": (th["n"], "-"), "z0": (th["z0"], "-"),
               "first_scale": (th["first_scale"], "-"),
               "loss_at_T0": (fx.hysteresis_loss(b["z_sat"], th["T_s"], th["rho"], th["n"], t0),
                              "rad"),
               "T0": (t0, "N·m")}
    elif effect == "backlash":
        out = {"lost_motion": (b["lost_motion"], "rad"), "T_w": (th["T_w"], "N·m")}
    elif effect == "housing_compliance":
        c = b["compliance"]
        out = {"K_h": (1.0 / c if c > 0 else math.inf, "N·m/rad"), "compliance": (c, "rad/(N·m)")}
    elif effect in ("te_1x", "te_2x"):
        out = {"amplitude": (math.hypot(b["sin"], b["cos"]), "rad"),
               "phase": (math.atan2(b["cos"], b["sin"]), "rad")}
        if "damping_ratio" in th:
            out["damping_ratio"] = (th["damping_ratio"], "-")
    elif effect == "low_load_efficiency":
        out = {"c": (th["c"], "-"), "q": (th["q"], "-"), "s": (th["s"], "-"),
               "Ke_at_alpha_0.58_1000rpm": (
                   float(fx.low_load_factor(np.array(0.58), th["c"], th["q"])), "-")}
    elif effect == "temperature_dependence":
        out = {"a": (th["a"], "-"), "b": (th["b"], "1/K"),
               "t_ref": (fx.REFERENCE_TEMPERATURE_C, "°C")}
    return {k: {"value": float(v), "unit": u} for k, (v, u) in out.items()}


def reconcile(kind: str, data: dict, model: GearModel, catalog: Catalog,
              load_inertia_kgm2: float | None = None) -> Reconciliation:
    """Find, name and add the effects the catalog model misses."""
    data = validate_data(kind, data)
    base = baselines.build(kind, data, model, catalog, load_inertia_kgm2)
    check_units(kind, base)
    problem = _problem(kind, base)
    # 1. baseline with its free parameters, residual, noise from the data itself
    current = fit_model(problem, ())
    resid0 = base.y - current.prediction
    steps, candidates = [], []
    # 3-4. candidates on top of the accepted effects, best first, until none passes
    while len(current.effects) < MAX_EFFECTS:
        sigma = noise_rms(base.y - current.prediction) or _rmse(resid0)
        names = [n for n in fx.applicable(kind) if n not in current.effects]
        fits = [fit_model(problem, current.effects + (n,), current.theta) for n in names]
        tau = _round_tau(problem, fits) if fits else 1.0
        round_ = []
        for name, fit in zip(names, fits):
            bic, cv, explained = _gains(problem, current, fit, sigma, tau)
            ok = bic > BIC_MIN and cv > CV_GAIN_MIN and explained > EXPLAINED_MIN
            round_.append({"effect": name, "delta_bic": bic, "cv_gain": cv,
                           "explained_var_over_noise": explained, "accepted": False,
                           "fit": fit, "passes": ok})
        candidates.append(round_)
        passing = [c for c in round_ if c["passes"]]
        if not passing:
            break
        best = max(passing, key=lambda c: c["delta_bic"])
        best["accepted"] = True
        current = best["fit"]
        steps.append(Step(best["effect"], _params(problem, current, best["effect"]),
                          best["delta_bic"], best["cv_gain"],
                          _rmse(base.y - current.prediction)))
    # parameters as in the final model: a later effect refits the earlier effects' shapes
    for step in steps:
        step.params = _params(problem, current, step.effect)
    final = base.y - current.prediction
    sigma = noise_rms(final) or _rmse(final)
    tau = correlation_time(final)
    # 2 and 5: where the baseline disagrees, and what is left after the accepted effects
    table = _region_table(problem, resid0, final, sigma, tau)
    zeta = current.theta.get("damping_ratio", 0.05 if kind == "vibration" else None)
    harm0 = _harmonics(problem, resid0, sigma, tau, zeta)
    harm1 = _harmonics(problem, final, sigma, tau, zeta)
    disagreements = [{"where": label, "rms": rms, "noise_rms": sigma}
                     for label, rms, _, sig in table if sig]
    disagreements += [{"where": f"{k} cycle(s) per WG revolution", "rms": rms,
                       "noise_rms": sigma} for k, rms, sig in harm0 if sig]
    unexplained = _unexplained(problem, final, sigma, tau, harm1, current)
    after = {label: sig for label, _, _, sig in _region_table(problem, final, final, sigma, tau)}
    regions = [{"where": label, "rms_before": b, "rms_after": a, "significant": s,
                "significant_after": after.get(label, False)} for label, b, a, s in table]
    regions += [{"where": f"{k} cycle(s) per WG revolution", "rms_before": r0,
                 "rms_after": r1, "significant": s0, "significant_after": s1}
                for (k, r0, s0), (_, r1, s1) in zip(harm0, harm1)]
    return Reconciliation(
        kind=kind, model=model.code, disagreements=disagreements,
        missing_effects=[s.effect for s in steps], rmse_before=_rmse(resid0),
        rmse_after=_rmse(final), steps=steps, unexplained=unexplained, noise_rms=sigma,
        unit=base.unit,
        baseline_params={n: {"value": float(v), "unit": u} for n, v, u in
                         zip(base.free_names, current.beta, base.free_units)},
        regions=regions,
        candidates=[[{k: v for k, v in c.items() if k != "fit"} for c in r]
                    for r in candidates],
        notes=problem.notes + [GATE_NOTE],
        series={**{k: v for k, v in base.inputs.items() if np.ndim(v) == 1},
                "measured": base.y, "catalog": base.fixed, "baseline": base.y - resid0,
                "reconciled": current.prediction})


def _unexplained(problem, final, sigma, tau, harmonics, fit) -> list[str]:
    """Significant structure left in the residual after the accepted effects."""
    out = []
    explained_orders = {int(e[3]) for e in fit.effects if e.startswith("te_")}
    for k, rms, sig in harmonics:
        if sig and k not in explained_orders:
            out.append(f"residual at {k} cycle(s) per WG revolution (RMS {rms:.3g} "
                       f"{problem.base.unit}), unexplained")
    for label, rms, _, sig in _region_table(problem, final, final, sigma, tau):
        if sig:
            out.append(f"residual in {label} (RMS {rms:.3g} {problem.base.unit}, noise "
                       f"{sigma:.3g}), unexplained")
    return out
