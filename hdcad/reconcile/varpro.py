"""Variable projection: the Jacobian of a residual whose amplitudes are solved, not fitted.

Every fit's shape search minimises ‖y − X(θ)·β(θ)‖² over the shapes θ with the amplitudes β
the bounded linear least-squares solution on X's columns (:mod:`.bounded`). Differencing the
whole residual costs a bounded solve per shape and step; differentiating the projection
costs one factorisation per Jacobian, with only the columns differenced. With the amplitudes
at a bound held, r = P⊥·(y − X_H·β_H) on the free columns X_F and

    ∂r = −P⊥·∂X·β − (X_F⁺)ᵀ·∂X_Fᵀ·r,

the exact derivative of the projected residual (Golub and Pereyra), the same that a forward
difference of it approximates.

References
----------
Golub, G. H.; Pereyra, V. (1973) "The differentiation of pseudo-inverses and nonlinear least
squares problems whose variables separate", SIAM J. Numer. Anal. 10(2): 413-432.
Golub, G.; Pereyra, V. (2003) "Separable nonlinear least squares: the variable projection
method and its applications", Inverse Problems 19: R1-R26.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_triangular

from .bounded import column_rms, full_rank

# step of the shapes' forward differences, relative to max(1, |x|) (x a shape or its
# logarithm), as least_squares' diff_step
DIFF_STEP = 1e-4
# an amplitude this close to a bound, relative to the bound, is held at it
BOUND_SHARE = 1e-9


def steps(x: np.ndarray, lo: np.ndarray, hi: np.ndarray):
    """(x + h·e_k, h) for each k: forward steps of DIFF_STEP relative to max(1, |x_k|),
    backward where the bound is nearer (least_squares' 2-point rule)."""
    for k in range(len(x)):
        h = DIFF_STEP * (1.0 if x[k] >= 0 else -1.0) * max(1.0, abs(x[k]))
        if not lo[k] <= x[k] + h <= hi[k]:
            h = -h
        xk = x.copy()
        xk[k] += h
        yield xk, xk[k] - x[k]


def free_amplitudes(beta: np.ndarray, lower, upper) -> np.ndarray:
    """Mask of the amplitudes not at a bound (the bounded solve returns a held amplitude
    within rounding of its bound, the bound having been scaled with the column)."""
    def at(bound):
        bound = np.asarray(bound, float)
        return np.isfinite(bound) & (np.abs(beta - bound) <= BOUND_SHARE * np.abs(bound))
    return ~(at(lower) | at(upper))


def projected_jacobian(y: np.ndarray, model: dict, x: np.ndarray, lo: np.ndarray,
                       hi: np.ndarray, columns_at) -> np.ndarray | None:
    """∂r/∂x of r = y − X(x)·β(x), β the bounded least-squares amplitudes on X's columns,
    those at a bound held: r = P⊥(y − X_H·β_H) on the free columns X_F, so
    ∂r = −P⊥·∂X·β − (X_F⁺)ᵀ·∂X_Fᵀ·r (variable projection). The columns' derivatives are
    forward differences (:func:`steps`); the amplitudes' response is exact, which spares a
    bounded solve per step. None when the free columns are (nearly) collinear."""
    Xf, beta, free = model["Xf"], model["beta"], model["free"]
    r = y - Xf @ beta
    norm = column_rms(Xf[:, free])
    Q, R = np.linalg.qr(Xf[:, free] / norm)
    if not full_rank(R):
        return None
    J = np.empty((len(y), len(x)))
    for k, (xk, h) in enumerate(steps(x, lo, hi)):
        dX = columns_at(xk)
        if dX.shape != Xf.shape:
            return None
        dX = (dX - Xf) / h
        d = dX @ beta
        J[:, k] = -(d - Q @ (Q.T @ d))
        if free.any():
            J[:, k] -= Q @ solve_triangular(R, (dX[:, free].T @ r) / norm, trans="T")
    return J
