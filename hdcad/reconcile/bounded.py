"""Linear least squares with bounds on a few of its parameters, the inner solve of every fit.

A fit's shape search solves min ‖X·b − y‖² with lo ≤ b ≤ hi thousands of times for a
design matrix of a few columns (the catalog curve's scale and offset, the effects'
amplitudes), most of them with a bound in force (the stiffness scale within the catalog's
spread, a loop's or play's amplitude at zero). The rows are folded into the columns'
triangular factor once (X = QR: ‖Xb − y‖² = ‖Rb − Qᵀy‖² + const, R and Qᵀy read from the
factor of [X y]) and the bounded problem is solved on p × p by the active-set method of
Stark and Parker, written here in a few lines because scipy's general
``lsq_linear(method="bvls")`` spends most of its time in per-call overhead at this size.
The objective is strictly convex when R has full rank, so the solution (the point that
satisfies the Karush–Kuhn–Tucker conditions) is unique; a rank-deficient R, or a problem
the method does not settle in ``MAX_ROUNDS``, goes to scipy's solver.

References
----------
Lawson, C. L.; Hanson, R. J. (1974) Solving Least Squares Problems, Prentice-Hall, ch. 23
(the active-set method for non-negative least squares).
Stark, P. B.; Parker, R. L. (1995) "Bounded-variable least-squares: an algorithm and
applications", Computational Statistics 10: 129-141.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_triangular
from scipy.optimize import lsq_linear

# diagonal of R below this share of its largest: a column is (nearly) a combination of the
# others, and the triangular solve would not be the least-squares solution
RANK_TOLERANCE = 1e-10
MAX_ROUNDS = 50
# a bound's multiplier of this share of the largest of Rᵀc is zero (rounding): releasing the
# parameter would only bring it back
KKT_TOLERANCE = 1e-12


def solve(X: np.ndarray, y: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """b minimising ‖X·b − y‖² with ``lower`` ≤ b ≤ ``upper`` (±inf where unbounded), on
    columns scaled to unit RMS."""
    norm = column_rms(X)
    Xs = X / norm
    lo, hi = lower * norm, upper * norm
    p = Xs.shape[1]
    # the factor of [X y]: its first p columns are R and Qᵀy, without forming Q
    Ry = np.linalg.qr(np.column_stack([Xs, y]), mode="r")
    R, c = Ry[:p, :p], Ry[:p, p]
    if p and R.shape[0] == p and full_rank(R):
        beta = _active_set(R, c, lo, hi)
        if beta is not None:  # clipped: a bound scaled and back can be a rounding off
            return np.clip(beta / norm, lower, upper)
    beta = np.linalg.lstsq(Xs, y, rcond=None)[0]
    if np.any(beta < lo) or np.any(beta > hi):
        beta = lsq_linear(R, c, bounds=(lo, hi), method="bvls").x
    return np.clip(beta / norm, lower, upper)


def column_rms(X: np.ndarray) -> np.ndarray:
    """RMS of each column, 1 for a column of zeros (the scale the columns are solved at)."""
    norm = np.sqrt(np.einsum("ij,ij->j", X, X) / max(len(X), 1))
    norm[norm == 0] = 1.0
    return norm


def full_rank(R: np.ndarray) -> bool:
    """The triangular factor's columns are independent: no diagonal element below
    ``RANK_TOLERANCE`` of the largest (an empty factor has none to depend)."""
    diagonal = np.abs(np.diag(R))
    return not diagonal.size or diagonal.min() > RANK_TOLERANCE * diagonal.max()


def _active_set(R: np.ndarray, c: np.ndarray, lo: np.ndarray, hi: np.ndarray
                ) -> np.ndarray | None:
    """The bounded solution of ‖R·b − c‖² (R square, upper triangular, full rank), or None
    when it is not settled in ``MAX_ROUNDS`` rounds."""
    b = solve_triangular(R, c, check_finite=False)
    side = np.where(b <= lo, -1, np.where(b >= hi, 1, 0))  # at the lower, upper bound, free
    if not side.any():
        return b
    b = np.clip(b, lo, hi)
    tol = KKT_TOLERANCE * float(np.abs(R.T @ c).max())
    for _ in range(MAX_ROUNDS):
        free, held = side == 0, side != 0
        z = b.copy()
        if free.any():
            z[free] = np.linalg.lstsq(R[:, free], c - R[:, held] @ b[held], rcond=None)[0]
        outside = free & ((z < lo) | (z > hi))
        if outside.any():  # step from b towards z as far as the first bound it meets
            step = z - b
            with np.errstate(divide="ignore", invalid="ignore"):
                share = np.where(outside, np.where(step < 0, lo - b, hi - b) / step, np.inf)
            alpha = float(np.clip(share.min(), 0.0, 1.0))
            hit = outside & (share <= alpha)
            b = np.clip(b + alpha * step, lo, hi)
            side[hit] = np.where(step[hit] < 0, -1, 1)
            b[hit] = np.where(step[hit] < 0, lo[hit], hi[hit])
            continue
        b = z
        pull = R.T @ (c - R @ b)  # the descent direction of each parameter
        wrong = ((side < 0) & (pull > tol)) | ((side > 0) & (pull < -tol))
        if not wrong.any():
            return b
        side[np.argmax(np.where(wrong, np.abs(pull), -1.0))] = 0
    return None
