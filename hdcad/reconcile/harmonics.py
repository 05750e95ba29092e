"""The transmission error's columns: sin/cos of its angle at k cycles per wave-generator
revolution, in the frame of the member that carries it, times Legendre polynomials of the
record position (a slowly varying amplitude and phase), and the load joint's response to
them in a run-up.

References
----------
Seed 000 p.021 (angular transmission error, two cycles per input revolution; the load
resonance it excites, formula 021-3); seed 000 p.010 (rotation directions and ratios).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from . import joint

if TYPE_CHECKING:
    from .fitting import Problem

# Legendre order of the slowly varying TE amplitude and phase while effects are named (3 and
# 4 fit modulated TE better but a flexible TE also takes what a second effect explains);
# once named, the order is chosen by BIC up to TE_ORDER_MAX (:func:`.te_forms.refine_te_order`)
TE_ORDER = 2
TE_ORDER_MAX = 24


def te_labels(order: int) -> tuple[str, ...]:
    """Names of the TE amplitudes: sin, cos, then sin_uk, cos_uk for P1 … P_order."""
    return ("sin", "cos") + tuple(f"{f}_u{k}" for k in range(1, order + 1)
                                  for f in ("sin", "cos"))


TE_LABELS = te_labels(TE_ORDER)


def te_order_of(name: str) -> int:
    """Cycles per WG revolution k of the error effect ``name`` (``te_1x`` → 1)."""
    return int(name[3])


def harmonic(problem: Problem, order: int, theta: dict, full: bool,
             frames: tuple[float, float | None] | None = None) -> np.ndarray:
    """The error's columns at ``order`` on the fitted rows or every row (``full``):
    :func:`te_basis`, or the linear joint's response to them (vibration, when ``theta``
    holds the damping); in ``frames`` (frame, second frame or None) if given, else in the
    error's own (``(0.0, None)``: at k·φ whatever the error's frame)."""
    frames = frames_of(problem, order) if frames is None else frames
    key = (order, frames, theta.get("damping_ratio"), theta.get("stiffness_scale", 1.0),
           full, problem.steady_state, problem.relative_damping)
    width = te_width(problem, order, frames)
    # a lower Legendre order's columns are the first of a higher one's: kept once, sliced
    if key not in problem.cache or problem.cache[key].shape[1] < width:
        cols = np.column_stack(te_basis(problem, order, frames))
        cols = _through_joint(problem, cols, lambda: pair_rates(problem, order, frames), theta)
        cols = cols if full else cols[problem.rows]
        if len(problem.cache) > 64:
            problem.cache.clear()
        problem.cache[key] = cols
    return problem.cache[key][:, :width]


def _through_joint(problem: Problem, pairs: np.ndarray, rates, theta: dict) -> np.ndarray:
    """(sin, cos) pairs of excitation columns on every row as the load's angle: themselves
    (transmission), or the linear joint's response to them (vibration, when ``theta`` holds
    the damping; the steady state at each pair's rate [rad/s], ``rates()``, or the run-up's
    time history)."""
    zeta = theta.get("damping_ratio")
    if zeta is None:
        return pairs
    inp = problem.base.inputs
    k = float(inp["K_Nm_per_rad"]) * theta.get("stiffness_scale", 1.0)
    J = float(inp["J_kgm2"])
    if problem.steady_state:
        return joint.steady_response(pairs, rates(), k, J, zeta)
    return joint.joint_response(inp["time_s"], pairs, k, J, zeta,
                                on_twist=problem.relative_damping)


def locked_overtone(problem: Problem, theta: dict, full: bool) -> np.ndarray:
    """The 1× error's 2× overtone locked to it, times P0 … P_te_order of the record position
    as the error's own amplitude, on the fitted rows or every row (n × (te_order + 1);
    labelled by :func:`locked_labels`). With the 1× error a·sin(a + p), a = (1 + δ)·φ in its
    frame δ, and ``Problem.te_locked_2x`` = (p, shift): the excitation sin(2a + 2p + shift)
    through the joint (as :func:`harmonic`), except a function of the 1×'s value in a
    vibration test (shift π/2), whose 2× is the 1×'s excitation times the 1×'s response
    through the joint, sin(a + p)·r(t) (a stiffness that varies once per revolution acting
    on the twist it causes, Hill's equation): with r = α·sin(a + p) + β·cos(a + p) at each
    instant, its 2× part (β·sin 2(a + p) − α·cos 2(a + p))/2, through the joint at 2×."""
    p, shift = problem.te_locked_2x
    frames = (frames_of(problem, 1)[0], None)
    if "damping_ratio" not in theta or shift != math.pi / 2:
        cols = harmonic(problem, 2, theta, full, frames)
        return cols[:, 0::2] * np.cos(2 * p + shift) + cols[:, 1::2] * np.sin(2 * p + shift)
    a = (1 + frames[0]) * problem.base.inputs["wg_angle_rad"]
    r_s, r_c = harmonic(problem, 1, theta, True, frames)[:, :2].T
    alpha = r_s * np.sin(a) + r_c * np.cos(a)  # the joint's gain in phase at 1×
    beta = r_s * np.cos(a) - r_c * np.sin(a)   # and in quadrature
    b = 2 * (a + p)
    polys = legendre(problem.base.inputs["record_position"], problem.te_order)
    # per Legendre term, two pairs: β·sin b (with its cosine partner) and α·cos b
    pairs = np.column_stack([c * poly for poly in polys
                             for c in (beta * np.sin(b), beta * np.cos(b),
                                       alpha * np.cos(b), -alpha * np.sin(b))])
    response = _through_joint(
        problem, pairs,
        lambda: np.repeat(pair_rates(problem, 2, frames)[:, -1:], 2 * len(polys), axis=1),
        theta)
    cols = 0.5 * (response[:, 0::4] - response[:, 2::4])
    return cols if full else cols[problem.rows]


def locked_labels(order: int) -> list[str]:
    """Names of :func:`locked_overtone`'s columns: locked_2x, then locked_2x_uk."""
    return ["locked_2x"] + [f"locked_2x_u{k}" for k in range(1, order + 1)]


def overtones_of(problem: Problem, effects: tuple[str, ...], name: str) -> list[int]:
    """The chosen overtones that belong to the named error ``name``: to te_2x those it
    divides, to te_1x the rest."""
    mine = [k for k in problem.te_overtones if k % 2 == 0 and "te_2x" in effects]
    return mine if name == "te_2x" else [k for k in problem.te_overtones if k not in mine]


def sidebands(problem: Problem, order: int, full: bool, theta: dict | None = None
              ) -> np.ndarray:
    """sin/cos of the error at ``order`` shifted by ± j·f_m, j = 1 … the modulation's count
    (``Problem.te_sidebands``), on the fitted rows or every row (n × 4j; labelled by
    :func:`sideband_labels`): an amplitude modulation a·(1 + m·cos(f_m·φ)) gives the pair
    k ± f_m, a phase modulation of depth d the pairs k ± j·f_m in the Bessel functions
    J_j(d) (Carson 1922). In a vibration test (``theta`` holding the damping) the joint's
    response to them, each at its own rate.

    References: Carson, J. R. (1922) "Notes on the theory of modulation", Proc. IRE 10(1):
    57-64.
    """
    frame = frames_of(problem, order)[0]
    f_m, count = problem.te_sidebands[order]
    phi = problem.base.inputs["wg_angle_rad"]
    shifted = [order * (1 + frame) + side * j * f_m for j in range(1, count + 1)
               for side in (1, -1)]
    out = np.column_stack([g(m * phi) for m in shifted for g in (np.sin, np.cos)])
    out = _through_joint(problem, out, lambda: np.outer(
        2 * np.pi * problem.base.inputs["input_speed_rpm"] / 60.0, shifted), theta or {})
    return out if full else out[problem.rows]


def sideband_labels(count: int) -> tuple[str, ...]:
    """Names of :func:`sidebands`' columns: sin/cos at k + j·f_m and k − j·f_m."""
    return tuple(f"{g}_sb{j}_{side}" for j in range(1, count + 1) for side in ("plus", "minus")
                 for g in ("sin", "cos"))


def frames_of(problem: Problem, order: int) -> tuple[float, float | None]:
    """(frame, second frame or None) of the error at ``order`` (``Problem.te_frames``)."""
    return problem.te_frames.get(order, 0.0), problem.te_second_frames.get(order)


def te_width(problem: Problem, order: int,
             frames: tuple[float, float | None] | None = None) -> int:
    """Columns of the error at ``order``: :func:`te_basis`'s at the problem's order, in
    ``frames`` if given, else in the error's own."""
    frames = frames_of(problem, order) if frames is None else frames
    return 2 * (problem.te_order + 1) + 2 * (frames[1] is not None)


def te_basis(problem: Problem, order: int,
             frames: tuple[float, float | None] | None = None) -> list[np.ndarray]:
    """The error's columns on every row: sin/cos of its angle k·(1 + δ)·φ in its frame δ
    (``Problem.te_frames``) times P0 … P_te_order of the record position (a slowly varying
    amplitude and phase), after the sin/cos of a second frame's share when there is one;
    labelled as :func:`te_column_labels`."""
    inp = problem.base.inputs
    frame, second = frames_of(problem, order) if frames is None else frames
    phi = inp["wg_angle_rad"]
    a = order * (1 + frame) * phi
    own = ([np.sin(order * (1 + second) * phi), np.cos(order * (1 + second) * phi)]
           if second is not None else [])
    return own + [c * p for p in legendre(inp["record_position"], problem.te_order)
                  for c in (np.sin(a), np.cos(a))]


def pair_rates(problem: Problem, order: int, frames: tuple[float, float | None]
               ) -> np.ndarray:
    """Angular rate [rad/s] of each (sin, cos) pair of :func:`te_basis`'s columns in
    ``frames`` (n × pairs): k·(1 + δ) times the WG's rate."""
    frame, second = frames
    rates = ([order * (1 + second)] if second is not None else []) + \
        [order * (1 + frame)] * (problem.te_order + 1)
    return np.outer(2 * np.pi * problem.base.inputs["input_speed_rpm"] / 60.0, rates)


def te_column_labels(problem: Problem, order: int) -> tuple[str, ...]:
    """Names of :func:`te_basis`'s columns."""
    own = ("sin_second", "cos_second") if frames_of(problem, order)[1] is not None else ()
    return own + te_labels(problem.te_order)


def legendre(u: np.ndarray, order: int) -> list[np.ndarray]:
    """P0 … P_order of u ∈ [−1, 1] (Bonnet's recursion)."""
    out = [np.ones_like(u), u]
    for n in range(1, order):
        out.append(((2 * n + 1) * u * out[n] - n * out[n - 1]) / (n + 1))
    return out[:order + 1]
