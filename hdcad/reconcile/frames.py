"""The member a transmission error turns with, in a run-up.

An error carried by the fixed circular spline repeats k times per wave-generator revolution.
One carried by the output member turns with the output, which the wave generator passes
k·(1 + δ) times per revolution: δ = +1/R when the circular spline is fixed and the flexspline
turns at −1/R (a flexspline's runout or tooth error in a gear head), δ = −1/(R + 1) when the
flexspline is fixed and the circular spline turns at +1/(R + 1) (seed 000 p.010, figure
010-1, arrangements ① and ②; R the rating table's ratio). Over the few revolutions of a
transmission test the two differ by a slow phase that the error's modulation follows; over
a run-up of hundreds of revolutions the phase slides through whole cycles and the resonance
the error excites sits 1/R away in speed, so an error in the fixed frame misses it.

The frame is chosen per harmonic before any effect is named: the single error's fit in each
frame, a change from the fixed frame kept only when it lowers the BIC by more than
``BIC_MIN`` and explains ``FRAME_EXPLAINED_MIN`` noise variances more (the frames have the
same number of parameters). Once named, a share carried by a second member (an ellipse
error of both splines) is kept on the same terms, two amplitudes more.
"""

from __future__ import annotations

from . import effects as fx
from .fitting import Fit, Problem, fit_model, rss_at
from .gates import beyond
from .harmonics import te_order_of

# a frame other than the fixed one, and a second frame's share, must explain this many noise
# variances more than the alternative (the fixed frame; the error with a slowly modulated
# amplitude and phase) beside ΔBIC > BIC_MIN: a misfit of the joint's damping law or spring
# beats near the resonance much as two close rates do (a share kept on BIC alone took
# 0.1–0.7 σ² of such misfits in four independent suites), and band-limited floor vibration
# at the resonance was read in a detuned frame at 1.6 σ² (ΔBIC 25); errors carried by the
# output member gained 3.9–52 σ²
FRAME_EXPLAINED_MIN = 2.0


def frames(ratio: float) -> tuple[float, ...]:
    """Offsets δ [-] of the error's rate k·(1 + δ) per WG revolution: the fixed circular
    spline (0), the flexspline as output (+1/R), the circular spline as output
    (−1/(R + 1)); ``ratio`` R [-] the rating table's.

    References
    ----------
    Seed 000 p.010, figure 010-1 (rotation directions and ratios, arrangements ① and ②).
    """
    return (0.0, 1 / ratio, -1 / (ratio + 1))


def _orders(names) -> list[tuple[str, int]]:
    return [(n, te_order_of(n)) for n in names if n in ("te_1x", "te_2x")]


def choose_frames(problem: Problem, start: Fit) -> dict[str, Fit]:
    """Vibration: sets ``problem.te_frames`` to the frame in which each error alone fits
    ``start``'s residual best, the fixed frame unless another lowers the BIC by more than
    ``BIC_MIN`` and explains ``FRAME_EXPLAINED_MIN`` noise variances more. Returns each
    error's single fit in its chosen frame (the gear search's first singles)."""
    chosen: dict[str, Fit] = {}
    if problem.kind != "vibration":
        return chosen
    for name, k in _orders(fx.applicable(problem.kind)):
        problem.te_frames[k] = 0.0
        fixed = fit_model(problem, start.effects + (name,), start.theta)
        kept = _better_frame(problem, k, 0.0, problem.te_frames, fixed)
        chosen[name] = kept[1] if kept else fixed
    return chosen


def _better_frame(problem: Problem, k: int, skip: float, frames_of_k: dict[int, float],
                  fit: Fit, *others: Fit) -> tuple[float, Fit] | None:
    """(frame, fit) of order ``k`` other than ``skip`` that beats ``fit`` and ``others`` on
    :func:`.gates.beyond`, set in ``frames_of_k`` (the problem's ``te_frames`` or
    ``te_second_frames``), or None with ``frames_of_k`` as it was. The frames are compared
    at ``fit``'s damping and stiffness (amplitudes only) and only the best is fitted in
    full, when it already fits better than ``fit`` (polishing the joint is what costs)."""
    before = frames_of_k.get(k)
    trials = {}
    for s in frames(problem.base.figures["ratio"][0]):
        if s != skip:
            frames_of_k[k] = s
            trials[s] = rss_at(problem, fit.effects, fit.theta)
    best = min(trials, key=trials.get) if trials else None
    if best is not None and trials[best] < fit.rss:
        frames_of_k[k] = best
        trial = fit_model(problem, fit.effects, fit.theta)
        if beyond(problem, fit, *others, trial, explained_min=FRAME_EXPLAINED_MIN):
            return best, trial
    if before is None:
        frames_of_k.pop(k, None)
    else:
        frames_of_k[k] = before
    return None


def refine_frames(problem: Problem, fit: Fit) -> Fit:
    """Vibration: each named error with a constant-amplitude share in a second frame, kept
    when it lowers the BIC by more than ``BIC_MIN`` at N/τ (τ from the wider fit's
    residual) both against the error alone and against the error with a linearly varying
    amplitude and phase (as many parameters more: a share that a slow modulation explains
    as well is not told apart from one) and explaining ``FRAME_EXPLAINED_MIN`` noise
    variances more than the latter; the joint's damping and stiffness fitted again with
    it. Sets ``problem.te_second_frames`` and says which frames the named errors are in."""
    if problem.kind != "vibration":
        return fit
    for name, k in _orders(fit.effects):
        problem.te_order += 1
        modulated = fit_model(problem, fit.effects, fit.theta)
        problem.te_order -= 1
        if problem.te_frames.get(k, 0.0):
            problem.notes.append(
                f"{name}: an error turning with the output member fits the run-up better, "
                f"at {k * (1 + problem.te_frames[k]):.4f} cycles per WG revolution")
        kept = _better_frame(problem, k, problem.te_frames.get(k, 0.0),
                             problem.te_second_frames, fit, modulated)
        if kept:
            fit = kept[1]
            problem.notes.append(f"{name}: a share turning at {k * (1 + kept[0]):.4f} cycles "
                                 "per WG revolution kept beside it (BIC)")
    return fit
