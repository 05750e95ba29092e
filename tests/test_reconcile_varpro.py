"""The shape fits' Jacobian by variable projection (``hdcad.reconcile.varpro``) against
forward differences of the whole residual, the bounded amplitudes solved again at every
step (what least_squares' 2-point rule computed before): the same derivative, free
amplitudes and amplitudes held at a bound alike."""

from __future__ import annotations

import numpy as np
import pytest

from hdcad.reconcile.bounded import solve
from hdcad.reconcile.varpro import free_amplitudes, projected_jacobian, steps

T = np.linspace(0.0, 4.0, 400)


def columns(x):
    """Three columns with two shapes: a decay rate and a frequency, and a constant."""
    return np.column_stack([np.exp(-x[0] * T), np.sin(x[1] * T), np.ones_like(T)])


def model(x, y, lower, upper):
    X = columns(x)
    beta = solve(X, y, lower, upper)
    return {"Xf": X, "beta": beta, "free": free_amplitudes(beta, lower, upper)}


def residual(x, y, lower, upper):
    m = model(x, y, lower, upper)
    return y - m["Xf"] @ m["beta"]


# 1/1.1: a bound that the solve's column scaling returns a rounding off (a catalog stiffness
# scale held at the spread's end, which the Jacobian must hold too)
@pytest.mark.parametrize("upper_of_sine", [np.inf, 0.5, 1 / 1.1])
def test_projected_jacobian_is_the_residuals_derivative(upper_of_sine):
    rng = np.random.default_rng(3)
    y = 2.0 * np.exp(-0.7 * T) + 1.2 * np.sin(2.1 * T) + 0.3 + 0.01 * rng.normal(size=T.size)
    lower = np.array([-np.inf, 0.0, -np.inf])
    upper = np.array([np.inf, upper_of_sine, np.inf])
    x = np.array([0.8, 2.0])
    lo, hi = np.array([0.0, 0.0]), np.array([5.0, 5.0])
    m = model(x, y, lower, upper)
    assert m["free"].sum() == (3 if np.isinf(upper_of_sine) else 2)  # the sine held
    J = projected_jacobian(y, m, x, lo, hi, columns)
    # central differences of the whole residual, a step far below the forward one's error
    central = np.column_stack([
        (residual(x + e, y, lower, upper) - residual(x - e, y, lower, upper)) / (2 * e.sum())
        for e in np.eye(2) * 1e-6])
    scale = np.abs(central).max(axis=0)
    # forward steps of 1e-4 relative: the error is of order h·∂²r, a few 1e-4 of the slope
    assert np.abs(J - central).max(axis=0) / scale == pytest.approx([0, 0], abs=2e-3)
    forward = np.column_stack([(residual(xk, y, lower, upper) - residual(x, y, lower, upper))
                               / h for xk, h in steps(x, lo, hi)])
    assert np.abs(J - forward).max(axis=0) / scale == pytest.approx([0, 0], abs=2e-3)


def test_collinear_free_columns_are_left_to_differences():
    y = np.exp(-0.5 * T)
    def doubled(x):
        X = columns(x)
        return np.column_stack([X, 2.0 * X[:, 2]])
    X = doubled(np.array([0.5, 1.0]))
    m = {"Xf": X, "beta": np.zeros(4), "free": np.ones(4, bool)}
    assert projected_jacobian(y, m, np.array([0.5, 1.0]), np.zeros(2), np.full(2, 5.0),
                              doubled) is None
