"""Hysteresis as a Preisach model with a continuous parametric density.

A relay (hysteron) with up-switching torque α and down-switching torque β < α reads +1 once
the torque has reached α and −1 once it has fallen to β, and holds its state in between.
The loop is the relays' weighted mean over the Preisach plane, written here in the
half-width w = (α − β)/2 (the slip torque of a friction element) and the centre
c = (α + β)/2 (its bias), with a lognormal density in w and a normal density in c (Della
Torre 1999). A narrow centre spread switches the relays at fixed torques ±w (a loop that
turns over at T ≈ ±w, as in magnetic materials); a wide one (uniform in c) is the
Prandtl–Ishlinskii play-operator sum, each play slipping after a travel 2w from the last
turning point (Masing's friction loop).

Unlike the Bouc–Wen loop the model has the Preisach memory: a minor loop closes on its
turning point and a larger excursion wipes the smaller ones out, which is what the friction
of many tooth contacts does under cycles of several amplitudes.

The output follows from the Everett function E(α, β) (the density's mass on the triangle
β ≤ b ≤ a ≤ α) at the record's alternating dominant extrema (Mayergoyz 1991, ch. 1):
f = −E(α0, β0) + 2 Σ [E(M_k, m_{k−1}) − E(M_k, m_k)] over the memory, the last term at the
current torque. The memory depends on the torque history only, not on the density: its
terms are listed once per record (:func:`everett_terms`) and each density is one weighted
sum. The record starts from the demagnetised state (negative saturation, then alternating
extrema decaying to zero).

References
----------
Mayergoyz, I. D. (1991) *Mathematical Models of Hysteresis*, Springer.
Della Torre, E. (1999) *Magnetic Hysteresis*, IEEE Press (lognormal × normal densities).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import sparse
from scipy.special import erf

# limiting triangle |α|, |β| ≤ LIMIT·T0: relays wider than that never switch in the test
LIMIT = 3.0
# the demagnetising prehistory: extrema ±LIMIT·T0·DECAY^k, down to DEMAG_END·T0
DECAY = 0.8
DEMAG_END = 1e-3
# Gauss–Hermite nodes for the integral over the relays' centres; the six outermost of 24
# weigh 3.4e-10 together (the Everett function is a mass ≤ 1), so they are left out
_NODES, _WEIGHTS = np.polynomial.hermite.hermgauss(24)
_KEPT = _WEIGHTS / math.sqrt(math.pi) > 1e-9
_NODES, _WEIGHTS = _NODES[_KEPT], _WEIGHTS[_KEPT] / math.sqrt(math.pi)
_MAJOR_POINTS = 200


def everett(alpha: np.ndarray, beta: np.ndarray, width: float, spread: float,
            centre_spread: float) -> np.ndarray:
    """Everett function E(α, β) [-]: the density's mass on the triangle β ≤ b ≤ a ≤ α.

    In (w, c): 0 ≤ w ≤ min(c − β, α − c), so E = ∫ g(c)·F(min(c − β, α − c)) dc with F the
    lognormal CDF of the half-width (median ``width`` [N·m], log-spread ``spread``) and g
    the normal density of the centre (standard deviation ``centre_spread`` [N·m]),
    integrated by Gauss–Hermite quadrature."""
    c = math.sqrt(2.0) * centre_spread * _NODES
    reach = np.minimum(c - beta[:, None], alpha[:, None] - c)
    with np.errstate(divide="ignore"):
        u = np.log(np.maximum(reach, 0.0) / width) / (spread * math.sqrt(2.0))
    return (0.5 * (1.0 + erf(u))) @ _WEIGHTS


def everett_terms(torque_Nm: np.ndarray, T0: float
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(sample, α, β, coefficient): the Everett terms of every sample's output, the
    constant −E(α0, β0) aside, along the history demagnetised → ``torque_Nm``.

    The memory changes only at a turn and where the torque passes a stored extremum, so it
    is followed run by run (a run: the torque moving one way); a long run's samples read
    their depth in the memory by bisection, a short one's (a noisy torque's) one by one."""
    top = LIMIT * T0
    demag = [(-1) ** k * top * DECAY ** k for k in range(1, 200)
             if top * DECAY ** k > DEMAG_END * T0]
    u = np.concatenate([demag, [0.0], np.asarray(torque_Nm, dtype=float)])
    first = len(demag) + 1                      # the record's first sample in u
    direction = _directions(np.diff(u, prepend=-top))
    turns = np.flatnonzero(np.diff(np.concatenate([[1.0], direction])) != 0)
    bounds = np.unique(np.concatenate([[0], turns, [len(u)]]))
    maxima, minima = [], [-top]   # dominant extrema; minima[0] = β0 (negative saturation)
    pieces, scalars = [], ([], [], [], [])
    turned = set(turns.tolist())
    values, bounds = u.tolist(), bounds.tolist()
    for s, e in zip(bounds[:-1], bounds[1:]):
        rising = bool(direction[s] > 0)
        if s in turned:
            (minima if rising else maxima).append(values[s - 1] if s else -top)
        if e - s > _SHORT_RUN:
            if scalars[0]:
                pieces.append(tuple(np.array(x) for x in scalars))
                scalars = ([], [], [], [])
            pieces.append(_run_terms(u, s, e, first, rising, maxima, minima))
        else:
            for i in range(s, e):
                _sample_terms(values[i], i - first, rising, maxima, minima, scalars)
    if scalars[0]:
        pieces.append(tuple(np.array(x) for x in scalars))
    return tuple(np.concatenate(p) for p in zip(*pieces))


# runs of at most this many samples are followed one sample at a time
_SHORT_RUN = 16


def _directions(step: np.ndarray) -> np.ndarray:
    """+1 / −1: the sign of the last non-zero step up to each sample (rising at the start)."""
    moved = np.flatnonzero(step)
    if not moved.size:
        return np.ones_like(step)
    last = np.searchsorted(moved, np.arange(len(step)), side="right") - 1
    out = np.sign(step[moved[np.maximum(last, 0)]])
    out[last < 0] = 1.0
    return out


def _sample_terms(u: float, sample: int, rising: bool, maxima: list, minima: list,
                  out: tuple) -> None:
    """One sample of a run: the extrema it passes wiped out, its terms appended to ``out``
    (a sample of the demagnetising prehistory, ``sample`` < 0, adds none)."""
    if rising:
        while maxima and maxima[-1] <= u:   # wiped out: the pair below it goes too
            maxima.pop()
            if len(minima) > 1:
                minima.pop()
    else:
        while len(minima) > 1 and minima[-1] >= u:
            minima.pop()
            maxima.pop()
    if sample < 0:
        return
    rows, alphas, betas, coefs = out
    for k in range(len(maxima) if rising else len(maxima) - 1):  # the closed pairs
        rows += [sample, sample]
        alphas += [maxima[k], maxima[k]]
        betas += [minima[k], minima[k + 1]]
        coefs += [2.0, -2.0]
    if rising:                           # the rising branch from the last minimum
        rows.append(sample)
        alphas.append(u)
        betas.append(minima[-1])
        coefs.append(2.0)
    else:                                # the falling branch from the last maximum
        rows += [sample, sample]
        alphas += [maxima[-1], maxima[-1]]
        betas += [minima[-1], u]
        coefs += [2.0, -2.0]


def _run_terms(u: np.ndarray, s: int, e: int, first: int, rising: bool, maxima: list,
               minima: list) -> tuple:
    """The terms of the samples s…e−1 of one run, in the order of :func:`_sample_terms`; the
    memory left as after the run's last sample. The maxima decrease and the minima increase
    up the memory, so a rising sample keeps the maxima above it, a falling one the minima
    below it."""
    seg = u[s:e]
    mx, mn = np.array(maxima), np.array(minima)
    if rising:
        depth = len(mx) - np.searchsorted(mx[::-1], seg, side="right")
    else:
        depth = np.searchsorted(mn[1:], seg, side="left") + 1
    last = int(depth[-1])
    del maxima[last:]
    del minima[last + int(rising):]
    lo = max(s, first) - s
    seg, depth = seg[lo:], depth[lo:]
    sample = np.arange(s + lo, e) - first
    closed = depth if rising else depth - 1          # closed pairs of each sample
    count = 2 * closed + (1 if rising else 2)
    start = np.cumsum(count) - count
    alpha, beta, coef = (np.empty(int(count.sum())) for _ in range(3))
    owner = np.repeat(np.arange(len(seg)), closed)
    k = np.arange(len(owner)) - np.repeat(np.cumsum(closed) - closed, closed)
    at = start[owner] + 2 * k
    alpha[at], beta[at], coef[at] = mx[k], mn[k], 2.0
    alpha[at + 1], beta[at + 1], coef[at + 1] = mx[k], mn[k + 1], -2.0
    end = start + 2 * closed
    if rising:                           # the rising branch from the last minimum
        alpha[end], beta[end], coef[end] = seg, mn[depth], 2.0
    else:                                # the falling branch from the last maximum
        alpha[end], beta[end], coef[end] = mx[depth - 1], mn[depth - 1], 2.0
        alpha[end + 1], beta[end + 1], coef[end + 1] = mx[depth - 1], seg, -2.0
    return np.repeat(sample, count), alpha, beta, coef


def term_matrix(terms, n: int) -> tuple[sparse.csr_matrix, np.ndarray, np.ndarray]:
    """(S, α, β): ``terms`` folded onto their distinct (α, β) pairs, so that the output of
    ``n`` samples is S @ E(α, β). The closed pairs of the memory repeat from sample to
    sample; only the branch from the last turning point is new, so the distinct pairs are
    a few per sample where the terms are ten or more."""
    rows, alpha, beta, coef = terms
    # one sort of α + iβ (lexicographic on complex numbers) instead of a row-wise unique
    pairs, index = np.unique(alpha + 1j * beta, return_inverse=True)
    S = sparse.csr_matrix((coef, (rows, index.ravel())), shape=(n, len(pairs)))
    return S, pairs.real.copy(), pairs.imag.copy()


class PreisachPlane:
    """The Everett terms of one torque record and of the steady major loop between ±T0
    (listed once); :meth:`loop` is the model for one density."""

    def __init__(self, torque_Nm: np.ndarray, T0: float):
        self.T0 = T0
        self.terms = term_matrix(everett_terms(torque_Nm, T0), len(torque_Nm))
        self.grid = np.linspace(-T0, T0, _MAJOR_POINTS)
        history = np.concatenate([np.linspace(0.0, T0, _MAJOR_POINTS), self.grid[::-1],
                                  self.grid])
        self.major = term_matrix(everett_terms(history, T0), len(history))
        self._subsets: dict = {}
        self._last: tuple = (None, None)

    def _output(self, terms, density: tuple[float, float, float]) -> np.ndarray:
        S, alpha, beta = terms
        total = everett(np.array([LIMIT * self.T0]), np.array([-LIMIT * self.T0]), *density)
        return S @ everett(alpha, beta, *density) - total

    @staticmethod
    def _key(rows) -> tuple:
        if isinstance(rows, slice):
            return ()
        return (len(rows), int(rows[0]), int(rows[-1]), int(rows.sum()))

    def _terms_on(self, rows) -> tuple:
        """The record's terms on ``rows`` (sorted sample indices, or every row)."""
        if isinstance(rows, slice):
            return self.terms
        key = self._key(rows)
        if key not in self._subsets:
            S, alpha, beta = self.terms
            S = S[rows]
            used = np.unique(S.indices)
            self._subsets = {key: (S[:, used], alpha[used], beta[used])}
        return self._subsets[key]

    def _record(self, rows, density) -> np.ndarray:
        """The Preisach output on ``rows``; the last one is kept, since the loop's forms
        share it."""
        key = (self._key(rows), density)
        if self._last[0] != key:
            self._last = (key, self._output(self._terms_on(rows), density))
        return self._last[1]

    def loop(self, torque_Nm: np.ndarray, rows, width: float, spread: float,
             centre_spread: float, centred: bool) -> np.ndarray:
        """The loop's state z [-] on ``rows`` of the record, in the friction-state sign of
        the Bouc–Wen loop (the twist −z_sat·z): minus the Preisach output. ``centred``:
        less the centre line of the steady major loop (the mean of its descending and
        ascending branches, which the catalog curve is), at the rows' torque."""
        density = (width, spread, centre_spread)
        z = -self._record(rows, density)
        if centred:
            down, up = self._branches(density)
            z = z + np.interp(torque_Nm, self.grid, 0.5 * (down + up))
        return z

    def loss(self, width: float, spread: float, centre_spread: float) -> float:
        """Width at zero torque of the steady major loop between ±T0, per unit z_sat (the
        twist B − B′ of seed 000 p.020 over z_sat)."""
        down, up = self._branches((width, spread, centre_spread))
        return float(np.interp(0.0, self.grid, down - up))

    def _branches(self, density) -> tuple[np.ndarray, np.ndarray]:
        """Preisach output on the descending and ascending branches of the major loop, on
        :attr:`grid`."""
        f = self._output(self.major, density)
        return f[_MAJOR_POINTS:2 * _MAJOR_POINTS][::-1], f[2 * _MAJOR_POINTS:]
