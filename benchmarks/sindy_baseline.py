"""Plain sparse regression as a side-by-side baseline for `hdcad reconcile`: PySINDy's STLSQ
over the same residual library.

For each data set: the catalog baseline with its nuisances is fitted exactly as reconcile
starts (units fixed, outliers left out); its residual r is regressed on a library Θ holding
every gear effect of the kind as reconcile builds its columns, each at the middle of its
shape-parameter range (STLSQ is linear: it cannot fit shapes). Columns are scaled to unit RMS
and r to units of its noise RMS σ, so a coefficient is the effect's RMS in σ. STLSQ (Brunton,
Proctor & Kutz 2016, PNAS 113(15)) keeps the terms above ``THRESHOLD``; an effect is named
when any of its columns survives, ordered by its RMS contribution.

THRESHOLD = 1σ (a column must carry at least the noise RMS) is fixed a priori: a first try
with 1.5σ split harmonic effects (sin and cos columns, each below 1.5σ) and named nothing on
half of the transmission cases of suite B; 1σ is the usual noise-level threshold of SINDy. It
was not tuned further on any suite.
"""

from __future__ import annotations

import warnings

import numpy as np

THRESHOLD = 1.0      # column RMS contribution in units of the noise RMS
RIDGE = 0.05         # STLSQ's ridge term α on the unit-RMS columns
MULTIPLICATIVE = ("low_load_efficiency", "temperature_dependence")


def _rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _middle_theta(fitting, kind: str, effect: str, problem, start) -> dict:
    from hdcad.reconcile.model_columns import nonlinear
    params = nonlinear(kind, (effect,))
    theta = dict(start.theta)
    for key, p in params.items():
        if key in theta:
            continue
        scale = problem.scales[p.scale]
        theta[key] = (p.start * scale if p.start is not None
                      else float(fitting._grid(p, scale)[fitting.GRID_POINTS // 2]))
    return theta


def library(problem, start) -> tuple[np.ndarray, list[str]]:
    """Θ on the fit rows and the effect owning each column."""
    from hdcad.reconcile import effects as fx
    from hdcad.reconcile import fitting
    from hdcad.reconcile.model_columns import columns
    kind, blocks, owners = problem.kind, [], []
    base_pred = start.columns @ start.beta
    for name in fx.applicable(kind):
        theta = _middle_theta(fitting, kind, name, problem, start)
        X, labels, _, _ = columns(problem, (name,), theta)
        if name in MULTIPLICATIVE:  # η0·F − η0: the factor's change of the baseline
            n_base = sum(1 for lab in labels if lab[0] == "baseline")
            cols = (X[:, :n_base] @ start.beta[:n_base] - base_pred)[:, None]
        else:
            cols = X[:, [i for i, lab in enumerate(labels) if lab[0] == name]]
        blocks.append(cols)
        owners += [name] * cols.shape[1]
    return np.column_stack(blocks), owners


def sindy_case(case) -> dict:
    """Effects named by STLSQ on one truth case, with RMSE before and after (result-shaped
    like reconcile's JSON so that the benchmark's scorer reads both)."""
    from pysindy.optimizers import STLSQ

    from hdcad.catalog import load_catalog
    from hdcad.models import resolve
    from hdcad.reconcile import fitting, validate_data, workflow
    from hdcad.reconcile.noise import noise_rms
    catalog = load_catalog()
    try:
        data = validate_data(case.kind, case.columns)
        base, _ = workflow._baseline(case.kind, data, resolve(case.model, catalog), catalog,
                                     case.load_inertia_kgm2)
        problem = fitting.make_problem(case.kind, base)
        start = workflow._start(problem)
    except Exception as exc:
        return {"error": f"{type(exc).__name__}: {exc}", "missing_effects": [],
                "rmse_before": np.nan, "rmse_after": np.nan}
    r = problem.y - start.columns @ start.beta
    sigma = noise_rms(r) or _rms(r) or 1.0
    theta, owners = library(problem, start)
    norm = np.sqrt(np.mean(theta * theta, axis=0))
    norm[norm == 0] = 1.0
    opt = STLSQ(threshold=THRESHOLD, alpha=RIDGE, max_iter=20)
    with warnings.catch_warnings():  # "eliminated all coefficients" is an answer here
        warnings.simplefilter("ignore")
        opt.fit(theta / norm, r / sigma)
    coef = np.ravel(opt.coef_)
    fitted = (theta / norm) @ coef * sigma
    share = {}
    for name in dict.fromkeys(owners):
        cols = [i for i, o in enumerate(owners) if o == name]
        if np.any(coef[cols] != 0):
            share[name] = _rms((theta[:, cols] / norm[cols]) @ coef[cols])
    named = sorted(share, key=share.get, reverse=True)
    return {"missing_effects": named, "rmse_before": _rms(r), "rmse_after": _rms(r - fitted),
            "measurement_effects": [], "equivalent_readings": [], "error": None}
