"""Gross outliers of a residual in time order: found, left out of the fits and the RMSE,
and given back where the final model fits them."""

from __future__ import annotations

import numpy as np
from scipy.ndimage import median_filter

from .fitting import Fit, Problem, fit_model, set_rows
from .noise import noise_rms

# A sample further than this many noise RMS from the median of its neighbours is a gross
# outlier (a Gaussian sample does so with probability 2·10⁻⁹).
OUTLIER_SIGMA = 6.0
OUTLIER_WINDOW = 7
# Rows over which the spread of those departures is taken: a sample stands out only from
# residual that is quiet around it (a misfit that swings from row to row is no outlier).
SPREAD_WINDOW = 51
MAD_TO_SIGMA = 1.4826
# The residual swings where that spread is over this many noise RMS (white noise's departures
# from a 7-row median spread 0.82× its RMS, AR(1) noise's less); elsewhere a sample is
# tested against the noise RMS alone.
SWING_SPREAD = 2.0


def find_outliers(residual: np.ndarray) -> np.ndarray:
    """Indices of gross outliers of a residual in time order: samples further than
    ``OUTLIER_SIGMA`` times the noise RMS from the median of their ``OUTLIER_WINDOW``
    neighbours, and than as many times the spread of those departures over
    ``SPREAD_WINDOW`` rows over ``SWING_SPREAD`` (a Hampel filter's robust scale, floored
    at the noise). A misfit that swings faster than the median follows (a resonance's
    response not yet refined, a phase that wanders) departs from its neighbours over whole
    stretches; an isolated spike departs alone.

    References
    ----------
    Pearson, R. K. et al. (2016). Generalized Hampel filters. EURASIP J. Adv. Signal
    Process. 2016:87."""
    sigma = noise_rms(residual)
    if not sigma > 0:
        return np.zeros(0, dtype=int)
    local = residual - median_filter(residual, OUTLIER_WINDOW, mode="nearest")
    spread = MAD_TO_SIGMA * median_filter(np.abs(local), SPREAD_WINDOW, mode="nearest")
    scale = np.maximum(sigma, spread / SWING_SPREAD)
    return np.flatnonzero(np.abs(local) > OUTLIER_SIGMA * scale)


def set_aside(problem: Problem, found: np.ndarray, where: str) -> np.ndarray:
    """The gross outliers ``found`` (:func:`find_outliers` of a fit's residual) not yet left out,
    added to ``problem.outliers`` (left out of the RMSE) with a note saying they were,
    ``where``."""
    bad = np.setdiff1d(found, problem.outliers)
    if bad.size:
        problem.outliers = np.union1d(problem.outliers, bad)
        problem.notes.append(f"{bad.size} gross outlier(s) (> {OUTLIER_SIGMA:g}× the noise RMS "
                             f"from their neighbours) {where}")
    return bad


def without_outliers(problem: Problem, fit: Fit) -> Fit:
    """``fit`` again without the gross outliers of its residual not yet left out.

    Once on the baseline, so that outliers do not steer the search, and once on the named
    model before its final form: before its effects are in, the residual holds them (an
    efficiency grid run in random order reads as rough as noise to the neighbours) and hides
    an outlier in them."""
    which = "the named model's fit" if fit.effects else "the fit"
    bad = set_aside(problem, find_outliers(problem.base.y - fit.prediction),
                     f"left out of {which} and the RMSE")
    if not bad.size:
        return fit
    set_rows(problem, np.setdiff1d(problem.rows, bad))
    return fit_model(problem, fit.effects, fit.theta)


def outliers_of_final(problem: Problem, final: Fit) -> None:
    """The gross outliers of the final form's residual not yet left out, left out of the
    RMSE. What the final form follows (a rectified 2× error's overtones) hid 14 of 17 of
    suite P's outliers from the named model's residual. The final form is not fitted again
    without them: some of its forms are no columns to solve again (a joint on the catalog
    curve, integrated), and a few rows among thousands barely move it.

    Rows set aside earlier that :func:`find_outliers` does not find in the final form's
    residual are no gross outliers: a form not yet refined missed them (a play
    taken up more steeply than a tanh, before its exponent). They count in the RMSE again,
    as rows the final form was not fitted to."""
    found = find_outliers(problem.base.y - final.prediction)
    set_aside(problem, found, "in the final model's residual left out of the RMSE (the "
                               "final form was fitted with them)")
    back = np.setdiff1d(problem.outliers, found)
    if back.size:
        problem.outliers = np.setdiff1d(problem.outliers, back)
        problem.notes.append(
            f"{back.size} of the rows set aside as gross outliers do not stand "
            f"{OUTLIER_SIGMA:g}× the noise RMS out of their neighbours under the final model "
            "(a form not yet refined missed them): counted in the RMSE again, though left "
            "out of the fit")
