"""The bounded linear least squares inside every fit (:mod:`hdcad.reconcile.bounded`).

The reference is scipy's ``lsq_linear`` (its own BVLS implementation, tolerance 1e-14) on
the same problems: random design matrices of 1–9 columns at scales 0.1–10, three in ten with
two nearly collinear columns (as the catalog curve's scale and its printed reading are),
about half the parameters bounded on one side or both. The objective is convex, so the
solutions agree where the minimum is unique; the objective is compared (to 1e-9 of it, a
thousand times the rounding of a sum of a few hundred squares) and the bounds must hold.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import lsq_linear

from hdcad.reconcile.bounded import solve


def _problem(rng):
    n, p = int(rng.integers(20, 300)), int(rng.integers(1, 10))
    X = rng.normal(size=(n, p)) * rng.uniform(0.1, 10.0, p)
    if p > 1 and rng.random() < 0.3:
        X[:, 1] = X[:, 0] + 1e-3 * rng.normal(size=n)
    y = 2.0 * X @ rng.normal(size=p) + rng.normal(size=n)
    lo = np.where(rng.random(p) < 0.5, rng.normal(size=p) - 0.5, -np.inf)
    hi = np.where(rng.random(p) < 0.5, np.maximum(lo, -1.0) + rng.uniform(0.01, 2.0, p), np.inf)
    return X, y, lo, hi


@pytest.mark.parametrize("seed", range(4))
def test_the_bounded_solution_is_scipy_s(seed):
    rng = np.random.default_rng(seed)
    for _ in range(500):
        X, y, lo, hi = _problem(rng)
        b = solve(X, y, lo, hi)
        ref = lsq_linear(X, y, bounds=(lo, hi), method="bvls", tol=1e-14).x
        assert np.all(b >= lo) and np.all(b <= hi)
        rss, rss_ref = np.sum((X @ b - y) ** 2), np.sum((X @ ref - y) ** 2)
        assert rss <= rss_ref * (1 + 1e-9)


def test_a_repeated_column_is_solved_by_the_general_solver():
    """Two equal columns: R is singular, the triangular solve is not the least-squares
    solution, and the general path gives the fit with the same residual as scipy's."""
    rng = np.random.default_rng(9)
    x = rng.normal(size=200)
    X = np.column_stack([x, x, np.ones(200)])
    y = 3.0 * x + 1.0 + 0.1 * rng.normal(size=200)
    lo, hi = np.array([0.0, 0.0, -np.inf]), np.array([1.0, np.inf, np.inf])
    b = solve(X, y, lo, hi)
    ref = lsq_linear(X, y, bounds=(lo, hi), method="bvls", tol=1e-14).x
    assert np.sum((X @ b - y) ** 2) == pytest.approx(np.sum((X @ ref - y) ** 2), rel=1e-9)
    assert b[0] + b[1] == pytest.approx(3.0, abs=0.05)
