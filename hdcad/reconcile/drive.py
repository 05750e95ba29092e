"""The drive's torque ripple in a vibration test: an excitation q times per motor (input)
revolution that the load resonance picks up as the run-up passes q·f_in = f_n.

A servo motor's cogging torque repeats once per slot pitch and its electrical ripple six
times per pole pair; their orders per revolution (the slot count, the least common multiple
of slots and poles, 3·poles) are 6 … 72 on common motors. The gear's own transmission error
repeats once and twice per wave-generator revolution (``te_1x``, ``te_2x``) and its
harmonic series follows those; an order of 3 or more without them is the drive's, or a
higher harmonic of the gear's error that the catalog does not name. Either way it is
reported as the rig's (``measurement_effects``): the motor and its coupling are checked
first.

The ripple's response is the transmission error's (:func:`.harmonics.harmonic` at order
q, in the motor's own frame, through the same joint with the same damping and stiffness):
the servo holds the motor's speed, so its torque ripple shows as a ripple of the input's
angle, which the gear passes on as a kinematic excitation of the joint, as it does its own
error. Once a gear error is named, a ripple at one of that error's overtone orders is its
overtone rather than the drive's (:func:`at_a_named_overtone`).

References
----------
Jahns, T. M., Soong, W. L. (1996) "Pulsating torque minimization techniques for permanent
magnet AC motor drives — a review", IEEE Trans. Ind. Electron. 43(2): 321-330 (cogging and
ripple orders).
Seed 000 p.021 (resonance of the load on the gear's spring at k·f_in = f_n).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from scipy.signal import hilbert

from . import joint
from .effects import EFFECTS, Effect, Parameter
from .noise import noise_rms

if TYPE_CHECKING:
    from .fitting import Problem

# Orders looked for: from the first the gear's error does not name to the highest a motor's
# cogging reaches (the least common multiple of slots and poles, e.g. 72 for 9 slots and 8
# poles) with margin
ORDER_MIN, ORDER_MAX = 3, 96
# the resonance the order's crossing is looked for at: f_n within the joint's stiffness
# bounds (the te effects' stiffness_scale, 0.5 … 2: f_n × 0.71 … 1.41)
FN_SHARES = (math.sqrt(0.5), math.sqrt(2.0))
# a response followed at least this many samples per cycle at the record's top speed
SAMPLES_PER_CYCLE = 4
# damping and stiffness of the joint the orders are compared at (the fit then fits both)
SCAN_DAMPING = 0.05
SCAN_STIFFNESS = (0.85, 1.0, 1.15)
# where its response is (the rows within half the peak of its envelope) the ripple explains
# at least this share of the residual's structure above the noise: a drive's ripple is
# locked to the motor's angle, so it is what rings there; an ambient vibration rings the
# resonance at every speed, and a ripple fitted to it explains a part only (0.40 on suite
# H's floor vibration against 0.99–1.00 on suite O's cogging)
COHERENT_SHARE_MIN = 0.5

_JOINT = {p.name: p for p in EFFECTS["te_1x"].parameters
          if p.name in ("damping_ratio", "stiffness_scale")}

DRIVE_RIPPLE = Effect(
    name="drive_ripple",
    description=("The drive's torque ripple: the motor's cogging or electrical ripple, "
                 "q times per input revolution (q ≥ 3), excites the load's resonance as the "
                 "run-up passes q·f_in = f_n; or a higher harmonic of the gear's own error "
                 "(the catalog names only 1× and 2×)."),
    form=("e += a·sin(q·φ) + b·cos(q·φ), φ = WG (input) angle, through the joint as the "
          "transmission error; q the integer order whose resonance crossing fits best, the "
          "joint's damping and stiffness shared with the te effects"),
    parameters=(Parameter("a", "rad", "sine part of the excitation", -np.inf, np.inf,
                          linear=True),
                Parameter("b", "rad", "cosine part of the excitation", -np.inf, np.inf,
                          linear=True),
                _JOINT["damping_ratio"], _JOINT["stiffness_scale"]),
    kinds=("vibration",))


def natural_frequency(problem: Problem, stiffness_scale: float = 1.0) -> float:
    """f_n [Hz] of the load on the gear's spring K1 × ``stiffness_scale`` (formula 021-3)."""
    inp = problem.base.inputs
    return math.sqrt(stiffness_scale * float(inp["K_Nm_per_rad"])
                     / float(inp["J_kgm2"])) / (2 * math.pi)


def orders(problem: Problem) -> list[int]:
    """The orders whose resonance crossing the run-up passes (f_n within ``FN_SHARES`` of
    the catalog's) and that the sampling follows."""
    inp = problem.base.inputs
    fn = natural_frequency(problem)
    f_in = inp["input_speed_rpm"][problem.rows] / 60.0
    low, high = float(np.min(f_in)), float(np.max(f_in))
    dt = np.diff(inp["time_s"])
    top = (1.0 / float(np.median(dt)) / SAMPLES_PER_CYCLE / high
           if dt.size and high > 0 else ORDER_MIN - 1)
    return [q for q in range(ORDER_MIN, ORDER_MAX + 1)
            if q * high >= FN_SHARES[0] * fn and q * low <= FN_SHARES[1] * fn and q <= top]


def best_order(problem: Problem, residual: np.ndarray) -> int:
    """The order whose steady-state response through the joint explains most of
    ``residual`` (on the fitted rows), or 0 when the run-up crosses none."""
    candidates = orders(problem)
    if not candidates:
        return 0
    inp = problem.base.inputs
    rows = problem.rows
    phi = inp["wg_angle_rad"][rows]
    omega = 2 * math.pi * inp["input_speed_rpm"][rows] / 60.0
    k, J = float(inp["K_Nm_per_rad"]), float(inp["J_kgm2"])
    r = residual - residual.mean()
    best, chosen = -math.inf, 0
    for q in candidates:
        pairs = np.column_stack([np.sin(q * phi), np.cos(q * phi)])
        for s in SCAN_STIFFNESS:
            X = joint.steady_response(pairs, q * omega[:, None], s * k, J, SCAN_DAMPING)
            beta, *_ = np.linalg.lstsq(X, r, rcond=None)
            explained = float(r @ (X @ beta))
            if explained > best:
                best, chosen = explained, q
    return chosen


def crossing_rpm(problem: Problem, order: int, stiffness_scale: float) -> float:
    """Input speed [r/min] at which the order's excitation meets the joint's resonance."""
    return 60.0 * natural_frequency(problem, stiffness_scale) / order


def at_a_named_overtone(problem: Problem, effects: tuple[str, ...],
                        overtones: dict[str, tuple[int, ...]]) -> bool:
    """Whether the drive's ripple in ``effects`` sits at an overtone order (``overtones``:
    each gear error's) of a gear error named beside it: then it is that error's harmonic."""
    return "drive_ripple" in effects and any(
        problem.drive_order in overtones.get(e, ()) for e in effects)


def coherent_at_crossing(problem: Problem, without, fit) -> bool:
    """Whether the ripple fitted (``without`` → ``fit``) explains at least
    ``COHERENT_SHARE_MIN`` of the structure above the noise where its response rings: the
    rows within half the peak of the response's envelope (the analytic signal's magnitude),
    on every row in time order (the fitted rows of a long record are a random subset), less
    the gross outliers."""
    keep = np.ones(len(problem.base.y), bool)
    keep[problem.outliers] = False
    before = (problem.base.y - without.prediction)[keep]
    after = (problem.base.y - fit.prediction)[keep]
    envelope = np.abs(hilbert(before - after))
    ring = envelope >= 0.5 * float(np.max(envelope))
    sigma = noise_rms(after)
    structure = float(np.sum(before[ring] ** 2)) - ring.sum() * sigma ** 2
    explained = float(np.sum(before[ring] ** 2) - np.sum(after[ring] ** 2))
    return bool(structure > 0 and explained >= COHERENT_SHARE_MIN * structure)
